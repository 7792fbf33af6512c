/**
 * @class   amMeshQuality
 * @brief   Element quality of a tetrahedral mesh as the paper measures it, and its Table 1.
 *
 * Per tetrahedron (cell data of output port 0, a shallow copy of the input's tetrahedra):
 * - "Quality": Q = alpha * h_max / rho, the longest edge over the inradius, alpha = sqrt(6)/12 so
 *   a regular tetrahedron scores 1 and worse elements score higher (flat or degenerate: +inf);
 * - "MinimumDihedralAngle", "MaximumDihedralAngle" (degrees);
 * - "RadiusRatio": circumradius over three times the inradius (VTK's radius ratio, 1 for regular);
 * - "Volume" (signed, mm^3: a non-positive volume is an inverted or flat element).
 *
 * Output port 1: a vtkTable in the layout of the paper's Table 1, one row per region (cell data
 * RegionArrayName, default "Region"; one row "all" when absent) and a last row for the whole
 * mesh: Region, np (vertices), nt (boundary triangles: faces of the region's tetrahedra not shared
 * with another of its tetrahedra; for the whole mesh, every interface and outer face once), ne
 * (tetrahedra), MeanQuality, MinimumQuality, MaximumQuality, MinimumDihedralAngle,
 * MaximumDihedralAngle, Volume, InvertedTetrahedra. Region is -1 in the whole-mesh row.
 *
 * Other cells beside the tetrahedra (the boundary triangles of a mesh read back from Medit or
 * Gmsh) are left out: output port 0 then holds the tetrahedra alone, with their cell data. A mesh
 * without a tetrahedron is an error.
 *
 * Reference: the CEMRACS 2004 paper, Table 1 (the quality Q = alpha h_max / rho of each
 * tetrahedron, 1 for the regular one).
 *
 * @sa amTetrahedralize amLabelMapTetrahedralize
 */
#ifndef amMeshQuality_h
#define amMeshQuality_h

#include "AnatomeshFiltersVolumeModule.h" // export macro
#include "vtkUnstructuredGridAlgorithm.h"

class ANATOMESHFILTERSVOLUME_EXPORT amMeshQuality : public vtkUnstructuredGridAlgorithm
{
public:
  static amMeshQuality* New();
  vtkTypeMacro(amMeshQuality, vtkUnstructuredGridAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// Cell array with the region label of each tetrahedron (default "Region").
  vtkSetStringMacro(RegionArrayName);
  vtkGetStringMacro(RegionArrayName);
  ///@}

  ///@{
  /// Whole-mesh figures of the last run.
  vtkGetMacro(MeanQuality, double);
  vtkGetMacro(MaximumQuality, double);
  vtkGetMacro(MinimumDihedralAngle, double);
  vtkGetMacro(MaximumDihedralAngle, double);
  vtkGetMacro(NumberOfInvertedTetrahedra, vtkIdType);
  ///@}

  /// Quality measures of one tetrahedron: Q, min/max dihedral (degrees), radius ratio, volume.
  static void TetraQuality(const double p0[3], const double p1[3], const double p2[3], const double p3[3],
    double& quality, double& minDihedral, double& maxDihedral, double& radiusRatio, double& volume);

  /// The tetrahedra of 'grid' with their cell data, copied into 'tetrahedra' when the grid has
  /// other cells too (left empty when every cell is a tetrahedron); false when it has none.
  static bool TetrahedraOf(vtkUnstructuredGrid* grid, vtkUnstructuredGrid* tetrahedra);

protected:
  amMeshQuality();
  ~amMeshQuality() override;
  int FillOutputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  char* RegionArrayName;
  double MeanQuality;
  double MaximumQuality;
  double MinimumDihedralAngle;
  double MaximumDihedralAngle;
  vtkIdType NumberOfInvertedTetrahedra;

private:
  amMeshQuality(const amMeshQuality&) = delete;
  void operator=(const amMeshQuality&) = delete;
};

#endif
