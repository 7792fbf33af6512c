#include "amRemesher.h"

#include "amRemeshScheduler.h"
#include "amThreading.h"
#include <limits>

namespace amRemesh
{
/// Every surface vertex moved halfway to the centroid of its neighbours, along the surface,
/// then onto the input (where Move allows it); on two workers (see OnTwoWorkers: a move
/// changes the triangles of v's star and the clusters of v and its neighbours).
int Remesher::RelaxPass()
{
  this->Grid.RebuildIfStale();
  // In the Morton order of the vertices (see CollapsePass).
  std::vector<std::pair<unsigned long long, int>> order;
  for (size_t v = 0; v < this->Mesh.P.size(); ++v)
    if (this->Mesh.VAlive[v] && this->Mesh.Kind[v] == amSurfaceMesh::Surface && !this->Mesh.VT[v].empty())
      order.push_back({ Bins::MortonCode(this->Mesh.P[v], this->Grid.Size), static_cast<int>(v) });
  amThreading::Sort(order.begin(), order.end());
  return OnTwoWorkers(
    this->Mesh, order.size(), [&](size_t i) { return this->Grid.ZoneAt(this->Mesh.P[order[i].second]); },
    [&](size_t i) { return this->Relax(order[i].second); });
}

/// One vertex of RelaxPass: 1 moved, 0 not, -1 left for the serial pass (a worker's vertex whose
/// star or new place is not all on its side).
int Remesher::Relax(int v)
{
  if (!this->Mesh.VAlive[v] || this->Mesh.Kind[v] != amSurfaceMesh::Surface || this->Mesh.VT[v].empty())
    return 0;
  if (CurrentZone() >= 0 && !this->StarsInZone(v, v, CurrentZone()))
    return -1;
  thread_local std::vector<int> ring;
  this->Mesh.Neighbours(v, ring);
  Vec3 centroid = Vec3::Zero(), n = Vec3::Zero();
  for (int q : ring)
    centroid += this->Mesh.P[q];
  centroid /= static_cast<double>(ring.size());
  for (int t : this->Mesh.VT[v])
    n += this->Mesh.Normal(t);
  if (n.norm() == 0)
    return 0;
  n.normalize();
  Vec3 x = this->Mesh.P[v] + 0.5 * ((centroid - this->Mesh.P[v]) - (centroid - this->Mesh.P[v]).dot(n) * n);
  const int sheet = this->Mesh.T[this->Mesh.VT[v][0]].Sheet;
  double cl[3];
  vtkIdType tri;
  if (this->In.Ref[sheet].ClosestPointFacing(x.data(), n.data(), cl, tri) == std::numeric_limits<double>::infinity())
    return 0;
  x = Vec3(cl);
  if (CurrentZone() >= 0 && this->Grid.ZoneAt(x) != CurrentZone())
    return -1;
  return this->Move(v, x, true) ? 1 : 0;
}

/// Move surface vertex v to x (a point of the input) unless a triangle around it would turn
/// over, leave its interface by more than Eps, carry an input point too far, cross another, or
/// get a smaller angle than before ('relax') or than min(before, SmallAngle) (otherwise).
bool Remesher::Move(int v, const Vec3& x, bool relax)
{
  // Not a move where v already is (it would count as done and change nothing).
  if (this->Mesh.Kind[v] != amSurfaceMesh::Surface || this->Mesh.Held[v] || this->Mesh.VT[v].empty() ||
    x == this->Mesh.P[v])
    return false;
  double before = M_PI, after = M_PI;
  std::vector<std::array<int, 3>> ids;
  std::vector<std::array<Vec3, 3>> pos;
  std::vector<int> sheets;
  std::vector<std::array<Vec3, 4>> swept;
  for (int t : this->Mesh.VT[v])
  {
    std::array<Vec3, 3> p, q;
    int fixed = 0;
    std::array<Vec3, 4> sweep;
    for (int k = 0; k < 3; ++k)
    {
      p[k] = this->Mesh.P[this->Mesh.T[t].V[k]];
      q[k] = this->Mesh.T[t].V[k] == v ? x : p[k];
      if (this->Mesh.T[t].V[k] != v)
        sweep[fixed++] = p[k];
    }
    sweep[2] = this->Mesh.P[v];
    sweep[3] = x;
    swept.push_back(sweep);
    before = std::min(before, MinAngle(p[0], p[1], p[2]));
    after = std::min(after, MinAngle(q[0], q[1], q[2]));
    const Vec3 n0 = (p[1] - p[0]).cross(p[2] - p[0]), n1 = (q[1] - q[0]).cross(q[2] - q[0]);
    if (n1.norm() == 0 || n0.normalized().dot(n1.normalized()) < 0.7)
      return false;
    ids.push_back({ this->Mesh.T[t].V[0], this->Mesh.T[t].V[1], this->Mesh.T[t].V[2] });
    pos.push_back(q);
    sheets.push_back(this->Mesh.T[t].Sheet);
  }
  if (after < (relax ? before : std::min(before, SmallAngle)))
    return false;
  static const std::vector<int> none;
  if (!this->Approximation.StarNear(ids, pos, sheets, v, none))
    return false;
  std::vector<int> ring;
  this->Mesh.Neighbours(v, ring);
  ring.push_back(v);
  if (!this->Approximation.ClustersStayNear(this->Mesh.VT[v], ids, pos, sheets, this->Mesh.VT[v], ring, this->W()) ||
    this->Crossing.Crosses(ids, pos, this->Mesh.VT[v], this->W(), &swept))
    return false;
  this->Approximation.KeepHints(this->W());
  this->Mesh.P[v] = x;
  this->Grid.Update(this->Mesh.VT[v]);
  ++this->W().Moves;
  for (int w : ring)
    this->Mesh.Touch(w);
  return true;
}

/// Where the point x of the input is nearest to a surface vertex of triangle t (it lies above
/// a vertex where the surface bends, not above a triangle to insert it into): move that vertex
/// to x. Returns whether it was done.
bool Remesher::MoveVertexNearest(int t, const Vec3& x)
{
  if (!this->Mesh.T[t].Alive)
    return false;
  const int* w = this->Mesh.T[t].V;
  double cl[3];
  amTriangleLocator::ClosestPointOnTriangle(
    x.data(), this->Mesh.P[w[0]].data(), this->Mesh.P[w[1]].data(), this->Mesh.P[w[2]].data(), cl);
  const double longest = std::max({ (this->Mesh.P[w[1]] - this->Mesh.P[w[0]]).norm(),
    (this->Mesh.P[w[2]] - this->Mesh.P[w[1]]).norm(), (this->Mesh.P[w[0]] - this->Mesh.P[w[2]]).norm() });
  for (int k = 0; k < 3; ++k)
    if ((Vec3(cl) - this->Mesh.P[w[k]]).norm() < 0.05 * longest)
      return this->Move(w[k], x, false);
  return false;
}
}
