/**
 * @class   amTetrahedralize
 * @brief   Conforming multi-region tetrahedral mesh of a labelled multi-material surface
 *          (TetGen constrained Delaunay refinement, the paper's "GHS3d" stage).
 *
 * Input: the conforming surface of amLabelSurface / amMetricRemeshing: triangles with the
 * 2-component cell array "Labels" (regions on either side, the normal pointing from Labels[0]
 * into Labels[1]); every interface a facet of the piecewise linear complex TetGen meshes.
 * Before meshing, each region's boundary must be closed (an open edge is an error naming its
 * triangles), no triangle may be degenerate or carry one label on both sides, and every region
 * must enclose a volume. A self-intersecting surface makes TetGen stop; the error then names the
 * crossing triangles (CGAL exact test).
 *
 * Sizing: each surface vertex's size is the mean length of its edges (or, when present, the
 * point array SizeArrayName, e.g. "Size" of amCurvatureMetric). Inside, a graded size field
 * h(x) = min(MaximumSize, min_i (h_i + (Gradation - 1)|x - p_i|)) (amGradedSizeField) drives
 * TetGen's refinement: a tetrahedron is split when its circumradius exceeds 0.75 h at its
 * centroid, so elements grow away from the surface at the gradation rate. Quality: TetGen's
 * radius-edge bound (MaximumRadiusEdgeRatio) and dihedral bound (MinimumDihedralAngle), then its
 * mesh optimisation (flips and smoothing, OptimizationLevel).
 *
 * Regions: no seed point can be misplaced, because none is used. The tetrahedra are grouped into
 * the connected sets that the surface triangles separate (face adjacency), and each set takes
 * its label from the triangles bounding it, on the side it lies: a thin or non-convex organ, or
 * one with several components (ribs), is labelled exactly. A set bounded inconsistently is an
 * error; sets of BackgroundLabel (outside, cavities) are dropped.
 *
 * With PreserveSurface (default, TetGen -Y) the boundary and interface triangles of the output
 * are the input triangles and the input points come first, in order, except where
 * MaximumSurfaceDeviation lets the surface move to free slivers. No tetrahedron then spans an
 * interface, so with ParallelGroups the regions in two groups of about equal work are meshed by
 * two TetGen processes at once and put together (amTetGenParts; NumberOfGroups says whether they
 * were): the groups depend on the surface alone, so the mesh is the same on any number of cores.
 *
 * Output port 0: vtkUnstructuredGrid of tetrahedra (positive volume), cell data "Region",
 * point data "SurfacePointId" (index of the input surface point, -1 inside).
 * Output port 1: the boundary and interface triangles on the output points, cell data "Labels"
 * (as the input, same orientation), "SourceTriangle" (input triangle), and "Tetra" (2 components:
 * the tetrahedron on the Labels[0] side and on the Labels[1] side, -1 for background).
 *
 * References: H. Si, TetGen, a Delaunay-based quality tetrahedral mesh generator, ACM TOMS 41(2),
 * 2015; the CEMRACS 2004 paper (Generation of computational meshes from MRI and CT-scan data),
 * whose quality measure and Table 1 amMeshQuality reproduces.
 *
 * @sa amMetricRemeshing amLabelMapTetrahedralize amMeshQuality
 */
#ifndef amTetrahedralize_h
#define amTetrahedralize_h

#include "AnatomeshFiltersVolumeModule.h" // export macro
#include "vtkUnstructuredGridAlgorithm.h"

