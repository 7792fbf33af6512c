/**
 * @file    amRemeshSurface.h
 * @brief   The surface that MetricRemeshing changes: vertices with their metric, labelled
 *          triangles, vertex stars and the input points each vertex stands for.
 *
 * Private to the remesher (Filters/Surface/Remeshing). A copy of this state is the remesher's
 * undo: everything an operation changes lives here, while the input, the bins and the measure's
 * cache live in their own classes and are never copied.
 */
#ifndef amRemeshSurface_h
#define amRemeshSurface_h

#include "AnatomeshFiltersSurfaceModule.h" // export macro
#include "amSurfaceMesh.h"                 // vertex kinds

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace amRemesh
{
using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;

/// Smallest angle (radians) an insertion or edge split may create: a refused one refines the
/// triangle instead (longest-edge split), which makes room for the next attempt.
constexpr double MinimumNewAngle = 2.0 * M_PI / 180.0;
/// Triangles with an angle under this are removed after the insertions where the checks allow.
constexpr double SmallAngle = 10.0 * M_PI / 180.0;
/// Triangles with an angle under this are degenerate: removed last, accepting new angles down to
/// MinimumNewAngle.
constexpr double DegenerateAngle = 1.0 * M_PI / 180.0;
/// Edges shorter than ShortEdge in the metric are collapsed where no edge longer than LongEdge
/// results (a larger ShortEdge gives fewer triangles but tetrahedra of lower quality on them).
constexpr double ShortEdge = 0.8;
constexpr double LongEdge = 4.0 / 3.0;

/// Smallest angle (radians) of triangle abc; 0 when an edge has no length.
inline double MinAngle(const Vec3& a, const Vec3& b, const Vec3& c)
{
  // The largest cosine, then one arc cosine (it is monotonic).
  const Vec3 p[3] = { a, b, c };
  double largest = -1.0;
  for (int k = 0; k < 3; ++k)
  {
    const Vec3 u = p[(k + 1) % 3] - p[k], v = p[(k + 2) % 3] - p[k];
    const double nu = u.norm(), nv = v.norm();
    if (nu == 0 || nv == 0)
      return 0;
    largest = std::max(largest, u.dot(v) / (nu * nv));
  }
  return std::acos(std::max(-1.0, std::min(1.0, largest)));
}

/// A triangle slot: vertices (oriented), interface (sheet) and the labels on its two sides.
struct Triangle
{
  int V[3];
  int Sheet;
  int Labels[2];
  bool Alive;
};

/// An input vertex a result vertex stands for, with the interface it must stay near (-1: every
/// interface around the vertex, for junction-curve points) and a triangle of the vertex's star
/// found within the tolerance of it (-1: none yet). While that triangle is still in the vertex's
/// star and untouched (every operation that changes a triangle's vertices or their positions
/// passes it as removed), the entry needs no search.
struct ClusterEntry
{
  int Point;
  int Sheet;
  int Hint;
};

class ANATOMESHFILTERSSURFACE_EXPORT Surface
{
public:
  std::vector<Vec3> P;             // vertex positions
  std::vector<Mat3> M;             // vertex metric tensors
  std::vector<unsigned char> Kind; // amSurfaceMesh::VertexKind
  std::vector<char> VAlive;        // 0: collapsed away
  /// Per vertex: 1 for an input vertex held where it is. No operation moves or removes it, or
  /// splits or flips an edge between two held vertices, so a triangle of three held vertices
  /// stays the input's own.
  std::vector<char> Held;
  std::vector<Triangle> T;                        // triangle slots (dead ones stay)
  std::vector<std::vector<int>> VT;               // per vertex: its live triangles
  std::vector<std::vector<ClusterEntry>> Cluster; // per vertex: the input points it stands for
  /// Per vertex: the input curve vertex a curve vertex sits on (-1 for surface vertices).
  std::vector<int> Anchor;
  /// Per vertex: the interfaces of the junction vertices closed into it (a strip's two curves
  /// zipped), beyond its anchor's (sorted).
  std::vector<std::vector<int>> Merged;
  /// Vertices whose neighbourhood changed since the last collapse pass began: only edges at one
  /// of them are tried again (a refused collapse whose star did not change would be refused
  /// again, unless it was refused for crossing a triangle elsewhere that has since moved: such
  /// an edge waits until something changes next to it).
  std::vector<char> Dirty;
  /// The same since the last flip pass began: a flip pass after another tries only the edges at
  /// one of them (an edge whose two triangles did not change keeps its angles, and the angles
  /// refuse most flips).
  std::vector<char> FlipDirty;

  /// Metric length of the edge from x (metric mx) to vertex b: the mean of the two ends' lengths.
  double Length(const Vec3& x, const Mat3& mx, int b) const
  {
    const Vec3 e = this->P[b] - x;
    return 0.5 * (std::sqrt(std::max(0.0, e.dot(mx * e))) + std::sqrt(std::max(0.0, e.dot(this->M[b] * e))));
  }
  double Length(int a, int b) const { return this->Length(this->P[a], this->M[a], b); }

  /// The vertices sharing a live triangle with v, sorted.
  void Neighbours(int v, std::vector<int>& out) const;
  /// The live triangles on edge (a, b).
  void EdgeTriangles(int a, int b, std::vector<int>& out) const;
  /// Whether (a, b) is an edge of a junction curve: other than two triangles, or two of
  /// different interfaces.
  bool IsFeature(int a, int b) const;
  bool IsFeature(const std::vector<int>& edge) const
  {
    return edge.size() != 2 || this->T[edge[0]].Sheet != this->T[edge[1]].Sheet;
  }
  /// Twice the area vector of triangle t.
  Vec3 Normal(int t) const
  {
    const int* v = this->T[t].V;
    return (this->P[v[1]] - this->P[v[0]]).cross(this->P[v[2]] - this->P[v[0]]);
  }
  /// Whether v's connected component has at most n vertices (searches no further than that).
  bool ComponentAtMost(int v, size_t n) const;
  /// A new vertex (no triangles yet); returns its id.
  int AddVertex(const Vec3& x, const Mat3& m, unsigned char kind, int anchor);
  /// Both dirty flags sized for every vertex (new vertices count as touched).
  void SizeDirty();
  /// v's neighbourhood changed: its edges are tried again by the next collapse and flip passes.
  void Touch(int v)
  {
    if (static_cast<size_t>(v) >= std::min(this->Dirty.size(), this->FlipDirty.size()))
      this->SizeDirty();
    this->Dirty[v] = 1;
    this->FlipDirty[v] = 1;
  }
  /// Live triangles with an angle under SmallAngle, the smallest angle (radians) and the
  /// shortest live edge.
  void AngleSummary(long long& small, double& smallest, double& shortest) const;
};
}

#endif
