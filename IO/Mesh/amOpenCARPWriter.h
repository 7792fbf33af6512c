/**
 * @class   amOpenCARPWriter
 * @brief   Writes a tetrahedral mesh in openCARP's text format: points (.pts), elements with their
 *          region tags (.elem), fibres and sheets (.lon), and tagged surfaces (.surf, .vtx).
 *
 * FileName is the mesh's base name (openCARP's -meshname; a .pts, .elem or .lon ending is taken
 * off): base.pts holds the point count, then x y z per point in micrometres (CoordinateScale 1000
 * times the mesh's millimetres); base.elem the element count, then "Tt a b c d region" per
 * tetrahedron (RegionArrayName, "Region"; 0 without it); base.lon, when the mesh has the cell vector
 * array FiberArrayName ("Fibers"), "2" (or "1" without SheetArrayName's "Sheets"), then each element's
 * fibre (and sheet) direction, zero where the mesh has none (outside the heart). Only points that a
 * tetrahedron uses are written, renumbered from 0 in their order: openCARP (and any solver that
 * assembles over all points) needs every point in an element.
 *
 * Optional input 1 ("Surfaces"): triangles with cell data SurfaceTagArrayName ("VentricularTag")
 * and point data InputPointId (Ventricular Fibres' Tags output): one base.NAME.surf ("N", then
 * "Tr a b c" per triangle) and base.NAME.vtx ("N", "intra", then the node ids) per tag, NAME from
 * the field data TagNames ("1 LVEndocardium") or "tagK": the surfaces a stimulus or a boundary
 * condition is put on.
 *
 * Every file is written to a temporary beside its target and renamed only when all were written:
 * a full disk leaves the previous files (or none), never a half-written set. A non-tetrahedral cell,
 * a non-finite coordinate or a fibre array of another size is an error naming it.
 */
#ifndef amOpenCARPWriter_h
#define amOpenCARPWriter_h

#include "AnatomeshIOMeshModule.h" // export macro
#include "vtkAlgorithm.h"

#include <string>
#include <vector>

class ANATOMESHIOMESH_EXPORT amOpenCARPWriter : public vtkAlgorithm
{
public:
  static amOpenCARPWriter* New();
  vtkTypeMacro(amOpenCARPWriter, vtkAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The mesh's base name (base.pts, base.elem, base.lon, base.NAME.surf/.vtx).
  vtkSetStringMacro(FileName);
  vtkGetStringMacro(FileName);
  ///@}

  ///@{
  /// Arrays: region labels (cells, "Region"), fibres ("Fibers") and sheets ("Sheets"), the surfaces'
  /// tags (cells of input 1, "VentricularTag").
  vtkSetStringMacro(RegionArrayName);
  vtkGetStringMacro(RegionArrayName);
  vtkSetStringMacro(FiberArrayName);
  vtkGetStringMacro(FiberArrayName);
  vtkSetStringMacro(SheetArrayName);
  vtkGetStringMacro(SheetArrayName);
  vtkSetStringMacro(SurfaceTagArrayName);
  vtkGetStringMacro(SurfaceTagArrayName);
  ///@}

  ///@{
  /// Coordinates written are the mesh's times this (default 1000: mm to openCARP's micrometres).
  vtkSetClampMacro(CoordinateScale, double, 1e-12, 1e12);
  vtkGetMacro(CoordinateScale, double);
  ///@}

  /// Set the mesh (and the surfaces) to write without a pipeline connection.
  void SetInputData(vtkDataObject* input) { this->SetInputDataInternal(0, input); }
  void SetSurfacesData(vtkDataObject* surfaces) { this->SetInputDataInternal(1, surfaces); }
  void SetSurfacesConnection(vtkAlgorithmOutput* output) { this->SetInputConnection(1, output); }

  /// Write the input. Returns 1 on success, 0 on error (reported with vtkErrorMacro).
  int Write();
  /// The files the last successful write made.
  const std::vector<std::string>& GetWrittenFiles() const { return this->Written; }

  /// The base name of a path: a .pts, .elem or .lon ending taken off.
  static std::string BaseName(const std::string& path);

  vtkTypeBool ProcessRequest(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

protected:
  amOpenCARPWriter();
  ~amOpenCARPWriter() override;
  int FillInputPortInformation(int port, vtkInformation* info) override;
  int WriteData(vtkDataObject* input, vtkDataObject* surfaces);

  char* FileName;
  char* RegionArrayName;
  char* FiberArrayName;
  char* SheetArrayName;
  char* SurfaceTagArrayName;
  double CoordinateScale;

private:
  bool LastWriteOk = false;
  std::vector<std::string> Written;
  amOpenCARPWriter(const amOpenCARPWriter&) = delete;
  void operator=(const amOpenCARPWriter&) = delete;
};

#endif
