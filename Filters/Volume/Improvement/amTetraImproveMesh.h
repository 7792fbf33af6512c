/**
 * @file   amTetraImproveMesh.h
 * @brief   The mesh that amTetraMeshOptimizer improves, and its local operations (not wrapped).
 *
 * One operation per file: amTetraImproveFlips.cxx (edge removal, 2-3 flip),
 * amTetraImproveMoves.cxx (smoothing, local search), amTetraImproveInsert.cxx (free edge split),
 * amTetraImproveFaceSplit.cxx (free face split). Each is accepted only when it makes the worst
 * element it touches better; none crosses a fixed face or moves a fixed vertex.
 *
 * The sliver phase (amTetraImproveSlivers.cxx), where the surface may move within a budget:
 * surface vertex slides (Climb with a radius, StarDeviation), amTetraImproveRelabel.cxx (a
 * surface-bound sliver handed to the region across the surface), amTetraImproveSurfaceSplit.cxx
 * (a surface edge split at its midpoint), amTetraImproveCollapse.cxx (a short surface edge
 * collapsed, along its interface or junction curve), amTetraImproveDeviation.cxx (what the
 * surface moved).
 *
 * Before the improvement, where the options give target volumes: amTetraImproveVolumes.cxx (the
 * surface moved along its normals until each region has its volume).
 */
#ifndef amTetraImproveMesh_h
#define amTetraImproveMesh_h

#include "amTetraGeometry.h"
#include "amTetraImproveOptions.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <functional>
#include <limits>
#include <map>
#include <unordered_map>
#include <unordered_set>
#include <vector>

namespace amTetraImprove
{
using Vec = amTetraGeometry::Vec;
using Tet = std::array<int, 4>;
using Tri = std::array<int, 3>;

struct TriHash
{
  size_t operator()(const Tri& k) const
  {
    uint64_t h = 1469598103934665603ull;
    for (int v : k)
      h ^= static_cast<uint64_t>(static_cast<uint32_t>(v)) + 0x9e3779b97f4a7c15ull + (h << 6) + (h >> 2);
    return static_cast<size_t>(h);
  }
};
inline Tri Sorted(int a, int b, int c)
{
  Tri t{ { a, b, c } };
  std::sort(t.begin(), t.end());
  return t;
}
inline uint64_t EdgeKey(int a, int b)
{
  if (a > b)
    std::swap(a, b);
  return (static_cast<uint64_t>(static_cast<uint32_t>(a)) << 32) | static_cast<uint32_t>(b);
}

/// The mesh being improved: tetrahedra are appended and killed, never moved, so ids stay valid.
class Mesh
{
public:
  std::vector<double>& P;
  std::vector<Tet> T;
  std::vector<int> R;
  std::vector<char> Alive;
  std::vector<double> Objectives; // per tetrahedron, Objective in (0, 1] (1/Q or the
                                  // dihedral term), kept current as vertices move
  std::vector<char> Tried;        // per tetrahedron: the flips failed and nothing moved since
  std::vector<char> Dirty;        // per vertex: its star changed since it was last smoothed
  std::vector<std::vector<int>> Inc;
  std::unordered_set<Tri, TriHash> FixedFaces;
  std::unordered_set<uint64_t> FixedEdges;
  std::vector<char> FixedVertex;
  std::vector<double> Origin; // where each vertex was when the surface could start to move (NaN: made inside since)

