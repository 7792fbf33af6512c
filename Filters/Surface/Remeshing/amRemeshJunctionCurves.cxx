#include "amRemeshJunctionCurves.h"

#include <functional>
#include <limits>
#include <unordered_map>

namespace amRemesh
{
void JunctionCurves::Build(const amSurfaceMesh& mesh, Surface& surface)
{
  const size_t np = surface.P.size();
  this->InputSheets.assign(np, {});
  surface.Anchor.assign(np, -1);
  surface.Merged.assign(np, {});
  for (size_t v = 0; v < np; ++v)
    if (surface.Kind[v] != amSurfaceMesh::Surface)
    {
      surface.Anchor[v] = static_cast<int>(v);
      auto& sheets = this->InputSheets[v];
      for (int t : surface.VT[v])
        sheets.push_back(surface.T[t].Sheet);
      std::sort(sheets.begin(), sheets.end());
      sheets.erase(std::unique(sheets.begin(), sheets.end()), sheets.end());
    }
  this->CurveNeighbours.assign(np, {});
  for (size_t e = 0; e < mesh.Edges.size(); ++e)
    if (mesh.FeatureEdge[e])
    {
      const int a = static_cast<int>(mesh.Edges[e][0]), b = static_cast<int>(mesh.Edges[e][1]);
      const double l = (surface.P[a] - surface.P[b]).norm();
      this->CurveNeighbours[a].push_back({ b, l });
      this->CurveNeighbours[b].push_back({ a, l });
    }
}

int JunctionCurves::CurveMiddle(int a, int b, double maxLength) const
{
  std::unordered_map<int, std::pair<double, int>> dist; // vertex: distance from a, previous
  std::vector<std::pair<double, int>> heap{ { 0.0, a } };
  dist[a] = { 0.0, -1 };
  bool found = false;
  while (!heap.empty())
  {
    std::pop_heap(heap.begin(), heap.end(), std::greater<>());
    const auto [d, v] = heap.back();
    heap.pop_back();
    if (d > dist[v].first)
      continue;
    if (v == b)
    {
      found = true;
      break;
    }
    for (const auto& [w, l] : this->CurveNeighbours[v])
    {
      const double dw = d + l;
      if (dw > maxLength)
        continue;
      auto it = dist.find(w);
      if (it == dist.end() || dw < it->second.first)
      {
        dist[w] = { dw, v };
        heap.push_back({ dw, w });
        std::push_heap(heap.begin(), heap.end(), std::greater<>());
      }
    }
  }
  if (!found)
    return -1;
  const double half = 0.5 * dist[b].first;
  int best = -1;
  double bestGap = std::numeric_limits<double>::infinity();
  for (int v = dist[b].second; v != a && v >= 0; v = dist[v].second)
    if (std::abs(dist[v].first - half) < bestGap)
    {
      bestGap = std::abs(dist[v].first - half);
      best = v;
    }
  return best;
}
}
