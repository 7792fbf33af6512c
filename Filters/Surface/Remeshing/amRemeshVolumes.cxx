#include "amRemeshScheduler.h"
#include "amRemesher.h"
#include "amSurfaceMesh.h"
#include "amThreading.h"
#include "amVolumeOffsets.h"

#include <algorithm>
#include <cmath>

namespace amRemesh
{
namespace
{
/// Six times the signed volume of the tetrahedron (origin, a, b, c): the triangle's share of
/// the volume of the region its normal leaves (Labels[0]), by the divergence theorem.
double SixVolume(const double* a, const double* b, const double* c)
{
  return a[0] * (b[1] * c[2] - b[2] * c[1]) + a[1] * (b[2] * c[0] - b[0] * c[2]) + a[2] * (b[0] * c[1] - b[1] * c[0]);
}
}

std::map<int, double> RegionVolumes(const amSurfaceMesh& mesh)
{
  std::map<int, double> volumes;
  if (mesh.Labels.size() != mesh.Triangles.size())
    return volumes;
  for (size_t t = 0; t < mesh.Triangles.size(); ++t)
  {
    const auto& v = mesh.Triangles[t];
    const double six = SixVolume(mesh.Points[v[0]].data(), mesh.Points[v[1]].data(), mesh.Points[v[2]].data());
    volumes[mesh.Labels[t][0]] += six / 6.0;
    volumes[mesh.Labels[t][1]] -= six / 6.0;
  }
  return volumes;
}

std::map<int, double> Remesher::RegionVolumes() const
{
  std::map<int, double> volumes;
  for (const Triangle& t : this->Mesh.T)
    if (t.Alive)
    {
      const double six =
        SixVolume(this->Mesh.P[t.V[0]].data(), this->Mesh.P[t.V[1]].data(), this->Mesh.P[t.V[2]].data());
      volumes[t.Labels[0]] += six / 6.0;
      volumes[t.Labels[1]] -= six / 6.0;
    }
  return volumes;
}

/// The vertices of each interface move along their normals by one offset per interface, the
/// offsets of smallest weighted norm (sum of area x offset^2) that give every region its target
/// volume to first order: a sparse system over the regions (regions x regions, a region coupled
/// to its neighbours). Junction-curve vertices stay, so the curves where regions meet do not
/// move; each vertex moves only where the crossing and approximation guards allow it, so the
/// surface stays within the tolerance of the input and free of crossings. Label 0 (outside) has
/// no target: its interfaces take up what the others need.
int Remesher::PreserveVolumes(const std::map<int, double>& target, int rounds)
{
  Surface& S = this->Mesh;
  int moved = 0;
  for (int round = 0; round < rounds; ++round)
  {
    const std::map<int, double> now = this->RegionVolumes();
    // The regions to correct: every label with a target, except the outside.
    std::map<int, double> error;
    for (const auto& kv : now)
      if (kv.first != 0 && target.count(kv.first) && target.at(kv.first) > 0)
        error[kv.first] = target.at(kv.first) - kv.second;
    if (error.empty())
      break;
    // Per interface vertex: the normal out of the interface's smaller label, and its volume
    // sensitivity (a third of the star's area vectors along it); per interface: the sums.
    int sheets = 0;
    for (const Triangle& t : S.T)
      if (t.Alive)
        sheets = std::max(sheets, t.Sheet + 1);
    std::vector<double> sensitivity(static_cast<size_t>(sheets), 0.0), area(static_cast<size_t>(sheets), 0.0);
    std::vector<std::array<int, 2>> sides(static_cast<size_t>(sheets), { { -1, -1 } });
    std::vector<Vec3> normal(S.P.size(), Vec3::Zero());
    std::vector<int> movable;
    for (size_t v = 0; v < S.P.size(); ++v)
    {
      if (!S.VAlive[v] || S.Kind[v] != amSurfaceMesh::Surface || S.VT[v].empty())
        continue;
      const Triangle& first = S.T[S.VT[v][0]];
      const int lo = std::min(first.Labels[0], first.Labels[1]);
      Vec3 sum = Vec3::Zero();
      double a = 0;
      for (int t : S.VT[v])
      {
        const Triangle& tri = S.T[t];
        const Vec3 av = 0.5 * (S.P[tri.V[1]] - S.P[tri.V[0]]).cross(S.P[tri.V[2]] - S.P[tri.V[0]]);
        sum += tri.Labels[0] == lo ? av : Vec3(-av);
        a += av.norm() / 3.0;
      }
      if (sum.norm() == 0)
        continue;
      normal[v] = sum.normalized();
      sensitivity[first.Sheet] += sum.dot(normal[v]) / 3.0;
      area[first.Sheet] += a;
      sides[first.Sheet] = { lo, std::max(first.Labels[0], first.Labels[1]) };
      movable.push_back(static_cast<int>(v));
    }
    std::vector<amVolumeOffsets::Sheet> system(static_cast<size_t>(sheets));
    for (int k = 0; k < sheets; ++k)
      if (sides[k][0] >= 0)
        system[k] = { sides[k][0], sides[k][1], sensitivity[k], area[k] };
    std::vector<double> offset = amVolumeOffsets::Solve(system, error, this->In.Eps);
    if (offset.empty())
      break;
    if (this->RoundVolumeOffsets)
      for (double& o : offset)
        o = std::round(o / (0.02 * this->In.Eps)) * (0.02 * this->In.Eps);
    bool any = false;
    for (double o : offset)
      any = any || std::fabs(o) > 1e-4 * this->In.Eps;
    if (!any)
      break;
    // Each vertex moved by its interface's offset, where the guards allow it, on the two workers:
    // no smaller angle than before (the elements TetGen builds on the triangles), but in the last
    // round, for what the others left, angles down to SmallAngle.
    const bool relax = round + 1 < rounds;
    this->Grid.RebuildIfStale();
    std::vector<std::pair<unsigned long long, int>> order;
    for (int v : movable)
      if (std::fabs(offset[S.T[S.VT[v][0]].Sheet]) > 1e-4 * this->In.Eps)
        order.push_back({ Bins::MortonCode(S.P[v], this->Grid.Size), v });
    amThreading::Sort(order.begin(), order.end());
    const int done = OnTwoWorkers(
      S, order.size(), [&](size_t i) { return this->Grid.ZoneAt(S.P[order[i].second]); },
      [&](size_t i) {
        const int v = order[i].second;
        if (CurrentZone() >= 0 && !this->StarsInZone(v, v, CurrentZone()))
          return -1;
        const Vec3 x = S.P[v] + offset[S.T[S.VT[v][0]].Sheet] * normal[v];
        if (CurrentZone() >= 0 && this->Grid.ZoneAt(x) != CurrentZone())
          return -1;
        return this->Move(v, x, relax) ? 1 : 0;
      });
    moved += done;
    if (done == 0)
      break;
  }
  return moved;
}
}
