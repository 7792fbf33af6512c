/**
 * @file    amLabelMapMesh3.h
 * @brief   CGAL Mesh_3 on a label map (not wrapped): the meshing core of amLabelMapTetrahedralize,
 *          which finishes its result (amTetraFinish) and records it.
 *
 * Any whole-number labels, any count: CGAL meshes a compact image (background 0, the other
 * labels 1..K in increasing order, 8-bit up to 255 labels, 16-bit beyond) padded by one voxel of
 * background, and the regions get their own labels back. Every connected component of every
 * label gets initial points; junction curves are protected when asked; the run is seeded, so the
 * same input gives the same mesh. The one translation unit of the module that includes Mesh_3.
 */
#ifndef amLabelMapMesh3_h
#define amLabelMapMesh3_h

#include "vtkType.h"

#include <functional>
#include <map>
#include <string>
#include <vector>

class vtkDataArray;
class vtkPolyData;
class vtkUnstructuredGrid;

namespace amLabelMapMesh3
{
/// amLabelMapTetrahedralize's properties of the same names (mm, degrees).
struct Settings
{
  int Background = 0;
  double FacetDistance = 0.5, FacetSize = 4.0, FacetAngle = 30.0, CellSize = 8.0, CellRadiusEdgeRatio = 2.0;
  bool ProtectJunctions = true;
  double EdgeSize = 0.0; // 0: FacetSize
  bool Odt = false, Lloyd = false, Perturb = true, Exude = true;
  double SliverBound = 12.0;
  std::vector<double> RegionCellSizes;  // (label, mm) pairs
  std::function<void(double)> Progress; // 0 .. 0.9 of the filter's progress
};

/// The image's geometry: voxels x fastest; direction row-major (world = origin + D (index * spacing)).
struct Grid
{
  int Dims[3];
  double Spacing[3];
  double Origin[3];
  const double* Direction;
};

struct Result
{
  std::size_t Curves = 0;            // junction polylines protected
  double EdgeSize = 0;               // mm, as used
  std::vector<std::string> Warnings; // e.g. a RegionCellSizes label not in the map
};

/// Meshes the labels of 'scalars' (whole numbers, voxelsOf: each label's voxel count, as
/// amInputCheck::LabelCounts gives them) into 'grid' (tetrahedra with cell data "Region", in the
/// world frame) and 'interfaces' (every facet of the complex once, the higher label first, with
/// cell data "Labels" and "Tetra" on the same points). False with 'why' on bad settings or when
/// CGAL fails or makes no tetrahedron.
bool Mesh(vtkDataArray* scalars, const Grid& grid, const std::map<int, vtkIdType>& voxelsOf, const Settings& s,
  vtkUnstructuredGrid* output, vtkPolyData* interfaces, Result& result, std::string& why);
}

#endif
