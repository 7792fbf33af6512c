/**
 * @class   amXdmfWriter
 * @brief   Writes a tetrahedral mesh as XDMF 3 (the heavy data in HDF5, or inline): the mesh with its
 *          cell tags (regions), and its facet tags (interfaces and outer boundary), as FEniCSx's
 *          XDMFFile and meshio read them.
 *
 * Two files, one grid each, each with its heavy data in an HDF5 file of the same name (NAME.h5,
 * NAME_facets.h5: datasets /topology, /geometry and one per attribute; HeavyDataFormat HDF5, the default)
 * or inline as text (XML):
 * - FileName (NAME.xdmf), grid "mesh": Topology Tetrahedron and Geometry XYZ (mm), only the points the
 *   tetrahedra use, renumbered in their order, and the Attribute "cell_tags" (Center Cell), the cell
 *   data RegionArrayName ("Region"), then, where the mesh has them, the cell vectors "Fibers" and
 *   "Sheets" (Ventricular Fibres');
 * - NAME_facets.xdmf, grid "facet_tags": the interface and boundary triangles (amTetraFaces: each
 *   face where the region changes, once, its normal from the higher region into the lower one) on
 *   the same points, with the Attribute "facet_tags", tagged like the Medit and Gmsh writers'
 *   references (1000 x higher + lower, 0 for the outside of the mesh).
 * Each grid's Information lists the tags' names (meshio's field data: the organ's name where the
 * mesh's field data LabelNames has it, "higher | lower" per interface); a comment states the units
 * (mm) and the frame (LPS). Numbers are written in their shortest form that reads back to the same
 * value; the HDF5 files hold no modification times, so the same mesh gives the same bytes. The files
 * appear atomically together (the .h5 files before the .xdmf files that name them); any cell other
 * than a tetrahedron, a non-finite
 * coordinate or a non-whole region is an error naming it.
 *
 * In FEniCSx: with XDMFFile(comm, "NAME.xdmf", "r") as f: mesh = f.read_mesh(name="mesh");
 * cells = f.read_meshtags(mesh, name="mesh"); then mesh.topology.create_connectivity(2, 3) and,
 * from NAME_facets.xdmf, facets = f.read_meshtags(mesh, name="facet_tags").
 */
#ifndef amXdmfWriter_h
#define amXdmfWriter_h

#include "AnatomeshIOMeshModule.h" // export macro
#include "vtkAlgorithm.h"

#include <string>

class ANATOMESHIOMESH_EXPORT amXdmfWriter : public vtkAlgorithm
{
public:
  static amXdmfWriter* New();
  vtkTypeMacro(amXdmfWriter, vtkAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// Target .xdmf file.
  vtkSetStringMacro(FileName);
  vtkGetStringMacro(FileName);
  ///@}

  ///@{
  /// Cell-data array holding region labels (default "Region").
  vtkSetStringMacro(RegionArrayName);
  vtkGetStringMacro(RegionArrayName);
  ///@}

  enum HeavyDataFormats
  {
    XML = 0,
    HDF5 = 1
  };

  ///@{
  /// Where the arrays go: HDF5 (default; NAME.h5 beside NAME.xdmf, which FEniCSx needs) or XML (inline
  /// text, one self-contained file; meshio and ParaView read both).
  vtkSetClampMacro(HeavyDataFormat, int, XML, HDF5);
  vtkGetMacro(HeavyDataFormat, int);
  ///@}

  /// Set the mesh to write without a pipeline connection.
  void SetInputData(vtkDataObject* input) { this->SetInputDataInternal(0, input); }

  /// Write the input. Returns 1 on success, 0 on error (reported with vtkErrorMacro).
  int Write();

  /// The facets' file beside a mesh file: NAME.xdmf gives NAME_facets.xdmf.
  static std::string FacetsFileName(const std::string& path);

  /// The HDF5 file of an .xdmf file: NAME.xdmf gives NAME.h5.
  static std::string HeavyDataFileName(const std::string& path);

  vtkTypeBool ProcessRequest(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

protected:
  amXdmfWriter();
  ~amXdmfWriter() override;
  int FillInputPortInformation(int port, vtkInformation* info) override;
  int WriteData(vtkDataObject* input);

  char* FileName;
  char* RegionArrayName;
  int HeavyDataFormat;

private:
  bool LastWriteOk = false;
  amXdmfWriter(const amXdmfWriter&) = delete;
  void operator=(const amXdmfWriter&) = delete;
};

#endif
