/**
 * @file    amRemesher.h
 * @brief   MetricRemeshing's algorithm without the pipeline: a labelled triangle surface remeshed
 *          to a metric (sizes per vertex) within a Hausdorff tolerance of the input, every
 *          interface and junction curve kept, the result never self-intersecting.
 *
 * The parts, each in its own file:
 * - Surface (amRemeshSurface): the state the operations change, and the undo copy.
 * - Input (amRemeshInput): the input per interface, with its distance queries.
 * - JunctionCurves (amRemeshJunctionCurves): where three or more regions meet.
 * - Bins (amRemeshBins): the live triangles binned, and the two workers' split plane.
 * - CrossingGuard, ApproximationGuard: the checks every operation passes before it changes
 *   anything (no crossing or fold; input and result stay within the tolerance of each other).
 * - Components: closed fragments too small to collapse further.
 * - OnTwoWorkers (amRemeshScheduler): a pass on two threads, the same result whatever the count.
 * - HausdorffMeasure: the two-sided distance, and where to insert points.
 * - Volumes (amRemeshVolumes): each region's volume, given back where the remeshing lost it.
 * - The operations, each a check and an apply in one file: collapse (amRemeshCollapse), flip
 *   (amRemeshFlip), split and insertion (amRemeshSplit), relaxation and moves (amRemeshRelax),
 *   the small-angle cleanup (amRemeshCleanup); the driver (amRemeshDriver) runs them.
 *
 * The method follows Frey's YAMS (metric-driven collapses, flips and relaxation of a surface
 * within a Hausdorff envelope) and Mmg's split of a remesher into one check/apply pair per
 * operation (mmgs: colver_s.c, swapar_s.c, split_s.c, movpt_s.c; the driver mmgs1.c).
 */
#ifndef amRemesher_h
#define amRemesher_h

#include "amRemeshApproximationGuard.h"
#include "amRemeshBins.h"
#include "amRemeshComponents.h"
#include "amRemeshCrossingGuard.h"
#include "amRemeshHausdorffMeasure.h"
#include "amRemeshInput.h"
#include "amRemeshJunctionCurves.h"
#include "amRemeshSurface.h"
#include "amRemeshWorker.h"

#include <functional>
#include <map>
#include <string>

namespace amRemesh
{
/// The volume each label's side of a labelled surface encloses (mm^3; Labels[0] is the side a
/// triangle's normal leaves; the outside, label 0, gets minus the total).
ANATOMESHFILTERSSURFACE_EXPORT std::map<int, double> RegionVolumes(const amSurfaceMesh& mesh);

class ANATOMESHFILTERSSURFACE_EXPORT Remesher
{
public:
  Remesher();
  Remesher(const Remesher&) = delete;
  Remesher& operator=(const Remesher&) = delete;

  /// Starts from the input surface (its topology built; labels give the interfaces, none: one
  /// interface) with one metric tensor per vertex, and the tolerance eps (mm).
  void Setup(const amSurfaceMesh& mesh, std::vector<Mat3> metric, double eps);

  struct Result
  {
    double Hausdorff = 0;  // the measured distance to the input (mm)
    double UpperBound = 0; // with the measure's sampling gap (mm)
    long long Inserted = 0;
  };
  /// Collapses, flips and relaxation 'iterations' times, then the bound enforced by insertions
  /// and the small angles cleaned where that keeps the bound. 'progress' (may be empty) is told
  /// the fraction done.
  Result Run(int iterations, const std::function<void(double)>& progress);

  long long Collapses() const { return this->Workers[0].Collapses + this->Workers[1].Collapses; }
  long long Flips() const { return this->Workers[0].Flips + this->Workers[1].Flips; }
  long long Moves() const { return this->Workers[0].Moves + this->Workers[1].Moves; }

  /// Longest metric edge a collapse may make: LongEdge, more while small angles are cleaned (an
  /// edge too long is split again by the insertions; a needle or cap stays).
  double LongestEdge = LongEdge;
  /// Smallest angle a collapse may make: SmallAngle, less while degenerate triangles are removed.
  double NewAngleFloor = SmallAngle;
  Surface Mesh;
  amRemesh::Input In;
  JunctionCurves Curves;
  Bins Grid;
  CrossingGuard Crossing;
  ApproximationGuard Approximation;
  HausdorffMeasure Hausdorff;
  Components Parts;
  mutable std::array<Worker, 2> Workers;
  /// The calling thread's worker.
  Worker& W() const { return this->Workers[CurrentWorker()]; }

