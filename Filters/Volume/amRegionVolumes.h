/**
 * @class   amRegionVolumes
 * @brief   A tetrahedral mesh's volume per region against its label map's voxel volume (not
 *          wrapped).
 *
 * amLabelSurface records each label's voxel volume in the surface's field data
 * ("LabelVoxelVolumes": label, mm^3), which smoothing and remeshing carry on. Compare adds field
 * data "RegionVolumes" to the mesh (4 components: label, voxel mm^3, mesh mm^3, relative
 * difference) and returns the regions of at least 'minimum' mm^3 of voxels whose mesh volume
 * differs by more than 'tolerance' (relative), largest difference first. A label with voxels but no
 * tetrahedra is one of them (mesh volume 0).
 */
#ifndef amRegionVolumes_h
#define amRegionVolumes_h

#include <string>
#include <vector>

class vtkDataArray;
class vtkUnstructuredGrid;

class amRegionVolumes
{
public:
  struct Miss
  {
    int Label;
    double Voxels; // mm^3
    double Mesh;   // mm^3
  };

  /// mesh: tetrahedra with the cell array regionArray; voxelVolumes: "LabelVoxelVolumes".
  static std::vector<Miss> Compare(
    vtkUnstructuredGrid* mesh, const char* regionArray, vtkDataArray* voxelVolumes, double minimum, double tolerance);

  /// "label 5 (12.3 cm3 of voxels, 11.9 in the mesh, -3.2 %), ..." for at most 'count' misses.
  static std::string Describe(const std::vector<Miss>& misses, size_t count);

  /// The tetrahedralizers' warning about the misses of Compare(..., 1000 mm^3, 2 %): how many, and
  /// the five largest.
  static std::string Warning(const std::vector<Miss>& misses);
};

#endif
