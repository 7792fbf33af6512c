#include "amSyntheticAtlas.h"

#include "vtkSMPTools.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace
{
/// A counter-based hash (splitmix64) of a seed and an index: uniform 64-bit values.
uint64_t Hash(uint64_t seed, uint64_t index)
{
  uint64_t z = seed * 0x9e3779b97f4a7c15ULL + index + 0x632be59bd9b4e019ULL;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

double Uniform(uint64_t seed, uint64_t index)
{
  return static_cast<double>(Hash(seed, index) >> 11) * (1.0 / 9007199254740992.0);
}
}

std::vector<std::array<double, 3>> amSyntheticAtlas::Seeds() const
{
  double half[3], centre[3];
  for (int d = 0; d < 3; ++d)
  {
    const double extent = (this->Dimensions[d] - 1) * this->Spacing[d];
    centre[d] = 0.5 * extent;
    half[d] = 0.45 * extent;
  }
  std::vector<std::array<double, 3>> seeds;
  for (uint64_t k = 0; seeds.size() < static_cast<size_t>(this->NumberOfLabels); ++k)
  {
    double u[3], r2 = 0;
    for (int d = 0; d < 3; ++d)
    {
      u[d] = 2.0 * Uniform(this->Seed, 3 * k + d) - 1.0;
      r2 += u[d] * u[d];
    }
    if (r2 > 1.0)
      continue; // rejection: uniform in the unit ball
    seeds.push_back({ centre[0] + half[0] * u[0], centre[1] + half[1] * u[1], centre[2] + half[2] * u[2] });
  }
  return seeds;
}

std::vector<int32_t> amSyntheticAtlas::Generate() const
{
  const int* n = this->Dimensions;
  const double* s = this->Spacing;
  const std::vector<std::array<double, 3>> seeds = this->Seeds();
  double half[3], centre[3], lo[3], hi[3];
  for (int d = 0; d < 3; ++d)
  {
    const double extent = (n[d] - 1) * s[d];
    centre[d] = 0.5 * extent;
    half[d] = 0.45 * extent;
    lo[d] = 0;
    hi[d] = extent;
  }
  // Seeds binned in cubes of about one cell's size: the nearest two are found in a few rings.
  const double volume = 4.0 / 3.0 * M_PI * half[0] * half[1] * half[2];
  const double cell = std::max(1e-9, std::cbrt(volume / std::max<size_t>(1, seeds.size())));
  int nb[3];
  for (int d = 0; d < 3; ++d)
    nb[d] = std::max(1, static_cast<int>(std::ceil((hi[d] - lo[d]) / cell)));
  std::vector<std::vector<int>> bins(static_cast<size_t>(nb[0]) * nb[1] * nb[2]);
  auto binOf = [&](const double x[3], int b[3]) {
    for (int d = 0; d < 3; ++d)
      b[d] = std::min(nb[d] - 1, std::max(0, static_cast<int>((x[d] - lo[d]) / cell)));
  };
  for (size_t k = 0; k < seeds.size(); ++k)
  {
    int b[3];
    binOf(seeds[k].data(), b);
    bins[(static_cast<size_t>(b[2]) * nb[1] + b[1]) * nb[0] + b[0]].push_back(static_cast<int>(k));
  }
  const int membrane = this->NumberOfLabels + 1;
  const size_t total = static_cast<size_t>(n[0]) * n[1] * n[2];
  std::vector<int32_t> labels(total, 0);
  vtkSMPTools::For(0, n[2], [&](vtkIdType k0, vtkIdType k1) {
    for (vtkIdType k = k0; k < k1; ++k)
      for (int j = 0; j < n[1]; ++j)
        for (int i = 0; i < n[0]; ++i)
        {
          const double x[3] = { i * s[0], j * s[1], k * s[2] };
          double e = 0;
          for (int d = 0; d < 3; ++d)
            e += (x[d] - centre[d]) * (x[d] - centre[d]) / (half[d] * half[d]);
          if (e > 1.0 || seeds.empty())
            continue;
          int b[3];
          binOf(x, b);
          double d1 = std::numeric_limits<double>::infinity(), d2 = d1;
          int best = -1;
          for (int r = 0;; ++r)
          {
            for (int bz = b[2] - r; bz <= b[2] + r; ++bz)
              for (int by = b[1] - r; by <= b[1] + r; ++by)
                for (int bx = b[0] - r; bx <= b[0] + r; ++bx)
                {
                  if (std::max({ std::abs(bx - b[0]), std::abs(by - b[1]), std::abs(bz - b[2]) }) != r || bx < 0 ||
                    by < 0 || bz < 0 || bx >= nb[0] || by >= nb[1] || bz >= nb[2])
                    continue;
                  for (int q : bins[(static_cast<size_t>(bz) * nb[1] + by) * nb[0] + bx])
                  {
                    double dist = 0;
                    for (int d = 0; d < 3; ++d)
                      dist += (x[d] - seeds[q][d]) * (x[d] - seeds[q][d]);
                    dist = std::sqrt(dist);
                    if (dist < d1 || (dist == d1 && q < best))
                    {
                      d2 = d1;
                      d1 = dist;
                      best = q;
                    }
                    else if (dist < d2)
                      d2 = dist;
                  }
                }
            // Every seed not yet seen lies at least r cells away from x.
            if (d2 <= r * cell || r > nb[0] + nb[1] + nb[2])
              break;
          }
          const bool sheet = this->SheetWidth > 0 && d2 - d1 < this->SheetWidth;
          labels[(static_cast<size_t>(k) * n[1] + j) * n[0] + i] = sheet ? membrane : best + 1;
        }
  });
  if (this->NoiseFraction > 0)
  {
    // Each voxel may take a face neighbour's label (read from the clean map: no chains).
    const std::vector<int32_t> clean = labels;
    const int64_t step[6] = { 1, -1, n[0], -n[0], static_cast<int64_t>(n[0]) * n[1],
      -static_cast<int64_t>(n[0]) * n[1] };
    vtkSMPTools::For(0, n[2], [&](vtkIdType k0, vtkIdType k1) {
      for (vtkIdType k = k0; k < k1; ++k)
        for (int j = 0; j < n[1]; ++j)
          for (int i = 0; i < n[0]; ++i)
          {
            const size_t v = (static_cast<size_t>(k) * n[1] + j) * n[0] + i;
            const uint64_t h = Hash(this->Seed ^ 0x5bd1e995u, v);
            if (static_cast<double>(h >> 11) * (1.0 / 9007199254740992.0) >= this->NoiseFraction)
              continue;
            const int f = static_cast<int>(Hash(this->Seed, v ^ 0xabcdef1234567ULL) % 6);
            const int c[3] = { i, j, static_cast<int>(k) };
            const int axis = f / 2, sign = f % 2 ? -1 : 1;
            if (c[axis] + sign < 0 || c[axis] + sign >= n[axis])
              continue;
            labels[v] = clean[static_cast<size_t>(static_cast<int64_t>(v) + step[f])];
          }
    });
  }
  return labels;
}
