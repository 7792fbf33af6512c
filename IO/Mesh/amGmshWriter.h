/**
 * @class   amGmshWriter
 * @brief   Writes a tetrahedral mesh as a Gmsh 4.1 ASCII file (.msh) with one physical volume
 *          group per region.
 *
 * Input: a vtkUnstructuredGrid of tetrahedra (e.g. Tetrahedralize or Label Map Tetrahedralize)
 * with the cell-data array RegionArrayName (default "Region"; one region 1 when absent). Each
 * region becomes an elementary volume entity and a physical group whose tag is the region label
 * (labels must be positive: Gmsh tags are) and whose name is the organ's where the mesh's field
 * data "LabelNames" (carried from the label map) has it, else "Region <label>"; nodes are numbered
 * from 1 in point order, elements from 1 in cell order. Coordinates are written with 17 significant
 * digits. Any other cell type, a non-positive label or a non-finite coordinate is an error naming
 * it. The file appears atomically (temporary name, then rename).
 *
 * WriteInterfaces (default on): the interface and boundary triangles (amTetraFaces: each face where
 * the region changes, once, its normal from the higher region into the lower one, outwards on the
 * boundary) as one physical surface per pair of regions, tagged like the Medit writer's references
 * (1000 × higher + lower, 0 for the outside) and named "<higher> | <lower>" (e.g. "Myocardium |
 * LVBlood", "Body | Outside"), so a solver can put boundary conditions on organ surfaces; region
 * labels must then lie in 1..999. Each volume entity lists its bounding surfaces (Gmsh's
 * getBoundary), negative where the surface's normal points into it.
 */
#ifndef amGmshWriter_h
#define amGmshWriter_h

#include "AnatomeshIOMeshModule.h" // export macro
#include "vtkAlgorithm.h"

class ANATOMESHIOMESH_EXPORT amGmshWriter : public vtkAlgorithm
{
public:
  static amGmshWriter* New();
  vtkTypeMacro(amGmshWriter, vtkAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// Target .msh file.
  vtkSetStringMacro(FileName);
  vtkGetStringMacro(FileName);
  ///@}

  ///@{
  /// Cell-data array holding region labels (default "Region").
  vtkSetStringMacro(RegionArrayName);
  vtkGetStringMacro(RegionArrayName);
  ///@}

  ///@{
  /// Also write the interface and boundary triangles as physical surfaces (default on).
  vtkSetMacro(WriteInterfaces, vtkTypeBool);
  vtkGetMacro(WriteInterfaces, vtkTypeBool);
  vtkBooleanMacro(WriteInterfaces, vtkTypeBool);
  ///@}

  /// Set the mesh to write without a pipeline connection.
  void SetInputData(vtkDataObject* input) { this->SetInputDataInternal(0, input); }

  /// Write the input. Returns 1 on success, 0 on error (reported with vtkErrorMacro).
  int Write();

  vtkTypeBool ProcessRequest(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

protected:
  amGmshWriter();
  ~amGmshWriter() override;
  int FillInputPortInformation(int port, vtkInformation* info) override;
  int WriteData(vtkDataObject* input);

  char* FileName;
  char* RegionArrayName;
  vtkTypeBool WriteInterfaces;

private:
  bool LastWriteOk = false;
  amGmshWriter(const amGmshWriter&) = delete;
  void operator=(const amGmshWriter&) = delete;
};

#endif
