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
  struct Options
  {
    int Passes = 4; // rounds of flips + smoothing
    // Thresholds in Q, applied to the objective (1/Q or the dihedral term, whichever is worse):
    double FlipQuality = 1.6;   // elements above this get flips
    double SearchQuality = 2.5; // the vertices of elements above this get the local search
    int MaxRing = 7;            // largest edge ring the edge removal triangulates
    double SplitQuality = 5;    // elements with Q above this that no flip mends get an edge split
    // Slivers: elements with Q above SliverQuality or a dihedral angle below SliverDihedral
    // (degrees) that the rounds above leave. Where interfaces meet at a junction curve at a small
    // angle, or a surface triangle lies almost flat on another, no element there can be better
    // than the surface allows. When MaximumSurfaceDeviation (mm) is positive, the surface may
    // move that far to free them (amTetraImproveSlivers.cxx): their surface vertices slide, those
    // still bad take the region across a surface face (or leave the mesh at its boundary), a
    // surface edge of the rest (where its dihedral angle is smallest, else the longest) is split
    // at its midpoint, and the flips and moves run again around them, for up to SliverRounds
    // rounds. The deviation is measured (two-sided, against the surface as it was) and kept
    // within the bound; the attempts, their order and budgets: amTetraImproveSchedule.h.
    double SliverQuality = 10;
    double SliverDihedral = 10;
    double MaximumSurfaceDeviation = 0;
    int SliverRounds = 4;
    // Region volumes: where TargetVolumes (label -> mm^3) is not empty and MaximumVolumeOffset
    // (mm) positive, the surface vertices inside one interface first move along their normals,
    // by at most that distance, until each region has its target (amTetraImproveVolumes.cxx),
    // where no element falls below Q SearchQuality (or its star's worst) and the boundary does
    // not run into itself. Junction curves stay.
    std::map<int, double> TargetVolumes;
    double MaximumVolumeOffset = 0;
    int VolumeRounds = 4;
  };
  struct Report
  {
    double WorstBefore = 0, WorstAfter = 0, MeanBefore = 0, MeanAfter = 0;
    long Flips23 = 0, EdgeRemovals = 0, EdgeSplits = 0, FaceSplits = 0, Moves = 0;
    long Relabels = 0;             // elements that changed region (or left the mesh)
    long SurfaceSplits = 0;        // surface edges split at their midpoints near slivers
    long SurfaceCollapses = 0;     // surface edges of slivers collapsed along their interface or curve
    long SurfaceMoves = 0;         // slides of surface vertices
    long VolumeMoves = 0;          // surface vertex moves that gave regions their volume
    double VolumeDisplacement = 0; // the farthest those moved a vertex (mm)
    double SurfaceDeviation = 0;   // the largest displacement of the surface they caused (mm)
    long Slivers = 0;              // elements still above SliverQuality or below SliverDihedral
    /// One line for provenance: worst and mean Q before -> after, and the operations done.
    std::string Describe() const;
  };

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

  /// What the operations maximise, in (0, 1] (1: regular), -1 when inverted or flat: the smaller
  /// of 1/Q and the smallest sine of the dihedral angles over that of the regular tetrahedron, so
  /// that no operation trades a dihedral angle for Q (slivers have both small).
  static double Objective(const double* a, const double* b, const double* c, const double* d);
};

#endif