  // The operations: each checks first and changes nothing when it refuses.
  /// Edge collapse: a disappears onto b, which stays where it is (half-edge collapse) or, given
  /// 'to' (two surface vertices only), moves there: a point of the input between them.
  bool Collapse(int a, int b, const Vec3* to = nullptr);
  /// The collapse Collapse has checked, made: a's triangles given to b (its edge's removed), a's
  /// clusters to b, b moved to x with metric mx; zip: b takes a's interfaces and becomes a corner.
  void ApplyCollapse(int a, int b, const Vec3& x, const Mat3& mx, bool zip, bool moved);
  /// Collapse of an edge between two surface vertices into the point of the input nearest its
  /// middle; 'outside': refused because that point lies outside the calling worker's zone.
  bool CollapseToMiddle(int a, int b, bool& outside);
  /// The collapse of a short edge in one of its forms: 1 done, 0 refused, -1 left for the
  /// serial pass.
  int TryCollapse(int a, int b);
  /// Every edge shorter than ShortEdge tried, shortest first; returns the collapses done.
  int CollapsePass();
  /// Flips edge (a, b) where that makes the smallest angle of its two triangles larger; both
  /// triangles keep their ids and labels.
  bool Flip(int a, int b);
  int FlipPass(bool onlyTouched = false);
  /// Flip the edges opposite vertex v where that improves the angles.
  void FlipAround(int v);
  /// Split edge k of triangle t (and every triangle on that edge) at x.
  bool SplitEdge(int t, int k, Vec3 x);
  /// Insert x into triangle t (1 -> 3), or split the edge it falls beside; then flips around it.
  bool Insert(int t, Vec3 x);
  /// Longest-edge split of t towards the input; returns the splits done.
  int Refine(int t);
  /// Move surface vertex v to x (a point of the input) where every guard allows it.
  bool Move(int v, const Vec3& x, bool relax);
  /// One vertex of RelaxPass: 1 moved, 0 not, -1 left for the serial pass.
  int Relax(int v);
  int RelaxPass();
  /// Where the point x of the input is nearest a vertex of triangle t, move that vertex there.
  bool MoveVertexNearest(int t, const Vec3& x);
  /// Whether the regions alternate consistently around every edge at b once a collapse into b
  /// (then at 'at') removes the triangles 'gone' and gives the triangles 'changed' the vertices 'ids'.
  bool LabelsInOrderAround(int b, const Vec3& at, const std::vector<int>& gone, const std::vector<int>& changed,
    const std::vector<std::array<int, 3>>& ids) const;
  /// Removes triangles with an angle under 'below' where a flip or collapse allows it.
  int SmallAngleCleanup(double below);

  /// The bound enforced: measure, insert where it is exceeded, measure again (at most 30 rounds).
  double Enforce(double& upper, long long& inserted);

  /// The volumes of the input's regions (Setup), given back in Run before the bound is enforced,
  /// when KeepVolumes (a coarser triangulation of a convex part lies inside it: the chords of a
  /// thin rib take several per cent of its volume).
  std::map<int, double> InputVolumes;
  bool KeepVolumes = false;
  /// Each interface's volume offset rounded to a fiftieth of the tolerance (amRemeshKeepInput's
  /// runs that hold input vertices): those runs correct nearly the same volumes, and rounded, the
  /// rest of the surface moves alike in each of them, instead of every vertex of a large interface
  /// a little differently and the bound missed somewhere new each time.
  bool RoundVolumeOffsets = false;
  /// The volume of each region of the surface as it is.
  std::map<int, double> RegionVolumes() const;
  /// Moves interface vertices along their normals towards each region's target volume, within
  /// the guards; returns the number of vertices moved.
  int PreserveVolumes(const std::map<int, double>& target, int rounds);

  /// The state the operations change, for an undo: the input, the bins and the measure's cache
  /// are not copied (the input never changes; Restore rebuilds the bins, and the measure's cache
  /// checks every triangle slot against the one it saw).
  struct Snapshot
  {
    Surface Mesh;
    std::array<std::array<long long, 3>, 2> Counters;
  };
  Snapshot Save() const;
  void Restore(Snapshot&& snapshot);

  /// The dead vertices and triangle slots dropped, the live ones renumbered in their order (the
  /// bins filled again at the same size and split plane). After the collapse passes most slots
  /// are dead: every later pass, measure and undo copy would read them.
  void Compact();
  /// Triangle t removed (it dies; its slot stays).
  void Detach(int t);
  /// A new triangle (a, b, c) with the sheet and labels of 'like'; returns its id.
  int AddTriangle(int a, int b, int c, const Triangle& like);
  /// The zone of edge (a, b): its ends' zone, or 2 (the serial pass) when they differ.
  int EdgeZone(int a, int b) const
  {
    const int za = this->Grid.ZoneAt(this->Mesh.P[a]), zb = this->Grid.ZoneAt(this->Mesh.P[b]);
    return za == zb ? za : 2;
  }
  /// Whether the stars of a and b lie in zone z's bins.
  bool StarsInZone(int a, int b, int z) const;
};
}

#endif
