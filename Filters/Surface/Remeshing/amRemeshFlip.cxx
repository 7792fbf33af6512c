#include "amRemesher.h"

#include "amRemeshScheduler.h"
#include "amThreading.h"
#include "vtkSMPThreadLocal.h"
#include <utility>

namespace amRemesh
{
bool Remesher::Flip(int a, int b)
{
  if (this->Mesh.Held[a] && this->Mesh.Held[b])
    return false;
  std::vector<int> edge;
  this->Mesh.EdgeTriangles(a, b, edge);
  if (this->Mesh.IsFeature(edge))
    return false;
  // t1 = (a, b, c), t2 = (b, a, d) in their own orientation.
  int t1 = edge[0], t2 = edge[1];
  auto rotateTo = [&](int t, int first, int second) {
    const int* v = this->Mesh.T[t].V;
    for (int k = 0; k < 3; ++k)
      if (v[k] == first && v[(k + 1) % 3] == second)
        return v[(k + 2) % 3];
    return -1;
  };
  int c = rotateTo(t1, a, b), d = rotateTo(t2, b, a);
  if (c < 0 || d < 0)
  {
    std::swap(t1, t2);
    c = rotateTo(t1, a, b);
    d = rotateTo(t2, b, a);
    if (c < 0 || d < 0)
      return false; // inconsistent orientation: leave it
  }
  if (c == d)
    return false;
  // The angles first: they refuse most edges, and cost less than the link test.
  const Vec3 &pa = this->Mesh.P[a], &pb = this->Mesh.P[b], &pc = this->Mesh.P[c], &pd = this->Mesh.P[d];
  const double before = std::min(MinAngle(pa, pb, pc), MinAngle(pb, pa, pd));
  const double after = std::min(MinAngle(pa, pd, pc), MinAngle(pd, pb, pc));
  if (after <= before + 1e-3)
    return false;
  std::vector<int> nc;
  this->Mesh.Neighbours(c, nc);
  if (std::binary_search(nc.begin(), nc.end(), d))
    return false;
  const Vec3 n0 = (this->Mesh.Normal(t1).normalized() + this->Mesh.Normal(t2).normalized()).normalized();
  const Vec3 n1 = (pd - pa).cross(pc - pa), n2 = (pb - pd).cross(pc - pd);
  if (n1.norm() == 0 || n2.norm() == 0 || n1.normalized().dot(n0) < 0.9 || n2.normalized().dot(n0) < 0.9)
    return false;
  const int sheet = this->Mesh.T[t1].Sheet;
  if (!this->In.TriangleNear(sheet, pa, pd, pc) || !this->In.TriangleNear(sheet, pd, pb, pc))
    return false;
  // The two triangles keep their ids (a worker must not add triangles): t1 becomes (a, d, c)
  // and t2 (d, b, c), with t1's labels.
  if (!this->Approximation.ClustersStayNear({ t1, t2 }, { { a, d, c }, { d, b, c } },
        { { pa, pd, pc }, { pd, pb, pc } }, { sheet, sheet }, { t1, t2 }, { a, b, c, d }, this->W()))
    return false;
  // The flip sweeps the tetrahedron (a, b, c, d): nothing may lie inside it.
  const std::vector<std::array<Vec3, 4>> swept = { { pa, pb, pc, pd } };
  if (this->Crossing.Crosses(
        { { a, d, c }, { d, b, c } }, { { pa, pd, pc }, { pd, pb, pc } }, { t1, t2 }, this->W(), &swept))
    return false;
  this->Approximation.KeepHints(this->W());
  const std::vector<int> pair = { t1, t2 };
  auto drop = [this](int v, int t) {
    auto& l = this->Mesh.VT[v];
    l.erase(std::remove(l.begin(), l.end(), t), l.end());
  };
  drop(a, t2);
  drop(b, t1);
  this->Mesh.VT[c].push_back(t2);
  this->Mesh.VT[d].push_back(t1);
  const int v1[3] = { a, d, c }, v2[3] = { d, b, c };
  std::copy(v1, v1 + 3, this->Mesh.T[t1].V);
  std::copy(v2, v2 + 3, this->Mesh.T[t2].V);
  std::copy(this->Mesh.T[t1].Labels, this->Mesh.T[t1].Labels + 2, this->Mesh.T[t2].Labels);
  this->Grid.Update(pair);
  ++this->W().Flips;
  for (int w : { a, b, c, d })
    this->Mesh.Touch(w);
  return true;
}

/// Every edge flipped where that makes the smallest angle of its two triangles larger; on two
/// workers (see OnTwoWorkers: a flip changes the two triangles of the edge, in the stars of its
/// ends). 'onlyTouched': only the edges at a vertex touched since the last flip pass began.
int Remesher::FlipPass(bool onlyTouched)
{
  this->Mesh.SizeDirty();
  this->Grid.RebuildIfStale();
  // Each edge once, in the Morton order of its midpoint (see CollapsePass): an edge of two
  // triangles of one orientation is the half-edge a -> b with a < b of one of them; a junction
  // edge may come more than once, and then its copies are neighbours in that order. (An edge
  // whose two triangles disagree on their orientation may be missed: Flip leaves those.)
  // (Gathered on the threads, sorted whole.)
  using Edge = std::pair<unsigned long long, std::pair<int, int>>;
  vtkSMPThreadLocal<std::vector<Edge>> found;
  vtkSMPTools::For(0, static_cast<vtkIdType>(this->Mesh.T.size()), [&](vtkIdType t0, vtkIdType t1) {
    auto& local = found.Local();
    for (vtkIdType t = t0; t < t1; ++t)
      if (this->Mesh.T[t].Alive)
        for (int k = 0; k < 3; ++k)
        {
          const int a = this->Mesh.T[t].V[k], b = this->Mesh.T[t].V[(k + 1) % 3];
          if ((a < b || this->Mesh.Kind[a] != amSurfaceMesh::Surface || this->Mesh.Kind[b] != amSurfaceMesh::Surface) &&
            (!onlyTouched || this->Mesh.FlipDirty[a] || this->Mesh.FlipDirty[b]))
            local.push_back({ Bins::MortonCode(0.5 * (this->Mesh.P[a] + this->Mesh.P[b]), this->Grid.Size),
              { std::min(a, b), std::max(a, b) } });
        }
  });
  std::vector<Edge> order;
  for (const auto& local : found)
    order.insert(order.end(), local.begin(), local.end());
  std::fill(this->Mesh.FlipDirty.begin(), this->Mesh.FlipDirty.end(), 0);
  amThreading::Sort(order.begin(), order.end());
  order.erase(std::unique(order.begin(), order.end()), order.end());
  std::vector<std::pair<int, int>> edges(order.size());
  for (size_t i = 0; i < order.size(); ++i)
    edges[i] = order[i].second;
  return OnTwoWorkers(
    this->Mesh, edges.size(), [&](size_t i) { return this->EdgeZone(edges[i].first, edges[i].second); },
    [&](size_t i) {
      const int a = edges[i].first, b = edges[i].second;
      if (CurrentZone() >= 0 && !this->StarsInZone(a, b, CurrentZone()))
        return this->Mesh.VAlive[a] && this->Mesh.VAlive[b] ? -1 : 0;
      return this->Flip(a, b) ? 1 : 0;
    });
}

/// Flip the edges opposite vertex v where that improves the angles.
void Remesher::FlipAround(int v)
{
  std::vector<std::pair<int, int>> link;
  for (int t : this->Mesh.VT[v])
    for (int k = 0; k < 3; ++k)
      if (this->Mesh.T[t].V[k] == v)
        link.emplace_back(this->Mesh.T[t].V[(k + 1) % 3], this->Mesh.T[t].V[(k + 2) % 3]);
  for (const auto& e : link)
    this->Flip(e.first, e.second);
}
}
