/**
 * @class   amMeditWriter
 * @brief   Writes a vtkPolyData or vtkUnstructuredGrid as a Medit ASCII mesh (.mesh) and,
 *          optionally, one point-data array as a Medit solution (.sol) beside it.
 *
 * Lines, triangles, quadrilaterals, tetrahedra and hexahedra are written (vertices are skipped;
 * any other cell type is an error naming the cell). Element references come from the cell-data
 * array RegionArrayName (default "Region", first component; 0 when absent), vertex references
 * from point data PointRefArrayName (default "Ref"). Coordinates are written with 17 significant
 * digits so a round trip through amMeditReader keeps every number. SolutionArrayName, when set,
 * writes that point-data array to "<name>.sol": 1 component as a scalar, 3 as a vector, 6 (VTK
 * symmetric tensor order XX YY ZZ XY YZ XZ) as a symmetric tensor in Medit order.
 * Files appear atomically (temporary name, then rename); NaN coordinates are refused.
 *
 * WriteInterfaces (default on): a tetrahedral mesh without triangles also gets its interface and
 * boundary triangles (amTetraFaces: each face where the region changes, once, the normal from the
 * higher region into the lower one, outwards on the boundary), so a solver can put boundary
 * conditions on organ surfaces. Their reference names the two regions: 1000 × higher + lower,
 * with 0 for the outside (e.g. 5006 is not possible, 6005 separates regions 6 and 5, 1000 is
 * region 1's outer boundary); region labels must then lie in 1..999.
 */
#ifndef amMeditWriter_h
#define amMeditWriter_h

#include "AnatomeshIOMeshModule.h" // export macro
#include "vtkAlgorithm.h"

class ANATOMESHIOMESH_EXPORT amMeditWriter : public vtkAlgorithm
{
public:
  static amMeditWriter* New();
  vtkTypeMacro(amMeditWriter, vtkAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// Target .mesh file.
  vtkSetStringMacro(FileName);
  vtkGetStringMacro(FileName);
  ///@}

  ///@{
  /// Cell-data array holding element references (default "Region").
  vtkSetStringMacro(RegionArrayName);
  vtkGetStringMacro(RegionArrayName);
  ///@}

  ///@{
  /// Point-data array holding vertex references (default "Ref").
  vtkSetStringMacro(PointRefArrayName);
  vtkGetStringMacro(PointRefArrayName);
  ///@}

  ///@{
  /// Also write the interface and boundary triangles of a tetrahedral mesh (default on).
  vtkSetMacro(WriteInterfaces, vtkTypeBool);
  vtkGetMacro(WriteInterfaces, vtkTypeBool);
  vtkBooleanMacro(WriteInterfaces, vtkTypeBool);
  ///@}
  ///@{
  /// Point-data array to write as "<name>.sol" (default empty: no .sol).
  vtkSetStringMacro(SolutionArrayName);
  vtkGetStringMacro(SolutionArrayName);
  ///@}

  /// Set the mesh to write without a pipeline connection.
  void SetInputData(vtkDataObject* input) { this->SetInputDataInternal(0, input); }

  /// Write the input. Returns 1 on success, 0 on error (reported with vtkErrorMacro).
  int Write();

  vtkTypeBool ProcessRequest(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

protected:
  amMeditWriter();
  ~amMeditWriter() override;
  int FillInputPortInformation(int port, vtkInformation* info) override;
  int WriteData(vtkDataObject* input);

  char* FileName;
  char* RegionArrayName;
  char* PointRefArrayName;
  char* SolutionArrayName;
  vtkTypeBool WriteInterfaces;

private:
  bool LastWriteOk = false;
  amMeditWriter(const amMeditWriter&) = delete;
  void operator=(const amMeditWriter&) = delete;
};

#endif
