// Exact Euclidean distance transform (P. Felzenszwalb and D. Huttenlocher, Distance Transforms
// of Sampled Functions, 2012): the squared distance is a lower envelope of parabolas per axis.
#include "amVoxelGrid.h"

#include "vtkSMPTools.h"

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
  const vtkIdType count = static_cast<vtkIdType>(mask.size());
  std::vector<double> sq(mask.size());
  vtkSMPTools::For(0, count, [&](vtkIdType i0, vtkIdType i1) {
    for (vtkIdType i = i0; i < i1; ++i)
      sq[i] = mask[i] ? 0.0 : inf;
  });
  const std::size_t stride[3] = { 1, static_cast<std::size_t>(g.N[0]), static_cast<std::size_t>(g.N[0]) * g.N[1] };
  for (int a = 0; a < 3; ++a)
  {
    // The lines along axis a are independent: on the threads, each with its own buffers.
    const int n = g.N[a], b = (a + 1) % 3, c = (a + 2) % 3;
    vtkSMPTools::For(0, static_cast<vtkIdType>(g.N[b]) * g.N[c], [&](vtkIdType l0, vtkIdType l1) {
      std::vector<double> f(n), d, z;
      std::vector<int> v;
      for (vtkIdType line = l0; line < l1; ++line)
      {
        const std::size_t start = (line % g.N[b]) * stride[b] + (line / g.N[b]) * stride[c];
        for (int t = 0; t < n; ++t)
          f[t] = sq[start + t * stride[a]];
        Envelope(f, d, g.Spacing[a], v, z);
        for (int t = 0; t < n; ++t)
          sq[start + t * stride[a]] = d[t];
      }
    });
  }
  std::vector<float> out(mask.size());
  vtkSMPTools::For(0, count, [&](vtkIdType i0, vtkIdType i1) {
    for (vtkIdType i = i0; i < i1; ++i)
      out[i] = sq[i] == inf ? std::numeric_limits<float>::max() : static_cast<float>(std::sqrt(sq[i]));
  });
  return out;
}
