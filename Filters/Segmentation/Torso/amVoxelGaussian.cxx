// Separable Gaussian smoothing in millimetres.
#include "amVoxelGrid.h"

#include "vtkSMPTools.h"

#include <algorithm>
#include <cmath>

void amVoxel::Gaussian(const amVoxelGrid& g, std::vector<float>& field, double sigma)
{
  const std::size_t stride[3] = { 1, static_cast<std::size_t>(g.N[0]), static_cast<std::size_t>(g.N[0]) * g.N[1] };
  for (int a = 0; a < 3; ++a)
  {
    const double s = sigma / g.Spacing[a];
    if (s < 0.1 || g.N[a] < 2)
      continue;
    const int r = static_cast<int>(std::ceil(3.0 * s));
    std::vector<double> w(2 * r + 1);
    double sum = 0.0;
    for (int t = -r; t <= r; ++t)
      sum += w[t + r] = std::exp(-0.5 * t * t / (s * s));
    for (double& x : w)
      x /= sum;
    const int n = g.N[a];
    const int b = (a + 1) % 3, c = (a + 2) % 3;
    // The lines along the axis are independent: on the threads.
    vtkSMPTools::For(0, static_cast<vtkIdType>(g.N[b]) * g.N[c], [&](vtkIdType l0, vtkIdType l1) {
      std::vector<float> line(n), smoothed(n);
      for (vtkIdType l = l0; l < l1; ++l)
      {
        const std::size_t p = static_cast<std::size_t>(l % g.N[b]), q = static_cast<std::size_t>(l / g.N[b]);
        const std::size_t start = p * stride[b] + q * stride[c];
        for (int t = 0; t < n; ++t)
          line[t] = field[start + t * stride[a]];
        for (int t = 0; t < n; ++t)
        {
          double acc = 0.0;
          for (int u = -r; u <= r; ++u)
            acc += w[u + r] * line[std::min(std::max(t + u, 0), n - 1)];
          smoothed[t] = static_cast<float>(acc);
        }
        for (int t = 0; t < n; ++t)
          field[start + t * stride[a]] = smoothed[t];
      }
    });
  }
}