class ANATOMESHFILTERSVOLUME_EXPORT amTetrahedralize : public vtkUnstructuredGridAlgorithm
{
public:
  static amTetrahedralize* New();
  vtkTypeMacro(amTetrahedralize, vtkUnstructuredGridAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// Label of the outside, not meshed (default 0).
  vtkSetMacro(BackgroundLabel, int);
  vtkGetMacro(BackgroundLabel, int);
  ///@}

  ///@{
  /// Keep the input triangles exactly (default on). Off lets TetGen split them.
  vtkSetMacro(PreserveSurface, vtkTypeBool);
  vtkGetMacro(PreserveSurface, vtkTypeBool);
  vtkBooleanMacro(PreserveSurface, vtkTypeBool);
  ///@}

  ///@{
  /// With PreserveSurface, mesh the regions in two groups of about equal work by two TetGen
  /// processes at once (default off). The mesh is then another one of the same quality (each
  /// group's Steiner points placed without the other's), which on a coarse heart shifts the
  /// simulation's activation times by a few ms: off keeps one run's mesh.
  vtkSetMacro(ParallelGroups, vtkTypeBool);
  vtkGetMacro(ParallelGroups, vtkTypeBool);
  vtkBooleanMacro(ParallelGroups, vtkTypeBool);
  ///@}

  ///@{
  /// Largest circumradius-to-shortest-edge ratio of the refinement (default 1.5; TetGen -q).
  vtkSetClampMacro(MaximumRadiusEdgeRatio, double, 1.0, 100.0);
  vtkGetMacro(MaximumRadiusEdgeRatio, double);
  ///@}

  ///@{
  /// Smallest dihedral angle aimed at, degrees (default 12; TetGen -q /angle).
  vtkSetClampMacro(MinimumDihedralAngle, double, 0.0, 30.0);
  vtkGetMacro(MinimumDihedralAngle, double);
  ///@}

  ///@{
  /// Size growth bound away from the surface (default 1.3: sizes grow by at most 0.3 mm per mm).
  vtkSetClampMacro(Gradation, double, 1.0, 10.0);
  vtkGetMacro(Gradation, double);
  ///@}

  ///@{
  /// Largest element size, mm (default 0: bounded by the gradation only).
  vtkSetClampMacro(MaximumSize, double, 0.0, 1e6);
  vtkGetMacro(MaximumSize, double);
  ///@}

  ///@{
  /// Point-data array of the input giving the size at each surface vertex, mm (default "Size";
  /// when absent, the mean length of the vertex's edges is used).
  vtkSetStringMacro(SizeArrayName);
  vtkGetStringMacro(SizeArrayName);
  ///@}

  ///@{
  /// TetGen's optimisation level 0-10 (default 3; TetGen -O).
  vtkSetClampMacro(OptimizationLevel, int, 0, 10);
  vtkGetMacro(OptimizationLevel, int);
  ///@}

  ///@{
  /// Improve the elements after TetGen (default on): 2-3 flips and edge removals that make the
  /// worst element they touch better, for the worst elements no flip mends the split of a free
  /// edge or face, smoothing and local search on the vertices that are not on the surface
  /// (amTetraMeshOptimizer). The surface and interface triangles stay exactly as
  /// they are, and every tetrahedron keeps its region.
  vtkSetMacro(ImproveQuality, vtkTypeBool);
  vtkGetMacro(ImproveQuality, vtkTypeBool);
  vtkBooleanMacro(ImproveQuality, vtkTypeBool);
  ///@}

  ///@{
  /// Rounds of flips and smoothing of the improvement (default 4; it stops earlier when a round
  /// changes nothing).
  vtkSetClampMacro(ImprovementPasses, int, 0, 100);
  vtkGetMacro(ImprovementPasses, int);
  ///@}

  ///@{
  /// How far (mm) the improvement may move the surface to free slivers (default 0.2; 0: the
  /// surface stays exactly the input's). Where interfaces meet at a junction curve at a small
  /// angle, or a surface triangle lies almost flat on another, no element can have Q <= 10 and
  /// dihedral angles >= 10 degrees unless the surface moves. Around the elements that flips and
  /// moves leave above Q 10 or below 10 degrees, surface vertices slide, such an element takes
  /// the region across its surface face, or a surface edge is split at its midpoint; the
  /// two-sided Hausdorff distance between the surface before and after is measured and kept
  /// within this bound (SurfaceDeviation). Which slivers those rounds free depends on how far
  /// each operation may move the surface: up to four such budgets within the bound are tried,
  /// four more with the regions changed before any slide where those leave slivers, four more
  /// where those still do with a short surface edge of each sliver first collapsed along its
  /// interface or junction curve (where a junction curve zigzags between elements, or a vertex
  /// inside an interface sits next to one), and the result with the fewest slivers kept. The triangles of output port 1
  /// are then the mesh's faces anew: those that remain keep their cell data, new ones have SourceTriangle -1. The
  /// mesh's surface is thus within the remeshing's Hausdorff distance plus SurfaceDeviation of
  /// the label surface.
  /// Default -1: half the tolerance the surface was remeshed to (its field data "Tolerance", from
  /// amMetricRemeshing), else 0.2 mm; SurfaceDeviationUsed gives the value of the last run.
  vtkSetClampMacro(MaximumSurfaceDeviation, double, -1.0, 1e6);
  vtkGetMacro(MaximumSurfaceDeviation, double);
  vtkGetMacro(SurfaceDeviationUsed, double);
  ///@}

  ///@{
  /// Results of the last run; the quality figures are TetGen's, before the improvement (Q as in
  /// amMeshQuality; 0 when no improvement ran). SurfaceDeviation: how far slivers that changed
  /// region moved the surface (mm); NumberOfSlivers: elements left above Q 10 or below 10
  /// degrees, checked on every run (improved or not); any is a warning with the worst one's place.
  vtkGetMacro(NumberOfTetrahedra, vtkIdType);
  vtkGetMacro(NumberOfSteinerPoints, vtkIdType);
  vtkGetMacro(WorstQualityBeforeImprovement, double);
  vtkGetMacro(MeanQualityBeforeImprovement, double);
  vtkGetMacro(SurfaceDeviation, double);
  vtkGetMacro(NumberOfSlivers, vtkIdType);
  /// Regions of at least 1 cm^3 of voxels whose mesh volume differs from it by more than 2 %
  /// (when the surface carries its label map's "LabelVoxelVolumes"); each region's figures are in
  /// the output's field data "RegionVolumes" (label, voxel mm^3, mesh mm^3, relative difference).
  vtkGetMacro(NumberOfVolumeMisses, vtkIdType);
  /// The groups of regions TetGen meshed at once (1: the surface in one run).
  vtkGetMacro(NumberOfGroups, int);
  ///@}

protected:
  amTetrahedralize();
  ~amTetrahedralize() override;
  int FillInputPortInformation(int port, vtkInformation* info) override;
  int FillOutputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int BackgroundLabel;
  vtkTypeBool PreserveSurface;
  vtkTypeBool ParallelGroups;
  double MaximumRadiusEdgeRatio;
  double MinimumDihedralAngle;
  double Gradation;
  double MaximumSize;
  char* SizeArrayName;
  int OptimizationLevel;
  vtkTypeBool ImproveQuality;
  int ImprovementPasses;
  double MaximumSurfaceDeviation;
  double SurfaceDeviationUsed = 0.2;
  vtkIdType NumberOfTetrahedra;
  vtkIdType NumberOfSteinerPoints;
  double WorstQualityBeforeImprovement;
  double MeanQualityBeforeImprovement;
  double SurfaceDeviation;
  vtkIdType NumberOfSlivers;
  vtkIdType NumberOfVolumeMisses;
  int NumberOfGroups;

private:
  amTetrahedralize(const amTetrahedralize&) = delete;
  void operator=(const amTetrahedralize&) = delete;
};

#endif
