/**
 * @class   amLabelMapTetrahedralize
 * @brief   Multi-region tetrahedral mesh straight from a label map (CGAL Mesh_3, labeled image
 *          domain): the second backend of the volume stage, next to amTetrahedralize (TetGen).
 *
 * Input: a label map (whole-number scalars of any type and any values, e.g. amMorphologyCleaning's
 * output or an int16 atlas; origin, spacing and direction honoured; non-whole values are an
 * error). Every label other than BackgroundLabel becomes a subdomain: CGAL meshes a compact copy
 * (background 0, the labels 1..K in increasing order; 8-bit up to 255 labels, 16-bit beyond; at most
 * amInputCheck::MaximumLabels, 1000: more distinct values are a scan, refused)
 * and each region is given its own label back.
 * CGAL's Delaunay refinement meshes the map padded with one voxel of background (so the labels on
 * the image's border keep their whole voxels), starts from points on the boundary of every
 * connected component of every label (CGAL's initialize_triangulation_from_labeled_image: a small
 * region is not left to chance), samples the interfaces of the (trilinearly interpolated) label function and refines
 * until the criteria hold: FacetDistance (surface approximation, mm),
 * FacetSize and FacetAngle (surface triangles), CellSize and CellRadiusEdgeRatio (tetrahedra).
 * With ProtectJunctions (default), the curves where three or more labels meet (and where labels
 * meet the image border) are found in the image (CGAL's polylines_to_protect) and protected by
 * balls of EdgeSize, so junctions come out as sharp shared edges. Then the optional optimisers:
 * ODT, Lloyd, sliver perturbation, sliver exudation (CGAL's order). A fixed random seed makes the
 * result reproducible.
 *
 * Output conventions are those of amTetrahedralize, so downstream filters do not care which
 * backend ran: port 0, tetrahedra (positive volume) with cell data "Region" (the label);
 * port 1, the boundary and interface triangles with cell data "Labels" (2 components: the higher
 * label first, the normal pointing from Labels[0] into Labels[1]) and "Tetra" (the tetrahedron on
 * either side, -1 outside).
 *
 * Kept in its own translation unit: CGAL Mesh_3 is heavy to compile.
 *
 * Reference: CGAL 3D Mesh Generation (Mesh_3), P. Alliez, C. Jamin, L. Rineau, S. Tayeb, J. Tournois,
 * M. Yvinec; J.-D. Boissonnat and S. Oudot, Provably good sampling and meshing of surfaces,
 * Graphical Models 67, 2005.
 *
 * @sa amTetrahedralize amMeshQuality
 */
#ifndef amLabelMapTetrahedralize_h
#define amLabelMapTetrahedralize_h

#include "AnatomeshFiltersVolumeModule.h" // export macro
#include "vtkUnstructuredGridAlgorithm.h"

#include <vector> // for RegionCellSizes

