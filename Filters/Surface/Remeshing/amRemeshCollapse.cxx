#include "amRemesher.h"

#include "amRemeshScheduler.h"
#include "amThreading.h"
#include "vtkSMPThreadLocal.h"
#include <limits>
#include <tuple>

namespace amRemesh
{
/// Edge collapse: a disappears onto b, which stays where it is (half-edge collapse) or, given
/// 'to' (two surface vertices only), moves there: a point of the input between them.
bool Remesher::Collapse(int a, int b, const Vec3* to)
{
  if (to && (this->Mesh.Kind[a] != amSurfaceMesh::Surface || this->Mesh.Kind[b] != amSurfaceMesh::Surface))
    return false;
  if (!this->Mesh.VAlive[a] || !this->Mesh.VAlive[b] || this->Mesh.Held[a] || (to && this->Mesh.Held[b]))
    return false;
  // Closing a strip: a junction vertex into another across the strip (or along a short curve
  // between two corners), b then taking a's interfaces too and becoming a corner.
  const bool zipping = !to && this->Approximation.CloseStrips && this->Mesh.Kind[a] != amSurfaceMesh::Surface &&
    this->Mesh.Kind[b] != amSurfaceMesh::Surface;
  if (this->Mesh.Kind[a] == amSurfaceMesh::Corner && !zipping)
    return false;
  Worker& worker = this->W();
  auto &edge = worker.C.Edge, &na = worker.C.Na, &nb = worker.C.Nb, &common = worker.C.Common, &apex = worker.C.Apex,
       &changed = worker.C.Changed, &removed = worker.C.Removed, &sheets = worker.C.Sheets,
       &affected = worker.C.Affected;
  auto& ids = worker.C.Ids;
  auto& pos = worker.C.Pos;
  auto& swept = worker.C.Swept;
  this->Mesh.EdgeTriangles(a, b, edge);
  if (edge.empty())
    return false;
  const bool feature = this->Mesh.IsFeature(edge);
  const bool zip = zipping && !(this->Mesh.Kind[a] == amSurfaceMesh::Curve && feature); // else along a curve
  if ((this->Mesh.Kind[a] == amSurfaceMesh::Curve) != feature && !zip)
    return false;
  // Link condition: the common neighbours are exactly the apexes of the edge's triangles.
  this->Mesh.Neighbours(a, na);
  this->Mesh.Neighbours(b, nb);
  common.clear();
  apex.clear();
  std::set_intersection(na.begin(), na.end(), nb.begin(), nb.end(), std::back_inserter(common));
  for (int t : edge)
    for (int k = 0; k < 3; ++k)
      if (this->Mesh.T[t].V[k] != a && this->Mesh.T[t].V[k] != b)
        apex.push_back(this->Mesh.T[t].V[k]);
  std::sort(apex.begin(), apex.end());
  apex.erase(std::unique(apex.begin(), apex.end()), apex.end());
  if (apex != common || apex.size() != edge.size())
    return false;
  // A closed fragment of five vertices or fewer is not collapsed further: as a tetrahedron it
  // is flat enough to turn inside out when its vertices are moved onto the input (an inverted
  // bubble whose labels contradict the volume around it, which Tetrahedralize refuses).
  // (A worker does not search: it only takes edges whose components are surely larger.)
  if (na.size() < 5 &&
    (CurrentZone() < 0 ? this->Mesh.ComponentAtMost(a, 5)
                       : !this->Parts.SurelyMoreThan(a, 5, this->W(), CurrentZone())))
    return false; // a and five neighbours are six already
  // The triangles that change: a's (a becomes b) and, when b moves, b's.
  const Vec3 x = to ? *to : this->Mesh.P[b];
  const Mat3 mx = to ? Mat3(0.5 * (this->Mesh.M[a] + this->Mesh.M[b])) : this->Mesh.M[b];
  changed.clear();
  removed = this->Mesh.VT[a];
  for (int t : this->Mesh.VT[a])
    if (std::find(edge.begin(), edge.end(), t) == edge.end())
      changed.push_back(t);
  if (to)
    for (int t : this->Mesh.VT[b])
      if (std::find(edge.begin(), edge.end(), t) == edge.end())
      {
        changed.push_back(t);
        removed.push_back(t);
      }
  ids.clear();
  pos.clear();
  sheets.clear();
  swept.clear();
  for (int t : changed)
  {
    std::array<int, 3> v;
    std::array<Vec3, 3> p;
    int other[2], o = 0;
    for (int k = 0; k < 3; ++k)
    {
      v[k] = this->Mesh.T[t].V[k] == a ? b : this->Mesh.T[t].V[k];
      p[k] = v[k] == b ? x : this->Mesh.P[v[k]];
      if (v[k] != b)
        other[o++] = v[k];
    }
    const Vec3 n0 = this->Mesh.Normal(t), n1 = (p[1] - p[0]).cross(p[2] - p[0]);
    if (n1.norm() <= 1e-12 * n0.norm() || n0.normalized().dot(n1.normalized()) < 0.5)
      return false;
    if (MinAngle(p[0], p[1], p[2]) < this->NewAngleFloor) // a cap or needle no later flip may mend
      return false;
    if (!this->Curves.Allowed(this->Mesh, b, this->Mesh.T[t].Sheet) &&
      !(zip && this->Curves.Allowed(this->Mesh, a, this->Mesh.T[t].Sheet)))
      return false;
    if (this->Mesh.Length(x, mx, other[0]) > this->LongestEdge ||
      this->Mesh.Length(x, mx, other[1]) > this->LongestEdge)
      return false;
    ids.push_back(v);
    pos.push_back(p);
    sheets.push_back(this->Mesh.T[t].Sheet);
    // The corner that moves (a, or b on its way to 'to') sweeps a tetrahedron over the fixed edge.
    const bool ofA = this->Mesh.T[t].V[0] == a || this->Mesh.T[t].V[1] == a || this->Mesh.T[t].V[2] == a;
    swept.push_back({ { this->Mesh.P[other[0]], this->Mesh.P[other[1]], this->Mesh.P[ofA ? a : b], x } });
  }
  if (!this->LabelsInOrderAround(b, x, edge, changed, ids))
    return false;
  // The distance samples last: they cost most, and the cheaper checks above refuse many
  // collapses first. Where b stays, its edges stay.
  static const std::vector<int> none;
  if (!this->Approximation.StarNear(ids, pos, sheets, b, to ? none : nb))
    return false;
  {
    // The input vertices a stood for must stay within Eps of the triangles of their interface
    // around b afterwards, and those of b and a's other neighbours within Eps of theirs (so no
    // patch of an interface can retract or vanish).
    affected = na;
    if (to)
      affected.insert(affected.end(), nb.begin(), nb.end());
    std::sort(affected.begin(), affected.end());
    affected.erase(std::unique(affected.begin(), affected.end()), affected.end());
    affected.erase(std::remove(affected.begin(), affected.end(), a), affected.end());
    if (!this->Approximation.ClustersStayNear(removed, ids, pos, sheets, changed, affected, worker, a, b))
      return false;
    if (this->Crossing.Crosses(ids, pos, removed, this->W(), &swept))
      return false;
  }
  this->Approximation.KeepHints(this->W());
  this->ApplyCollapse(a, b, x, mx, zip, to != nullptr);
  return true;
}

/// Collapse of an edge between two surface vertices into the point of the input nearest its
/// middle (on the side its triangles face): where neither end can take the other's triangles
/// without an edge longer than LongEdge, the middle often can: fewer triangles at the same
/// Hausdorff distance and angles.
bool Remesher::CollapseToMiddle(int a, int b, bool& outside)
{
  outside = false;
  if (this->Mesh.Kind[a] != amSurfaceMesh::Surface || this->Mesh.Kind[b] != amSurfaceMesh::Surface)
    return false;
  Vec3 n = Vec3::Zero();
  for (int v : { a, b })
    for (int t : this->Mesh.VT[v])
    {
      n += this->Mesh.Normal(t);
      // Not beside a junction curve: moving b there makes needles across the crease that no
      // insertion can bring back within Eps.
      for (int k = 0; k < 3; ++k)
        if (this->Mesh.Kind[this->Mesh.T[t].V[k]] != amSurfaceMesh::Surface)
          return false;
    }
  if (n.norm() == 0)
    return false;
  const Vec3 m = 0.5 * (this->Mesh.P[a] + this->Mesh.P[b]);
  double cl[3];
  vtkIdType tri;
  if (this->In.Ref[this->Mesh.T[this->Mesh.VT[a][0]].Sheet].ClosestPointFacing(m.data(), n.data(), cl, tri) ==
    std::numeric_limits<double>::infinity())
    return false;
  const Vec3 x(cl);
  if (CurrentZone() >= 0 && this->Grid.ZoneAt(x) != CurrentZone())
  {
    outside = true;
    return false;
  }
  return this->Collapse(a, b, &x);
}

/// The collapse of a short edge in one of its forms: 1 done, 0 refused, -1 left for the serial
/// pass (a worker's collapse into a middle outside its zone).
int Remesher::TryCollapse(int a, int b)
{
  if (!this->Mesh.VAlive[a] || !this->Mesh.VAlive[b] || this->Mesh.Length(a, b) >= ShortEdge)
    return 0;
  // Remove the less constrained end first.
  if (this->Mesh.Kind[a] <= this->Mesh.Kind[b] ? (this->Collapse(a, b) || this->Collapse(b, a))
                                               : (this->Collapse(b, a) || this->Collapse(a, b)))
    return 1;
  bool outside = false;
  if (this->CollapseToMiddle(a, b, outside))
    return 1;
  return outside ? -1 : 0;
}

int Remesher::CollapsePass()
{
  this->Mesh.SizeDirty();
  // Shortest first, by classes of metric length a tenth wide, and within a class in the Morton
  // order of the edges' midpoints (cells the size of the bins): consecutive collapses then
  // read and change the same part of memory. (Edges in order of length alone were scattered
  // over the whole surface: most reads of a collapse's checks missed the caches.)
  struct Candidate
  {
    long long Class;
    unsigned long long Code;
    double Length;
    int A, B;
    bool operator<(const Candidate& o) const
    {
      return std::tie(this->Class, this->Code, this->Length, this->A, this->B) <
        std::tie(o.Class, o.Code, o.Length, o.A, o.B);
    }
    bool operator==(const Candidate& o) const { return this->A == o.A && this->B == o.B; }
  };
  // Gathered on the threads (each edge once from one of its triangles, as the half-edge
  // a -> b with a < b; a junction edge maybe more than once), sorted whole.
  vtkSMPThreadLocal<std::vector<Candidate>> found;
  vtkSMPTools::For(0, static_cast<vtkIdType>(this->Mesh.T.size()), [&](vtkIdType t0, vtkIdType t1) {
    auto& local = found.Local();
    for (vtkIdType t = t0; t < t1; ++t)
    {
      if (!this->Mesh.T[t].Alive)
        continue;
      for (int k = 0; k < 3; ++k)
      {
        const int a = this->Mesh.T[t].V[k], b = this->Mesh.T[t].V[(k + 1) % 3];
        if (a < b && (this->Mesh.Dirty[a] || this->Mesh.Dirty[b]))
        {
          const double L = this->Mesh.Length(a, b);
          if (L < ShortEdge)
            local.push_back({ static_cast<long long>(L * 10.0),
              Bins::MortonCode(0.5 * (this->Mesh.P[a] + this->Mesh.P[b]), this->Grid.Size), L, a, b });
        }
      }
    }
  });
  std::vector<Candidate> cand;
  for (const auto& local : found)
    cand.insert(cand.end(), local.begin(), local.end());
  amThreading::Sort(cand.begin(), cand.end());
  cand.erase(std::unique(cand.begin(), cand.end()), cand.end());
  std::fill(this->Mesh.Dirty.begin(), this->Mesh.Dirty.end(), 0);
  // Two workers, one on each side of the split plane (see OnTwoWorkers): a collapse changes
  // only the triangles, links, positions and clusters of the stars of a and b.
  this->Parts.Find(this->Mesh, this->Grid, this->Workers);
  return OnTwoWorkers(
    this->Mesh, cand.size(), [&](size_t i) { return this->EdgeZone(cand[i].A, cand[i].B); },
    [&](size_t i) {
      const int a = cand[i].A, b = cand[i].B;
      // Small fragments are left to the serial pass: there the test for them searches the
      // whole component.
      if (CurrentZone() >= 0 &&
        (!this->StarsInZone(a, b, CurrentZone()) || !this->Parts.SurelyMoreThan(a, 5, this->W(), CurrentZone()) ||
          !this->Parts.SurelyMoreThan(b, 5, this->W(), CurrentZone())))
        return this->Mesh.VAlive[a] && this->Mesh.VAlive[b] ? -1 : 0;
      return this->TryCollapse(a, b);
    });
}

void Remesher::ApplyCollapse(int a, int b, const Vec3& x, const Mat3& mx, bool zip, bool moved)
{
  Worker& worker = this->W();
  const auto &edge = worker.C.Edge, &na = worker.C.Na, &nb = worker.C.Nb, &changed = worker.C.Changed;
  for (int t : edge)
    this->Detach(t);
  this->Mesh.Cluster[b].insert(this->Mesh.Cluster[b].end(), this->Mesh.Cluster[a].begin(), this->Mesh.Cluster[a].end());
  std::vector<ClusterEntry>().swap(this->Mesh.Cluster[a]);
  for (int t : this->Mesh.VT[a])
  {
    for (int k = 0; k < 3; ++k)
      if (this->Mesh.T[t].V[k] == a)
        this->Mesh.T[t].V[k] = b;
    this->Mesh.VT[b].push_back(t);
  }
  if (zip)
  {
    auto& merged = this->Mesh.Merged[b];
    const auto& sheets = this->Curves.InputSheets[this->Mesh.Anchor[a]];
    merged.insert(merged.end(), sheets.begin(), sheets.end());
    merged.insert(merged.end(), this->Mesh.Merged[a].begin(), this->Mesh.Merged[a].end());
    std::sort(merged.begin(), merged.end());
    merged.erase(std::unique(merged.begin(), merged.end()), merged.end());
    this->Mesh.Kind[b] = amSurfaceMesh::Corner;
  }
  this->Mesh.VT[a].clear();
  this->Mesh.VAlive[a] = 0;
  this->Mesh.P[b] = x;
  this->Mesh.M[b] = mx;
  this->Grid.Update(changed);
  ++worker.Collapses;
  if (CurrentZone() >= 0)
    ++worker.Removed[this->Parts.Of[a]];
  for (int w : na)
    this->Mesh.Touch(w);
  if (moved)
    for (int w : nb)
      this->Mesh.Touch(w);
}
}
