/**
 * @class   amTetraMeshOptimizer
 * @brief   Quality improvement of a tetrahedral mesh that keeps its surface (not wrapped).
 *
 * Improves the worst elements and the mean of the paper's quality Q = alpha h_max / rho, and the
 * dihedral angles, by local operations, each accepted only when it makes the worst element it
 * touches better (measured by Objective: 1/Q, or the dihedral sines where those are worse):
 * - topological: 2-3 face flips and edge removal (3-2 flip and its generalisation: the tetrahedra
 *   around an edge replaced by the best triangulation of their ring, Klincsek's dynamic program
 *   as in Shewchuk, "Two discrete optimization algorithms for the topological improvement of
 *   tetrahedral meshes", 2002), for rings of up to MaxRing vertices; for the worst elements
 *   (Q above SplitQuality) that no flip mends, such as a sliver whose four vertices lie on the
 *   surface, the split of a free edge, else of a free face (a sliver with three faces on the
 *   surface has no free edge), whose new vertex then moves to the best place found;
 * - geometric: smoothing of free vertices (candidate positions: the centroid of the star's
 *   centroids, weighted by volume, and the neighbours' mean), kept when the star's worst element
 *   is not worse and the mean of its inverse objectives better; then a local search that moves each vertex of a bad
 *   element along the numerical gradient of its star's worst quality.
 *
 * The fixed faces (the surface and interface triangles) and fixed vertices (those on them) never
 * change, so the boundary and every interface stay exactly as they were; an operation never
 * crosses a fixed face, so every tetrahedron keeps its region. The exception, off unless
 * Options::MaximumSurfaceDeviation is positive: around the slivers the operations above leave,
 * surface vertices slide, elements change region and surface edges are split (see Options),
 * which moves the surface by at most that distance. Deterministic, the same mesh on any number of
 * cores: the flips are planned on the threads and taken in order; the smoothing goes over classes
 * of vertices no two neighbours share (a greedy colouring), each class on the threads at once.
 */
#ifndef amTetraMeshOptimizer_h
#define amTetraMeshOptimizer_h

#include "amTetraImproveOptions.h"

#include <array>
#include <functional>
#include <map>
#include <string>
#include <vector>

class vtkPolyData;
class vtkUnstructuredGrid;

class amTetraMeshOptimizer
{
public:
  // The improvement's options and report (Improvement/amTetraImproveOptions.h).
  using Options = amTetraImprove::Options;
  using Report = amTetraImprove::Report;

  /// points: 3 doubles per vertex (free vertices move, split vertices are appended); tets: 4 vertex ids per
  /// tetrahedron, positively oriented (rewritten); regions: one label per tetrahedron (rewritten alike); fixedFaces:
  /// triangles that must remain faces (the surface); the vertices of those faces and of the mesh's boundary are fixed.
  /// progress(fraction) is called between passes. When elements change region (Report::Relabels), the surface is no
  /// longer 'fixedFaces': it is the faces between different regions and those of the mesh's boundary.
  static Report Optimize(std::vector<double>& points, std::vector<std::array<int, 4>>& tets, std::vector<int>& regions,
    const std::vector<std::array<int, 3>>& fixedFaces, const Options& options,
    const std::function<void(double)>& progress = nullptr);

  /// The same on a mesh as amTetrahedralize and amLabelMapTetrahedralize make it: 'grid' holds
  /// the tetrahedra with cell array "Region", 'surface' every boundary and interface triangle on
  /// the same vtkPoints with cell array "Labels" (the normal pointing into the Labels[1] side).
  /// Points move in place (new ones from edge splits are appended, with -1 in every point-data
  /// array), the cells are replaced (cell data other than Region is dropped), and
  /// the surface's "Tetra" array (the tetrahedron on each side, -1 for none) is recomputed.
  /// False, with why, when the data is not of that form.
  static bool ImproveGrid(vtkUnstructuredGrid* grid, vtkPolyData* surface, const Options& options, Report& report,
    std::string& why, const std::function<void(double)>& progress = nullptr);

  /// What the operations maximise (amTetraImprove::Objective).
  static double Objective(const double* a, const double* b, const double* c, const double* d)
  {
    return amTetraImprove::Objective(a, b, c, d);
  }
};

#endif
