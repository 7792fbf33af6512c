/**
 * @class   amOpenCARPReader
 * @brief   Reads an openCARP mesh (base.pts, base.elem, base.lon when present) into a tetrahedral
 *          vtkUnstructuredGrid: cell data Region from the elements' tags, Fibers (and Sheets) from
 *          the .lon file.
 *
 * FileName is the base name (a .pts, .elem or .lon ending is taken off). Coordinates are divided by
 * CoordinateScale (default 1000: openCARP's micrometres to millimetres). Only tetrahedra ("Tt") are
 * read; any other element type, a count that does not match the lines, a node index out of range, a
 * non-number or a .lon with another element count is an error naming the file and the line.
 */
#ifndef amOpenCARPReader_h
#define amOpenCARPReader_h

#include "AnatomeshIOMeshModule.h" // export macro
#include "vtkUnstructuredGridAlgorithm.h"

class ANATOMESHIOMESH_EXPORT amOpenCARPReader : public vtkUnstructuredGridAlgorithm
{
public:
  static amOpenCARPReader* New();
  vtkTypeMacro(amOpenCARPReader, vtkUnstructuredGridAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The mesh's base name.
  vtkSetStringMacro(FileName);
  vtkGetStringMacro(FileName);
  ///@}

  ///@{
  /// Coordinates read are divided by this (default 1000: micrometres to mm).
  vtkSetClampMacro(CoordinateScale, double, 1e-12, 1e12);
  vtkGetMacro(CoordinateScale, double);
  ///@}

protected:
  amOpenCARPReader();
  ~amOpenCARPReader() override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  char* FileName;
  double CoordinateScale;

private:
  amOpenCARPReader(const amOpenCARPReader&) = delete;
  void operator=(const amOpenCARPReader&) = delete;
};

#endif
