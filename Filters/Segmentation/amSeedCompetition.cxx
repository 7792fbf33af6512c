#include "amSeedCompetition.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <queue>
#include <tuple>

namespace
{
using Organ = amSeedCompetition::Organ;

// The organ's claim on the voxel (i, j, k) of the whole grid.
bool Claims(const Organ& o, int i, int j, int k)
{
  const int a = i - o.Lo[0], b = j - o.Lo[1], c = k - o.Lo[2];
  if (a < 0 || b < 0 || c < 0 || a >= o.Size[0] || b >= o.Size[1] || c >= o.Size[2])
    return false;
  return (*o.Inside)[(static_cast<std::size_t>(c) * o.Size[1] + b) * o.Size[0] + a] != 0;
}

// The box that holds every organ's region: lo and size.
void BoxOfAll(const std::vector<Organ>& organs, int lo[3], int size[3])
{
  for (int a = 0; a < 3; ++a)
  {
    int hi = 0;
    lo[a] = organs.front().Lo[a];
    for (const Organ& o : organs)
    {
      lo[a] = std::min(lo[a], o.Lo[a]);
      hi = std::max(hi, o.Lo[a] + o.Size[a]);
    }
    size[a] = hi - lo[a];
  }
}

// What a step into the voxel costs the organ's front per mm: 1 in the middle of its interval,
// 1 + BoundaryCost at its edges (and beyond).
double StepWeight(const Organ& o, const float* intensity, std::size_t q)
{
  if (!intensity || o.Upper <= o.Lower)
    return 1.0;
  const double half = 0.5 * (o.Upper - o.Lower);
  const double m = std::min(1.0, std::abs(intensity[q] - 0.5 * (o.Upper + o.Lower)) / half);
  const double m2 = m * m;
  return 1.0 + amSeedCompetition::BoundaryCost * m2 * m2;
}
}

std::vector<std::size_t> amSeedCompetition::Paste(const std::vector<Organ>& organs, const int dims[3],
  const double spacing[3], bool compete, unsigned char* out, const float* intensity)
{
  std::vector<std::size_t> voxels(organs.size(), 0);
  if (organs.empty())
    return voxels;
  int lo[3], size[3];
  BoxOfAll(organs, lo, size);
  const std::size_t n = static_cast<std::size_t>(size[0]) * size[1] * size[2];
  const auto gridId = [&](std::size_t q) {
    const int i = static_cast<int>(q % size[0]) + lo[0];
    const int j = static_cast<int>((q / size[0]) % size[1]) + lo[1];
    const int k = static_cast<int>(q / (static_cast<std::size_t>(size[0]) * size[1])) + lo[2];
    return (static_cast<std::size_t>(k) * dims[1] + j) * dims[0] + i;
  };
  // Who claims each voxel of the box: the earliest claimant, and whether another one does too (an
  // organ's index fits a byte: labels are 1..255, one organ each).
  constexpr std::uint8_t none = 255;
  std::vector<std::uint8_t> owner(n, none);
  std::vector<bool> shared(n, false);
  bool anyShared = false;
  for (std::size_t li = 0; li < organs.size(); ++li)
  {
    const Organ& o = organs[li];
    for (int c = 0; c < o.Size[2]; ++c)
      for (int b = 0; b < o.Size[1]; ++b)
        for (int a = 0; a < o.Size[0]; ++a)
          if ((*o.Inside)[(static_cast<std::size_t>(c) * o.Size[1] + b) * o.Size[0] + a])
          {
            const std::size_t q =
              (static_cast<std::size_t>(c + o.Lo[2] - lo[2]) * size[1] + (b + o.Lo[1] - lo[1])) * size[0] +
              (a + o.Lo[0] - lo[0]);
            if (owner[q] == none)
              owner[q] = static_cast<std::uint8_t>(li);
            else
              anyShared = shared[q] = true;
          }
  }
  if (compete && anyShared)
  {
    // The fronts: (path length, organ, voxel), the least first; the organ and the voxel order
    // ties, so the result depends on neither the thread count nor the visiting order.
    using Front = std::tuple<double, std::uint8_t, std::size_t>;
    std::priority_queue<Front, std::vector<Front>, std::greater<Front>> fronts;
    std::vector<std::uint8_t> reached(n, none);
    for (std::size_t li = 0; li < organs.size(); ++li)
      for (const auto& s : organs[li].Seeds)
        if (Claims(organs[li], s[0], s[1], s[2]))
          fronts.emplace(0.0, static_cast<std::uint8_t>(li),
            (static_cast<std::size_t>(s[2] - lo[2]) * size[1] + (s[1] - lo[1])) * size[0] + (s[0] - lo[0]));
    const std::size_t stride[3] = { 1, static_cast<std::size_t>(size[0]), static_cast<std::size_t>(size[0]) * size[1] };
    while (!fronts.empty())
    {
      const auto [d, li, q] = fronts.top();
      fronts.pop();
      if (reached[q] != none)
        continue;
      reached[q] = li;
      const int ijk[3] = { static_cast<int>(q % size[0]), static_cast<int>((q / size[0]) % size[1]),
        static_cast<int>(q / stride[2]) };
      for (int a = 0; a < 3; ++a)
        for (int step = -1; step <= 1; step += 2)
        {
          int next[3] = { ijk[0], ijk[1], ijk[2] };
          next[a] += step;
          if (next[a] < 0 || next[a] >= size[a])
            continue;
          const std::size_t w = step < 0 ? q - stride[a] : q + stride[a];
          if (reached[w] == none && Claims(organs[li], next[0] + lo[0], next[1] + lo[1], next[2] + lo[2]))
            fronts.emplace(d + spacing[a] * StepWeight(organs[li], intensity, w), li, w);
        }
    }
    // An organ is what its front reaches: a voxel of its region cut off from its seeds by the
    // other fronts (a speck of partial volume behind a septum the other organ took) is nobody's.
    for (std::size_t q = 0; q < n; ++q)
      owner[q] = reached[q];
  }
  for (std::size_t q = 0; q < n; ++q)
    if (owner[q] != none)
    {
      const std::size_t id = gridId(q);
      if (out[id] == 0)
      {
        out[id] = static_cast<unsigned char>(organs[owner[q]].Label);
        ++voxels[owner[q]];
      }
    }
  return voxels;
}