  explicit Mesh(std::vector<double>& p)
    : P(p)
  {
  }
  Mesh(const Mesh&) = default;
  /// Everything but the points (P is a reference: the caller restores those).
  void Assign(const Mesh& o)
  {
    this->T = o.T;
    this->R = o.R;
    this->Alive = o.Alive;
    this->Objectives = o.Objectives;
    this->Tried = o.Tried;
    this->Dirty = o.Dirty;
    this->Inc = o.Inc;
    this->FixedFaces = o.FixedFaces;
    this->FixedEdges = o.FixedEdges;
    this->FixedVertex = o.FixedVertex;
    this->Origin = o.Origin;
  }
  const double* X(int v) const { return &this->P[3 * static_cast<size_t>(v)]; }
  double Quality(int a, int b, int c, int d) const { return Objective(this->X(a), this->X(b), this->X(c), this->X(d)); }
  int AddPoint(const double* x)
  {
    this->P.insert(this->P.end(), x, x + 3);
    this->Inc.emplace_back();
    this->FixedVertex.push_back(0);
    this->Dirty.push_back(1);
    if (!this->Origin.empty())
      this->Origin.insert(this->Origin.end(), 3, std::numeric_limits<double>::quiet_NaN());
    return static_cast<int>(this->Inc.size()) - 1;
  }
  int Add(const Tet& t, int region) { return this->Add(t, region, this->Quality(t[0], t[1], t[2], t[3])); }
  /// Add with the tetrahedron's objective q computed already.
  int Add(const Tet& t, int region, double q)
  {
    const int id = static_cast<int>(this->T.size());
    this->T.push_back(t);
    this->R.push_back(region);
    this->Alive.push_back(1);
    this->Objectives.push_back(q);
    this->Tried.push_back(0);
    for (int v : t)
    {
      this->Inc[v].push_back(id);
      this->Dirty[v] = 1;
    }
    return id;
  }
  /// FixedEdges and FixedVertex from FixedFaces: every edge and vertex of a fixed face is fixed
  /// (the edges afresh; vertices once fixed stay fixed).
  void FixEdgesOfFixedFaces()
  {
    this->FixedEdges.clear();
    for (const Tri& f : this->FixedFaces)
      for (int k = 0; k < 3; ++k)
      {
        this->FixedVertex[f[k]] = 1;
        this->FixedEdges.insert(EdgeKey(f[k], f[(k + 1) % 3]));
      }
  }
  void Kill(int id)
  {
    this->Alive[id] = 0;
    for (int v : this->T[id])
    {
      auto& inc = this->Inc[v];
      inc.erase(std::find(inc.begin(), inc.end(), id));
    }
  }
  /// Brings a killed tetrahedron back in its slot (a change undone).
  void Revive(int id)
  {
    this->Alive[id] = 1;
    for (int v : this->T[id])
      this->Inc[v].push_back(id);
  }
  bool Has(int t, int v) const
  {
    const Tet& x = this->T[t];
    return x[0] == v || x[1] == v || x[2] == v || x[3] == v;
  }
  /// The tetrahedron on the other side of face i of t (the face opposite its vertex i), -1 for none.
  int Across(int t, int i) const
  {
    const Tet& x = this->T[t];
    const int a = x[(i + 1) % 4], b = x[(i + 2) % 4], c = x[(i + 3) % 4];
    for (int s : this->Inc[a])
      if (s != t && this->Has(s, b) && this->Has(s, c))
        return s;
    return -1;
  }
  bool Connected(int a, int b) const
  {
    for (int t : this->Inc[a])
      if (this->Has(t, b))
        return true;
    return false;
  }

