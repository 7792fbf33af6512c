// The noise of a scan, and how much of it a Gaussian leaves.
#include "amVoxelGrid.h"

#include <algorithm>
#include <cmath>

double amVoxel::NoiseLevel(const amVoxelGrid& g, const float* values, float floor)
{
  // Second differences of neighbours along the first axis (v[i-1] - 2 v[i] + v[i+1]): within a
  // tissue, and across the ramp a blurred edge makes, they are noise alone (six times its
  // variance); the few sharp edges left are outliers to the median.
  std::vector<float> d;
  d.reserve(g.Size() / 4);
  const std::size_t rows = g.Size() / g.N[0];
  for (std::size_t r = 0; r < rows; ++r)
  {
    const float* row = values + r * g.N[0];
    for (int i = 1; i + 1 < g.N[0]; ++i)
      if (row[i - 1] > floor && row[i] > floor && row[i + 1] > floor)
        d.push_back(std::fabs(row[i - 1] - 2.0f * row[i] + row[i + 1]));
  }
  if (d.empty())
    return 0.0;
  const auto mid = d.begin() + d.size() / 2;
  std::nth_element(d.begin(), mid, d.end());
  return 1.4826 * *mid / std::sqrt(6.0);
}

double amVoxel::GaussianNoiseFactor(const amVoxelGrid& g, double sigma)
{
  double factor = 1.0;
  for (int a = 0; a < 3; ++a)
  {
    const double s = sigma / g.Spacing[a];
    if (s < 0.1 || g.N[a] < 2)
      continue;
    // The same kernel as Gaussian(): the noise's variance falls by the sum of its squared weights.
    const int r = static_cast<int>(std::ceil(3.0 * s));
    double sum = 0.0, squares = 0.0;
    for (int t = -r; t <= r; ++t)
    {
      const double w = std::exp(-0.5 * t * t / (s * s));
      sum += w;
      squares += w * w;
    }
    factor *= std::sqrt(squares) / sum;
  }
  return factor;
}

double amVoxel::GaussianForNoise(const amVoxelGrid& g, double noise, double target)
{
  // The least sigma, in steps of a twentieth of the finest voxel, up to four voxels.
  const double finest = std::min({ g.Spacing[0], g.Spacing[1], g.Spacing[2] });
  double sigma = 0.1 * finest;
  while (noise * GaussianNoiseFactor(g, sigma) > target && sigma < 4.0 * finest)
    sigma += 0.05 * finest;
  return sigma;
}