class ANATOMESHFILTERSVOLUME_EXPORT amLabelMapTetrahedralize : public vtkUnstructuredGridAlgorithm
{
public:
  static amLabelMapTetrahedralize* New();
  vtkTypeMacro(amLabelMapTetrahedralize, vtkUnstructuredGridAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// Label of the outside, not meshed (default 0).
  vtkSetMacro(BackgroundLabel, int);
  vtkGetMacro(BackgroundLabel, int);
  ///@}

  ///@{
  /// Largest distance between a surface triangle's circumcentre and the interface, mm (default 0.5).
  vtkSetClampMacro(FacetDistance, double, 1e-6, 1e6);
  vtkGetMacro(FacetDistance, double);
  ///@}

  ///@{
  /// Largest surface Delaunay ball radius, mm (default 4).
  vtkSetClampMacro(FacetSize, double, 1e-6, 1e6);
  vtkGetMacro(FacetSize, double);
  ///@}

  ///@{
  /// Smallest surface triangle angle, degrees (default 30; CGAL guarantees termination up to 30).
  vtkSetClampMacro(FacetAngle, double, 0.0, 30.0);
  vtkGetMacro(FacetAngle, double);
  ///@}

  ///@{
  /// Largest tetrahedron circumradius, mm (default 8).
  vtkSetClampMacro(CellSize, double, 1e-6, 1e6);
  vtkGetMacro(CellSize, double);
  ///@}

  ///@{
  /// Finer (or coarser) tetrahedra in chosen regions: (label, cell size in mm) pairs. In such a
  /// region the largest circumradius is that size instead of CellSize, and the surface triangles
  /// bounding it get the facet size scaled alike (size * FacetSize / CellSize, at most FacetSize;
  /// an interface takes the smaller of its two regions'). E.g. a 2 mm myocardium in a 6 mm torso
  /// for the electrophysiology. Default: none (CellSize everywhere).
  void AddRegionCellSize(double label, double size);
  void RemoveAllRegionCellSizes();
  const std::vector<double>& GetRegionCellSizes() const { return this->RegionCellSizes; }
  ///@}

  ///@{
  /// Largest circumradius-to-shortest-edge ratio (default 2; CGAL needs >= 2 to terminate).
  vtkSetClampMacro(CellRadiusEdgeRatio, double, 1.0, 100.0);
  vtkGetMacro(CellRadiusEdgeRatio, double);
  ///@}

  ///@{
  /// Protect the junction curves found in the image (default on).
  vtkSetMacro(ProtectJunctions, vtkTypeBool);
  vtkGetMacro(ProtectJunctions, vtkTypeBool);
  vtkBooleanMacro(ProtectJunctions, vtkTypeBool);
  ///@}

  ///@{
  /// Size of the protecting balls along junction curves, mm (default 0: FacetSize).
  vtkSetClampMacro(EdgeSize, double, 0.0, 1e6);
  vtkGetMacro(EdgeSize, double);
  ///@}

  ///@{
  /// Optimisers, in CGAL's order: ODT and Lloyd smoothing (default off), sliver perturbation and
  /// exudation (default on).
  vtkSetMacro(Odt, vtkTypeBool);
  vtkGetMacro(Odt, vtkTypeBool);
  vtkBooleanMacro(Odt, vtkTypeBool);
  vtkSetMacro(Lloyd, vtkTypeBool);
  vtkGetMacro(Lloyd, vtkTypeBool);
  vtkBooleanMacro(Lloyd, vtkTypeBool);
  vtkSetMacro(Perturb, vtkTypeBool);
  vtkGetMacro(Perturb, vtkTypeBool);
  vtkBooleanMacro(Perturb, vtkTypeBool);
  vtkSetMacro(Exude, vtkTypeBool);
  vtkGetMacro(Exude, vtkTypeBool);
  vtkBooleanMacro(Exude, vtkTypeBool);
  ///@}

  ///@{
  /// Smallest dihedral angle the perturbation and exudation aim for, degrees (default 12).
  vtkSetClampMacro(SliverBound, double, 0.0, 30.0);
  vtkGetMacro(SliverBound, double);
  ///@}

  ///@{
  /// Give each region its voxel volume (default on): CGAL's surface passes through the middle of
  /// the label function's transitions and its facets are chords of it, so thin and convex regions
  /// come out smaller (the TotalSegmentator abdomen at 4 mm facets: -8 % on average, -37 % for a
  /// rib). The surface vertices inside one interface move along their normals, by at most
  /// FacetDistance or half the largest voxel spacing, whichever is more (the voxels' staircase
  /// lies that far from any smooth surface through them), one offset per interface chosen so
  /// that every region gets its voxel volume
  /// (amTetraMeshOptimizer's TargetVolumes), where no element falls below Q 2.5 (or its star's
  /// worst); the junction curves stay. NumberOfVolumeMisses tells what is left,
  /// VolumeDisplacement how far a surface vertex moved (mm).
  vtkSetMacro(PreserveVolumes, vtkTypeBool);
  vtkGetMacro(PreserveVolumes, vtkTypeBool);
  vtkBooleanMacro(PreserveVolumes, vtkTypeBool);
  vtkGetMacro(VolumeDisplacement, double);
  ///@}

  ///@{
  /// After CGAL, improve the elements as amTetrahedralize does (default on: CGAL's perturbation
  /// and exudation leave elements of Q 13-40 and 1.4-6 degrees on real label maps, the
  /// improvement none above Q 10 or under 10 degrees): edge removals and 2-3 flips that make the worst element they
  /// touch better, smoothing and local search on the vertices off the surface (amTetraMeshOptimizer). The surface and
  /// interface triangles stay as CGAL made them, but for the slivers that need them to move (at most
  /// MaximumSurfaceDeviation, mm, default 0.2; 0: never; see amTetrahedralize). ImprovementPasses: rounds (default 4).
  /// NumberOfSlivers: elements left above Q 10 or below 10 degrees, checked on every run (improved or not); any is a
  /// warning with the worst one's place; SurfaceDeviation: how far the surface moved (mm).
  vtkSetMacro(ImproveQuality, vtkTypeBool);
  vtkGetMacro(ImproveQuality, vtkTypeBool);
  vtkBooleanMacro(ImproveQuality, vtkTypeBool);
  vtkSetClampMacro(ImprovementPasses, int, 0, 100);
  vtkGetMacro(ImprovementPasses, int);
  vtkSetClampMacro(MaximumSurfaceDeviation, double, 0.0, 1e6);
  vtkGetMacro(MaximumSurfaceDeviation, double);
  vtkGetMacro(NumberOfSlivers, vtkIdType);
  /// Regions of at least 1 cm^3 of voxels whose mesh volume differs from it by more than 2 %; each
  /// region's figures are in the output's field data "RegionVolumes" (label, voxel mm^3, mesh
  /// mm^3, relative difference).
  vtkGetMacro(NumberOfVolumeMisses, vtkIdType);
  vtkGetMacro(SurfaceDeviation, double);
  ///@}

  /// Tetrahedra of the last run.
  vtkGetMacro(NumberOfTetrahedra, vtkIdType);

protected:
  amLabelMapTetrahedralize();
  ~amLabelMapTetrahedralize() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int FillOutputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int BackgroundLabel;
  double FacetDistance;
  double FacetSize;
  double FacetAngle;
  double CellSize;
  double CellRadiusEdgeRatio;
  std::vector<double> RegionCellSizes;
  vtkTypeBool ProtectJunctions;
  double EdgeSize;
  vtkTypeBool Odt;
  vtkTypeBool Lloyd;
  vtkTypeBool Perturb;
  vtkTypeBool Exude;
  double SliverBound;
  vtkTypeBool PreserveVolumes;
  double VolumeDisplacement = 0;
  vtkTypeBool ImproveQuality;
  int ImprovementPasses;
  double MaximumSurfaceDeviation;
  vtkIdType NumberOfSlivers;
  vtkIdType NumberOfVolumeMisses = 0;
  double SurfaceDeviation;
  vtkIdType NumberOfTetrahedra;

private:
  amLabelMapTetrahedralize(const amLabelMapTetrahedralize&) = delete;
  void operator=(const amLabelMapTetrahedralize&) = delete;
};

#endif
