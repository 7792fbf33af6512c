// Exact Euclidean distance transform (P. Felzenszwalb and D. Huttenlocher, Distance Transforms
// of Sampled Functions, 2012): the squared distance is a lower envelope of parabolas per axis.
#include "amVoxelGrid.h"

#include <cmath>
#include <limits>

namespace
{
// One axis of the transform: f holds squared distances along a line (h = spacing).
void Envelope(
  const std::vector<double>& f, std::vector<double>& d, double h, std::vector<int>& v, std::vector<double>& z)
{
  const int n = static_cast<int>(f.size());
  const double inf = std::numeric_limits<double>::infinity();
  v.assign(n, 0);
  z.assign(n + 1, 0.0);
  int k = -1;
  for (int q = 0; q < n; ++q)
  {
    if (f[q] == inf)
      continue;
    double s = -inf;
    while (k >= 0)
    {
      const double pq = q * h, pv = v[k] * h;
      s = ((f[q] + pq * pq) - (f[v[k]] + pv * pv)) / (2.0 * (pq - pv));
      if (s > z[k])
        break;
      --k;
    }
    ++k;
    v[k] = q;
    z[k] = k == 0 ? -inf : s;
    z[k + 1] = inf;
  }
  d.assign(n, inf);
  if (k < 0)
    return;
  int j = 0;
  for (int q = 0; q < n; ++q)
  {
    while (z[j + 1] < q * h)
      ++j;
    const double t = (q - v[j]) * h;
    d[q] = t * t + f[v[j]];
  }
}
}

std::vector<float> amVoxel::Distance(const amVoxelGrid& g, const amVoxelMask& mask)
{
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<double> sq(mask.size());
  for (std::size_t v = 0; v < mask.size(); ++v)
    sq[v] = mask[v] ? 0.0 : inf;
  const std::size_t stride[3] = { 1, static_cast<std::size_t>(g.N[0]), static_cast<std::size_t>(g.N[0]) * g.N[1] };
  std::vector<double> f, d, z;
  std::vector<int> v;
  for (int a = 0; a < 3; ++a)
  {
    const int n = g.N[a], b = (a + 1) % 3, c = (a + 2) % 3;
    f.resize(n);
    for (int q = 0; q < g.N[c]; ++q)
      for (int p = 0; p < g.N[b]; ++p)
      {
        const std::size_t start = p * stride[b] + q * stride[c];
        for (int t = 0; t < n; ++t)
          f[t] = sq[start + t * stride[a]];
        Envelope(f, d, g.Spacing[a], v, z);
        for (int t = 0; t < n; ++t)
          sq[start + t * stride[a]] = d[t];
      }
  }
  std::vector<float> out(mask.size());
  for (std::size_t i = 0; i < mask.size(); ++i)
    out[i] = sq[i] == inf ? std::numeric_limits<float>::max() : static_cast<float>(std::sqrt(sq[i]));
  return out;
}
