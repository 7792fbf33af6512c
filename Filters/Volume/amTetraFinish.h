/**
 * @file    amTetraFinish.h
 * @brief   The last step both tetrahedralizers share (not wrapped): the element improvement, each
 *          region's volume against its voxels, the points no tetrahedron uses removed, and the
 *          element bars checked.
 *
 * amTetrahedralize (TetGen) and amLabelMapTetrahedralize (CGAL Mesh_3) each make a mesh of
 * tetrahedra with cell array "Region" and its boundary and interface triangles (cell array
 * "Labels") on the same points; from there on the two are finished alike, so that both report
 * the same figures with the same words.
 */
#ifndef amTetraFinish_h
#define amTetraFinish_h

#include "amRegionVolumes.h"
#include "amTetraMeshOptimizer.h"

#include "vtkType.h"

#include <functional>
#include <string>
#include <vector>

class vtkDataArray;
class vtkPolyData;
class vtkUnstructuredGrid;

namespace amTetraFinish
{
/// Regions smaller than this (mm^3 of voxels, 1 cm^3) are not held to their volume: a few voxels'
/// staircase has no one volume a smooth surface should keep.
constexpr double MinimumRegionVolume = 1000.0;
/// A region larger than that whose mesh volume differs from its voxels' by more than this
/// (relative) is named in a warning.
constexpr double RegionVolumeTolerance = 0.02;

struct Settings
{
  bool Improve = false;                  // run amTetraMeshOptimizer::ImproveGrid with Options
  amTetraMeshOptimizer::Options Options; // its options
  vtkDataArray* VoxelVolumes = nullptr;  // (label, mm^3) rows; none: volumes not compared
  std::string Remedy;                    // the calling filter's properties that free poor elements
  std::function<void(double)> Progress;  // fraction 0..1 of the improvement
};

struct Result
{
  bool Improved = false;
  amTetraMeshOptimizer::Report Report;             // when Improved
  std::vector<amRegionVolumes::Miss> VolumeMisses; // largest difference first
  std::string VolumeWarning;                       // "" when every region keeps its volume
  std::string BarWarning;                          // "" when the bars hold (amQualityBars)
  vtkIdType Poor = 0;                              // elements that miss a bar
  /// " improvement: ..." for provenance when improved, else "".
  std::string Describe() const;
};

/// Finishes 'mesh' and 'interfaces' in place. False with 'why' when the improvement refuses the
/// data (not of the form above).
bool Run(
  vtkUnstructuredGrid* mesh, vtkPolyData* interfaces, const Settings& settings, Result& result, std::string& why);
}

#endif
