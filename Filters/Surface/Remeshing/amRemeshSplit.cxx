#include "amRemesher.h"

#include <limits>

namespace amRemesh
{
/// Split edge k of triangle t (and every triangle on that edge) at x, unless the new triangles
/// would cross another triangle. Returns whether it was done.
bool Remesher::SplitEdge(int t, int k, Vec3 x)
{
  this->W().LastHit = -1;
  if (!this->Mesh.T[t].Alive)
    return false;
  const int a = this->Mesh.T[t].V[k], b = this->Mesh.T[t].V[(k + 1) % 3];
  if (this->Mesh.Held[a] && this->Mesh.Held[b])
    return false;
  std::vector<int> edge;
  this->Mesh.EdgeTriangles(a, b, edge);
  const bool feature = this->Mesh.IsFeature(edge);
  int curvePoint = -1;
  if (feature)
  {
    // A junction edge is split at the input curve vertex nearest its midpoint (a point of one
    // interface off the curve would fold the others).
    if (this->Mesh.Anchor[a] < 0 || this->Mesh.Anchor[b] < 0)
      return false;
    const double length = (this->Mesh.P[b] - this->Mesh.P[a]).norm();
    curvePoint = this->Curves.CurveMiddle(this->Mesh.Anchor[a], this->Mesh.Anchor[b], 4.0 * length);
    if (curvePoint < 0)
      return false;
    for (int e : edge)
      if (!std::binary_search(this->Curves.InputSheets[curvePoint].begin(), this->Curves.InputSheets[curvePoint].end(),
            this->Mesh.T[e].Sheet))
        return false;
    x = this->In.Points[curvePoint];
  }
  const int v = static_cast<int>(this->Mesh.P.size());
  struct Half
  {
    int P, Q, C;
  };
  std::vector<Half> halves;
  std::vector<std::array<int, 3>> ids;
  std::vector<std::array<Vec3, 3>> pos;
  for (int e : edge)
  {
    const Triangle& like = this->Mesh.T[e];
    int i = 0;
    while (!(like.V[i] == a || like.V[i] == b) || !(like.V[(i + 1) % 3] == a || like.V[(i + 1) % 3] == b))
      ++i;
    const Half h{ like.V[i], like.V[(i + 1) % 3], like.V[(i + 2) % 3] };
    halves.push_back(h);
    ids.push_back({ h.P, v, h.C });
    pos.push_back({ this->Mesh.P[h.P], x, this->Mesh.P[h.C] });
    ids.push_back({ v, h.Q, h.C });
    pos.push_back({ x, this->Mesh.P[h.Q], this->Mesh.P[h.C] });
  }
  for (const auto& q : pos)
    if (MinAngle(q[0], q[1], q[2]) < MinimumNewAngle)
      return false;
  if (this->Crossing.Crosses(ids, pos, edge, this->W()))
    return false;
  this->Mesh.AddVertex(
    x, 0.5 * (this->Mesh.M[a] + this->Mesh.M[b]), feature ? amSurfaceMesh::Curve : amSurfaceMesh::Surface, curvePoint);
  for (size_t n = 0; n < edge.size(); ++n)
  {
    const Triangle like = this->Mesh.T[edge[n]];
    this->Detach(edge[n]);
    this->AddTriangle(halves[n].P, v, halves[n].C, like);
    this->AddTriangle(v, halves[n].Q, halves[n].C, like);
  }
  return true;
}

/// Insert x into triangle t (1 -> 3), then improve the neighbourhood by flips; refused when the
/// new triangles would cross another triangle. A point that falls near an edge of t (a new
/// triangle would get under 10 % of t's area) splits that edge instead, so no sliver triangle
/// appears. Returns whether it was done.
bool Remesher::Insert(int t, Vec3 x)
{
  this->W().LastHit = -1;
  if (!this->Mesh.T[t].Alive)
    return false;
  const Triangle like = this->Mesh.T[t];
  const int v = static_cast<int>(this->Mesh.P.size());
  const int* w = like.V;
  if (this->Mesh.Held[w[0]] && this->Mesh.Held[w[1]] && this->Mesh.Held[w[2]])
    return false;
  {
    const Vec3 n = (this->Mesh.P[w[1]] - this->Mesh.P[w[0]]).cross(this->Mesh.P[w[2]] - this->Mesh.P[w[0]]);
    int k = -1;
    double smallest = 0.1;
    for (int e = 0; e < 3; ++e)
    {
      const Vec3& p = this->Mesh.P[w[e]];
      const double fraction = n.dot((this->Mesh.P[w[(e + 1) % 3]] - p).cross(x - p)) / n.squaredNorm();
      if (fraction < smallest)
      {
        smallest = fraction;
        k = e;
      }
    }
    if (k >= 0)
    {
      // Only where x lies beside the edge's middle part; near a corner, neither split is good.
      const Vec3& p = this->Mesh.P[w[k]];
      const Vec3 e = this->Mesh.P[w[(k + 1) % 3]] - p;
      const double along = e.dot(x - p) / e.squaredNorm();
      if (along >= 0.15 && along <= 0.85 && this->SplitEdge(t, k, x))
      {
        this->FlipAround(static_cast<int>(this->Mesh.P.size()) - 1);
        return true;
      }
      // Beside a junction edge that is an edge of the input curve (nothing to split it at),
      // where the interface bulges beyond the curve's chord: insert inside the triangle,
      // moved towards the opposite vertex and put back on the input.
      if (!this->Mesh.IsFeature(w[k], w[(k + 1) % 3]))
        return false;
      const Vec3& o = this->Mesh.P[w[(k + 2) % 3]];
      x += (0.2 - smallest) / (1.0 - smallest) * (o - x);
      double cl[3];
      vtkIdType tri;
      if (this->In.Ref[like.Sheet].ClosestPointFacing(x.data(), n.data(), cl, tri) ==
        std::numeric_limits<double>::infinity())
        return false;
      x = Vec3(cl);
      for (int e = 0; e < 3; ++e)
      {
        const Vec3& q = this->Mesh.P[w[e]];
        if (n.dot((this->Mesh.P[w[(e + 1) % 3]] - q).cross(x - q)) / n.squaredNorm() < 0.05)
          return false;
      }
    }
  }
  for (int e = 0; e < 3; ++e)
    if (MinAngle(this->Mesh.P[w[e]], this->Mesh.P[w[(e + 1) % 3]], x) < MinimumNewAngle)
      return false;
  if (this->Crossing.Crosses({ { w[0], w[1], v }, { w[1], w[2], v }, { w[2], w[0], v } },
        { { this->Mesh.P[w[0]], this->Mesh.P[w[1]], x }, { this->Mesh.P[w[1]], this->Mesh.P[w[2]], x },
          { this->Mesh.P[w[2]], this->Mesh.P[w[0]], x } },
        { t }, this->W()))
    return false;
  const Mat3 m = (this->Mesh.M[like.V[0]] + this->Mesh.M[like.V[1]] + this->Mesh.M[like.V[2]]) / 3.0;
  this->Mesh.AddVertex(x, m, amSurfaceMesh::Surface, -1);
  this->Detach(t);
  this->AddTriangle(like.V[0], like.V[1], v, like);
  this->AddTriangle(like.V[1], like.V[2], v, like);
  this->AddTriangle(like.V[2], like.V[0], v, like);
  this->FlipAround(v);
  return true;
}

/// Split the longest edge of triangle t at the point of the input nearest its midpoint, then
/// flip around the new vertex: how the distance bound is restored where it is exceeded, and
/// where an insertion was refused because it would cross another part of the surface (both
/// come closer to their own input surfaces, which do not cross). Returns the splits done.
int Remesher::Refine(int t)
{
  if (t < 0 || !this->Mesh.T[t].Alive)
    return 0;
  // The longest edge first; where that split is refused, a junction edge of t (it can hold the
  // input curve vertex that a split of the longest edge would fold over; splitting a shorter
  // edge inside the interface instead only made fans of ever shorter edges).
  std::array<std::pair<double, int>, 3> order;
  for (int e = 0; e < 3; ++e)
    order[e] = { -(this->Mesh.P[this->Mesh.T[t].V[(e + 1) % 3]] - this->Mesh.P[this->Mesh.T[t].V[e]]).norm(), e };
  std::sort(order.begin(), order.end());
  // The input point on the side facing the way the triangle faces (in a thin part the nearest
  // input point can lie on the other side, and refining towards it crumples the surface).
  const Vec3 n = this->Mesh.Normal(t);
  for (const auto& [length, k] : order)
  {
    if (k != order[0].second && !this->Mesh.IsFeature(this->Mesh.T[t].V[k], this->Mesh.T[t].V[(k + 1) % 3]))
      continue;
    const Vec3 mid = 0.5 * (this->Mesh.P[this->Mesh.T[t].V[k]] + this->Mesh.P[this->Mesh.T[t].V[(k + 1) % 3]]);
    double cl[3];
    vtkIdType tri;
    if (this->In.Ref[this->Mesh.T[t].Sheet].ClosestPointFacing(mid.data(), n.data(), cl, tri) ==
        std::numeric_limits<double>::infinity() ||
      !this->SplitEdge(t, k, Vec3(cl)))
      continue;
    this->FlipAround(static_cast<int>(this->Mesh.P.size()) - 1);
    return 1;
  }
  return 0;
}
}
