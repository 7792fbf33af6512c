#include "amTetraImproveMesh.h"

#include "amSelfIntersection.h"
#include "amSurfaceMesh.h"
#include "amVolumeOffsets.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <map>

namespace amTetraImprove
{
namespace
{
constexpr int Outside = INT_MIN; // the label beyond the mesh's boundary: no target

/// A fixed face and the regions on its two sides: Region[0] is the tetrahedron it was first met
/// from, Out its area vector pointing out of that tetrahedron; Region[1] Outside at the boundary.
struct SidedFace
{
  Tri V;
  int Region[2] = { Outside, Outside };
  Vec Out{ { 0, 0, 0 } };
  int Lo() const { return std::min(this->Region[0], this->Region[1]); }
  int Hi() const { return std::max(this->Region[0], this->Region[1]); }
  /// The area vector pointing out of the lower label's side.
  Vec OutOfLo() const
  {
    return this->Region[0] == this->Lo() ? this->Out : Vec{ { -this->Out[0], -this->Out[1], -this->Out[2] } };
  }
};

/// Every fixed face between two regions or at the boundary, in the order the tetrahedra meet them.
std::vector<SidedFace> FacesWithSides(const Mesh& m)
{
  std::vector<SidedFace> faces;
  std::unordered_map<Tri, size_t, TriHash> index;
  index.reserve(2 * m.FixedFaces.size());
  for (size_t t = 0; t < m.T.size(); ++t)
  {
    if (!m.Alive[t])
      continue;
    const Tet& x = m.T[t];
    for (int i = 0; i < 4; ++i)
    {
      const int a = x[(i + 1) % 4], b = x[(i + 2) % 4], c = x[(i + 3) % 4];
      if (!m.FixedVertex[a] || !m.FixedVertex[b] || !m.FixedVertex[c])
        continue; // (a fixed face has its three vertices fixed: most faces are passed without a lookup)
      const Tri key = Sorted(a, b, c);
      if (!m.FixedFaces.count(key))
        continue;
      const auto found = index.find(key);
      if (found != index.end())
      {
        faces[found->second].Region[1] = m.R[t];
        continue;
      }
      SidedFace f;
      f.V = { { a, b, c } };
      f.Region[0] = m.R[t];
      Vec n = amTetraGeometry::Cross(amTetraGeometry::Sub(m.X(b), m.X(a)), amTetraGeometry::Sub(m.X(c), m.X(a)));
      if (amTetraGeometry::Dot(n, amTetraGeometry::Sub(m.X(x[i]), m.X(a))) > 0)
        n = { { -n[0], -n[1], -n[2] } };
      f.Out = { { 0.5 * n[0], 0.5 * n[1], 0.5 * n[2] } };
      index.emplace(key, faces.size());
      faces.push_back(f);
    }
  }
  return faces;
}

/// Indices (into 'boundary') of the boundary faces that cross another boundary face, among those
/// with a vertex marked in 'moved': the tetrahedra keep every interface inside the mesh from
/// crossing (none inverts), but two parts of the boundary may meet.
std::vector<vtkIdType> BoundaryCrossings(
  const Mesh& m, const std::vector<Tri>& boundary, const std::vector<char>& moved)
{
  amSurfaceMesh surface;
  std::vector<std::array<double, 3>> points(m.Inc.size());
  for (size_t v = 0; v < points.size(); ++v)
    points[v] = { { m.X(static_cast<int>(v))[0], m.X(static_cast<int>(v))[1], m.X(static_cast<int>(v))[2] } };
  std::vector<vtkIdType> among;
  for (size_t f = 0; f < boundary.size(); ++f)
  {
    const Tri& t = boundary[f];
    surface.Triangles.push_back({ { t[0], t[1], t[2] } });
    if (moved[t[0]] || moved[t[1]] || moved[t[2]])
      among.push_back(static_cast<vtkIdType>(f));
  }
  if (among.empty())
    return {};
  return amSelfIntersection::AllTriangles(surface, points, &among);
}
}

long PreserveVolumes(
  Mesh& m, const std::map<int, double>& target, double limit, double floor, int rounds, double& displacement)
{
  long moves = 0;
  const std::vector<double> start = m.P;
  std::vector<char> ever(m.Inc.size(), 0);
  for (int round = 0; round < rounds; ++round)
  {
    std::map<int, double> now;
    for (size_t t = 0; t < m.T.size(); ++t)
      if (m.Alive[t])
        now[m.R[t]] += amTetraGeometry::SignedVolume(m.X(m.T[t][0]), m.X(m.T[t][1]), m.X(m.T[t][2]), m.X(m.T[t][3]));
    std::map<int, double> error;
    for (const auto& kv : now)
    {
      const auto it = target.find(kv.first);
      if (it != target.end() && it->second > 0)
        error[kv.first] = it->second - kv.second;
    }
    if (error.empty())
      break;

    // A vertex moves when all its fixed faces lie on one interface (junction curves and corners
    // stay): along the sum of their area vectors out of the interface's lower label, which is
    // also its volume sensitivity (a third of that sum's length).
    const std::vector<SidedFace> faces = FacesWithSides(m);
    std::vector<std::vector<int>> facesOf(m.Inc.size());
    for (size_t f = 0; f < faces.size(); ++f)
      for (int v : faces[f].V)
        facesOf[v].push_back(static_cast<int>(f));
    std::map<std::pair<int, int>, int> sheetOf;
    std::vector<amVolumeOffsets::Sheet> sheets;
    std::vector<int> movable, sheetOfVertex(m.Inc.size(), -1);
    std::vector<Vec> normal(m.Inc.size(), Vec{ { 0, 0, 0 } });
    for (size_t v = 0; v < m.Inc.size(); ++v)
    {
      const std::vector<int>& around = facesOf[v];
      if (around.empty())
        continue;
      const int lo = faces[around[0]].Lo(), hi = faces[around[0]].Hi();
      bool one = true;
      Vec sum{ { 0, 0, 0 } };
      double area = 0;
      for (int f : around)
      {
        one = one && faces[f].Lo() == lo && faces[f].Hi() == hi;
        const Vec a = faces[f].OutOfLo();
        for (int k = 0; k < 3; ++k)
          sum[k] += a[k];
        area += amTetraGeometry::Norm(a) / 3.0;
      }
      const double length = amTetraGeometry::Norm(sum);
      if (!one || !(length > 0))
        continue;
      const auto inserted = sheetOf.emplace(std::make_pair(lo, hi), static_cast<int>(sheets.size()));
      if (inserted.second)
        sheets.push_back({ lo, hi, 0.0, 0.0 });
      amVolumeOffsets::Sheet& sheet = sheets[inserted.first->second];
      sheet.Sensitivity += length / 3.0;
      sheet.Area += area;
      sheetOfVertex[v] = inserted.first->second;
      normal[v] = { { sum[0] / length, sum[1] / length, sum[2] / length } };
      movable.push_back(static_cast<int>(v));
    }
    const std::vector<double> offset = amVolumeOffsets::Solve(sheets, error, limit);
    if (offset.empty())
      break;

    // Each vertex moved by its interface's offset (else half, a quarter) where no element of its
    // star inverts or falls below 'floor' (or below its star's worst, if that is lower).
    std::vector<double> before = m.P;
    std::vector<char> moved(m.Inc.size(), 0);
    long done = 0;
    for (int v : movable)
    {
      const double o = offset[sheetOfVertex[v]];
      if (!(std::fabs(o) > 1e-4 * limit))
        continue;
      double worst0, sum0;
      CurrentStar(m, v, worst0, sum0);
      const double bar = std::min(worst0, floor);
      for (double step : { 1.0, 0.5, 0.25 })
      {
        // Within 'limit' of where the vertex started, over all rounds.
        const double* x = m.X(v);
        const double* s = &start[3 * static_cast<size_t>(v)];
        double y[3], d[3];
        for (int k = 0; k < 3; ++k)
          d[k] = x[k] + step * o * normal[v][k] - s[k];
        const double far = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        for (int k = 0; k < 3; ++k)
          y[k] = s[k] + (far > limit ? limit / far : 1.0) * d[k];
        double worst, sum;
        StarQuality(m, v, y, worst, sum, bar);
        if (worst >= bar && worst > 0 && std::isfinite(sum))
        {
          MoveVertex(m, v, y);
          moved[v] = 1;
          ++done;
          break;
        }
      }
    }

    // Two parts of the boundary brought into each other: their vertices go back; if that does
    // not clear it, the whole round is undone.
    std::vector<Tri> boundary;
    for (const SidedFace& f : faces)
      if (f.Region[1] == Outside)
        boundary.push_back(f.V);
    for (int attempt = 0; done > 0; ++attempt)
    {
      const std::vector<vtkIdType> crossing = BoundaryCrossings(m, boundary, moved);
      if (crossing.empty())
        break;
      // The moved vertices of the crossing faces (the third time, every moved vertex), in vertex
      // order whatever order the crossings came in: a move back depends on those before it.
      const bool all = attempt == 2;
      std::vector<char> back(m.Inc.size(), 0);
      for (vtkIdType f : crossing)
        for (int v : boundary[f])
          back[v] = 1;
      for (size_t v = 0; v < back.size(); ++v)
      {
        if (!moved[v] || !(all || back[v]))
          continue;
        double worst, sum;
        StarQuality(m, static_cast<int>(v), &before[3 * v], worst, sum);
        if (all || (worst > 0 && std::isfinite(sum)))
        {
          MoveVertex(m, static_cast<int>(v), &before[3 * v]);
          moved[v] = 0;
          --done;
        }
      }
    }
    moves += done;
    for (size_t v = 0; v < moved.size(); ++v)
      ever[v] = ever[v] || moved[v];
    if (done == 0)
      break;
    // The free vertices around those moved make room for the next round.
    SmoothAll(m, m.Inc.size());
  }
  displacement = 0;
  for (size_t v = 0; v < ever.size(); ++v)
    if (ever[v])
      displacement =
        std::max(displacement, amTetraGeometry::Norm(amTetraGeometry::Sub(m.X(static_cast<int>(v)), &start[3 * v])));
  return moves;
}
}