  /// The tetrahedra around edge (u, v), ordered, with their ring w such that every tetrahedron
  /// (u, v, w[i], w[i+1]) is positively oriented. False when the ring is not closed, or has more
  /// than 'most' tetrahedra.
  bool Ring(int u, int v, std::vector<int>& tets, std::vector<int>& ring,
    size_t most = std::numeric_limits<size_t>::max()) const;
};

/// Edge removal: replaces the tetrahedra around (u, v) by the best triangulation of their ring.
bool RemoveEdge(Mesh& m, int u, int v, int maxRing, std::vector<int>& tets, std::vector<int>& ring);
/// RemoveEdge's choice without the change: the tetrahedra to remove ('tets') and those to make.
bool PlanEdgeRemoval(
  const Mesh& m, int u, int v, int maxRing, std::vector<int>& tets, std::vector<int>& ring, std::vector<Tet>& made);
/// 2-3 flip of the face of tetrahedron t opposite its vertex i.
bool Flip23(Mesh& m, int t, int i);
/// Flip23's choice without the change: the tetrahedron across the face and the three to make.
bool PlanFlip23(const Mesh& m, int t, int i, int& other, std::vector<Tet>& made);
/// Kills 'killed' and adds 'made' (of 'region'), in that order: a planned change made.
void Replace(Mesh& m, const std::vector<int>& killed, const std::vector<Tet>& made, int region);
/// The topology pass's work on tetrahedron t: the first of its edge removals (rings of up to
/// maxRing), 2-3 flips and, under 'split', edge and face splits that mends it, counted in the
/// report; else t is marked tried. True when the mesh changed.
bool Mend(
  Mesh& m, int t, double split, int maxRing, Report& report, std::vector<int>& ringTets, std::vector<int>& ring);
/// The topology pass over the tetrahedra 0 .. m.T.size()-1 as they are when it starts: for each
/// alive one not yet tried and worse than 'bad', Mend. Exactly that serial loop: blocks of tetrahedra have their flips
/// planned on the threads at once, then made in order, and one whose neighbourhood a change in its block touched first
/// is done again at its turn. Adds what it did to the report; returns the changes.
long TopologyPass(Mesh& m, double bad, double split, int maxRing, Report& report);
/// The star of v as it is: its worst objective and the sum of the inverse objectives.
void CurrentStar(const Mesh& m, int v, double& worst, double& sum);
/// The star of v with v moved to x: its worst objective and the sum of the inverse objectives
/// (inf when a tetrahedron inverts); it stops early, with a worst under 'floor' or a sum at
/// least 'ceiling', once the star is surely worse than either.
/// With 'each', the objective of every element evaluated, in the order of m.Inc[v].
void StarQuality(const Mesh& m, int v, const double* x, double& worst, double& sumQ,
  double floor = -std::numeric_limits<double>::infinity(), double ceiling = std::numeric_limits<double>::infinity(),
  double* each = nullptr);
/// Moves v to x and updates its star's objectives ('q': those of m.Inc[v] there, computed already)
/// and Tried flags; writes nothing outside v and its star's elements.
void PlaceVertex(Mesh& m, int v, const double* x, const double* q = nullptr);
/// Sets the Dirty flag of every vertex of v's star (v's included).
void MarkStarDirty(Mesh& m, int v);
/// PlaceVertex, then MarkStarDirty.
void MoveVertex(Mesh& m, int v, const double* x, const double* q = nullptr);
/// Smoothing of one free vertex: the best of a few candidate positions that keeps the star's
/// worst element at least as good and lowers its mean Q.
bool Smooth(Mesh& m, int v);
/// Smooth's choice without the move: the position (in 'to') and whether there is one. It reads
/// only v's star (the positions of its vertices and the objectives of its elements). With 'q'
/// (room for m.Inc[v].size() values), the star's objectives at that position.
bool SmoothTarget(const Mesh& m, int v, double* to, double* q = nullptr);
/// The free vertices among 0 .. n-1 that a smoothing pass may move (those whose Dirty flag is set,
/// and their free neighbours) in classes no two neighbours share: a greedy colouring in the
/// order of the vertices, each class in that order.
std::vector<std::vector<int>> SmoothingColours(const Mesh& m, size_t n);
/// Smooth over the classes of SmoothingColours in turn, each class's vertices in order: each one
/// whose Dirty flag is set when its turn comes (the flag cleared). A class's vertices are smoothed
/// on the threads at once: the result does not depend on their number. Returns the moves.
long SmoothAll(Mesh& m, size_t n);
/// Local search: moves v along the numerical gradient of its star's worst quality; with a finite
/// 'radius', only where the fixed faces around v stay within that distance of where they were
/// (StarDeviation): a surface vertex slides along a flat surface freely, off it only so far.
/// It stops once the star's worst objective reaches 'goal' (a surface vertex moves no farther
/// than the slivers need).
bool Climb(Mesh& m, int v, double radius = std::numeric_limits<double>::infinity(),
  double goal = std::numeric_limits<double>::infinity());
/// Splits the free edge (u, v) at its midpoint, then moves the new vertex where its star is best.
/// Undone unless every element around the new vertex reaches 'goal'.
bool SplitEdge(Mesh& m, int u, int v, double goal, std::vector<int>& tets, std::vector<int>& ring);
/// The end of an insertion (SplitEdge, SplitFace): moves the new vertex w to the best place for
/// its star, and keeps it when every element around it is better than 'old' and reaches 'goal';
/// else the elements 'before' (of 'region') replace its star and w is left unused.
bool KeepInsertion(Mesh& m, int w, const std::vector<Tet>& before, int region, double old, double goal);
/// Splits the free face f (2-6: both tetrahedra on it in three), then moves the new vertex where
/// its star is best. Undone unless every element around it reaches 'goal'.
bool SplitFace(Mesh& m, const Tri& f, double goal);
/// Gives tetrahedron t the region across one of its fixed faces (removes it at the mesh's
/// boundary) when that moves the surface by at most maxDeviation; the faces it shared with
/// that region leave FixedFaces and those with its own region join (FixedEdges is not updated).
/// Returns the surface's displacement, or -1 when no neighbour fits.
double Relabel(Mesh& m, int t, double maxDeviation, std::unordered_map<int, long>& regionCount);
/// Whether tetrahedron t fails the sliver bar of the options (Q above SliverQuality or a dihedral
/// angle below SliverDihedral).
bool IsSliver(const Mesh& m, int t, const Options& options);
/// The objective above which no element is a sliver by the options' bar.
double SliverClear(const Options& options);
/// The live tetrahedra that fail the sliver bar of the options.
long CountSlivers(const Mesh& m, const Options& options);
/// The faces where the mesh folds over itself (amTetraImproveFolds): more than two live
/// tetrahedra on one face, or two with their fourth corners on the same side of it.
long FoldedFaces(const Mesh& m);
/// The sliver phase of amTetraMeshOptimizer (Options::MaximumSurfaceDeviation > 0): rounds of
/// surface vertex slides, region changes and surface edge splits around the slivers left, each
/// followed by improve(round) (the flips and moves) and fixEdges() (FixedEdges from FixedFaces);
/// the surface's deviation is measured and kept within the budget (report.SurfaceDeviation).
void FreeSlivers(Mesh& m, const Options& options, Report& report, const std::function<void(int)>& improve,
  const std::function<void()>& fixEdges);
/// Collapses the surface edge (v, u): v moves onto u and leaves the mesh with the elements on the
/// edge; the fixed faces around u are then those between two regions. Only where every interface
/// around v is on the edge (v inside an interface, or on a junction curve along it), the link
/// condition holds (the mesh stays a manifold), no element inverts, the worst element around
/// the two gets better, every region keeps an element (regionCount, updated), and the surface
/// moves by at most maxDeviation (sampled, two-sided, over the fixed faces around them). Returns
/// that displacement, or -1 (the mesh as it was).
double CollapseSurfaceEdge(Mesh& m, int v, int u, double maxDeviation, std::unordered_map<int, long>& regionCount);
/// Gives the regions with a target their volume (label -> mm^3): rounds of moves of the surface
/// vertices that lie inside one interface, along their normals by one offset per interface
/// (amVolumeOffsets, at most 'limit' mm), each kept where no element of its star inverts or falls
/// below the objective 'floor' (or its star's worst, if lower) and no part of the mesh's boundary
/// is brought into another; the free vertices around are smoothed between rounds. Junction
/// curves stay. Returns the moves; 'displacement' is the farthest a vertex went.
long PreserveVolumes(
  Mesh& m, const std::map<int, double>& target, double limit, double floor, int rounds, double& displacement);
/// Splits the surface edge (u, v) at its midpoint, every element and fixed face on it in two
/// (the surface keeps its shape); returns the new vertex, or -1.
int SplitSurfaceEdge(Mesh& m, int u, int v);
/// The two-sided Hausdorff distance between the surface as it was ('before', on m.Origin) and
/// the fixed faces now, over the triangles that changed (sampled, corners and edges included).
double SurfaceDeviation(const Mesh& m, const std::vector<Tri>& before);
/// The largest distance from a point of triangle f to the triangles 'to' (sampled on a grid of
/// 45 points, corners and edges included); inf when 'to' is empty.
double FarthestPoint(const Mesh& m, const Tri& f, const std::vector<Tri>& to);
/// v's own share of the surface's displacement: the two-sided Hausdorff distance (sampled)
/// between the fixed faces around v with v at y and with v at its origin (m.Origin), the other
/// vertices where they are now; inf when v has no origin (made inside the mesh).
double StarDeviation(const Mesh& m, int v, const double* y);

/// Points of triangle (a, b, c) on a barycentric grid of 'steps' intervals per edge, corners
/// and edges included: f(x) for each.
template<typename F>
void SampleTriangle(const double* a, const double* b, const double* c, int steps, F&& f)
{
  for (int i = 0; i <= steps; ++i)
    for (int j = 0; i + j <= steps; ++j)
    {
      const double u = static_cast<double>(i) / steps, v = static_cast<double>(j) / steps, w = 1 - u - v;
      const double x[3] = { w * a[0] + u * b[0] + v * c[0], w * a[1] + u * b[1] + v * c[1],
        w * a[2] + u * b[2] + v * c[2] };
      f(x);
    }
}
}

#endif
