/**
 * @class   amMeditReader
 * @brief   Reads a Medit ASCII mesh (.mesh) and optionally its vertex solution (.sol).
 *
 * The INRIA Medit format is the one of the paper's tools (Yams, GHS3d). Output is a
 * vtkUnstructuredGrid with the vertices (point data "Ref"), and the edges, triangles,
 * quadrilaterals, tetrahedra and hexahedra in file order, their references in cell data
 * "Region" (the organ label of a tetrahedron, the surface patch of a triangle).
 * When ReadSolution is on (default) and a .sol file exists (SolutionFileName, or the mesh's name
 * with .sol), its fields become point data: scalars and vectors "Solution", symmetric tensors
 * "Metric" (6 components in VTK order XX YY ZZ XY YZ XZ); several fields get a numeric suffix.
 * A malformed file is reported with the file name and the line of the problem.
 */
#ifndef amMeditReader_h
#define amMeditReader_h

#include "AnatomeshIOMeshModule.h" // export macro
#include "vtkUnstructuredGridAlgorithm.h"

class ANATOMESHIOMESH_EXPORT amMeditReader : public vtkUnstructuredGridAlgorithm
{
public:
  static amMeditReader* New();
  vtkTypeMacro(amMeditReader, vtkUnstructuredGridAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The .mesh file.
  vtkSetStringMacro(FileName);
  vtkGetStringMacro(FileName);
  ///@}

  ///@{
  /// The .sol file (empty: the mesh's name with .sol, read only if it exists).
  vtkSetStringMacro(SolutionFileName);
  vtkGetStringMacro(SolutionFileName);
  ///@}

  ///@{
  /// Read the vertex solution (default on).
  vtkSetMacro(ReadSolution, bool);
  vtkGetMacro(ReadSolution, bool);
  vtkBooleanMacro(ReadSolution, bool);
  ///@}

protected:
  amMeditReader();
  ~amMeditReader() override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  char* FileName;
  char* SolutionFileName;
  bool ReadSolution;

private:
  amMeditReader(const amMeditReader&) = delete;
  void operator=(const amMeditReader&) = delete;
};

#endif
