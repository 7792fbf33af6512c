#include "amRemesher.h"

#include <algorithm>
#include <cmath>

namespace amRemesh
{
/// Whether, once a collapse into b is done, the regions still alternate consistently around
/// every edge at b: going round the edge, each triangle's side ahead faces the same region as the
/// next triangle's side behind. A collapse near a junction curve can fold a triangle over its
/// neighbour there (no crossing: they share the edge), or, closing a strip between two curves,
/// join edges whose triangles then interleave: a volume bounded by two labels, which TetGen
/// refuses.
/// 'at': where b is afterwards; 'gone': b's triangles that disappear; 'changed' with 'ids': the
/// triangles that change and their vertices afterwards (labels and orientation as before).
bool Remesher::LabelsInOrderAround(int b, const Vec3& at, const std::vector<int>& gone, const std::vector<int>& changed,
  const std::vector<std::array<int, 3>>& ids) const
{
  struct Fan
  {
    int Third;
    int Ahead, Behind;
  };
  // Triangles at b afterwards: vertices and labels.
  std::vector<std::pair<std::array<int, 3>, int>> star; // vertices, triangle slot (for labels)
  for (int t : this->Mesh.VT[b])
    if (std::find(gone.begin(), gone.end(), t) == gone.end() &&
      std::find(changed.begin(), changed.end(), t) == changed.end())
      star.push_back({ { this->Mesh.T[t].V[0], this->Mesh.T[t].V[1], this->Mesh.T[t].V[2] }, t });
  for (size_t n = 0; n < changed.size(); ++n)
    star.push_back({ ids[n], changed[n] });
  std::vector<int> others;
  for (const auto& s : star)
    for (int v : s.first)
      if (v != b)
        others.push_back(v);
  std::sort(others.begin(), others.end());
  others.erase(std::unique(others.begin(), others.end()), others.end());
  std::vector<std::pair<double, Fan>> fan;
  for (int w : others)
  {
    fan.clear();
    const Vec3 axis = (this->Mesh.P[w] - at).normalized();
    Vec3 u = axis.unitOrthogonal(), v = axis.cross(u);
    for (const auto& s : star)
    {
      const auto& x = s.first;
      const int kb = static_cast<int>(std::find(x.begin(), x.end(), b) - x.begin());
      const int kw = static_cast<int>(std::find(x.begin(), x.end(), w) - x.begin());
      if (kw == 3)
        continue;
      const int third = x[3 - kb - kw];
      // b -> w -> third in the triangle's own order: its normal turns the way the angle grows,
      // so its Labels[1] side (where the normal points) is ahead.
      const bool forward = (kb + 1) % 3 == kw;
      const Triangle& t = this->Mesh.T[s.second];
      const Vec3 d = this->Mesh.P[third] - at;
      const double angle = std::atan2(d.dot(v), d.dot(u));
      fan.push_back({ angle, { third, forward ? t.Labels[1] : t.Labels[0], forward ? t.Labels[0] : t.Labels[1] } });
    }
    if (fan.size() < 3)
      continue; // one or two triangles: nothing can interleave
    std::sort(fan.begin(), fan.end(), [](const auto& p, const auto& q) { return p.first < q.first; });
    for (size_t i = 0; i < fan.size(); ++i)
      if (fan[i].second.Ahead != fan[(i + 1) % fan.size()].second.Behind)
        return false;
  }
  return true;
}
}
