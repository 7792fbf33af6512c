// The ascending aorta where the atria's label took it: the aorta's cross-sections followed down
// slice by slice while each stays the size of the tube above it.
#include "amTorsoLabels.h"

#include <algorithm>
#include <cmath>

namespace
{
/// One step of a track: the section under 'current' (the pixels of the section above) in the slice
/// whose voxels are 'below': the atria's and aorta's pixels within 'radius' (mm) of current's centre
/// in the pieces that hold an atria pixel under current. Into next; returns its area (0: no atria
/// under current, the track ends).
std::size_t SectionBelow(const std::vector<char>& current, const std::vector<std::size_t>& below,
  const std::vector<std::uint8_t>& labels, int width, const double spacing[2], double radius, std::vector<char>& next)
{
  double cu = 0, cv = 0, n = 0;
  bool seeded = false;
  for (std::size_t q = 0; q < current.size(); ++q)
    if (current[q])
    {
      cu += static_cast<double>(q % width);
      cv += static_cast<double>(q / width);
      ++n;
      seeded = seeded || labels[below[q]] == amTorso::Atria;
    }
  if (!seeded)
    return 0;
  cu /= n;
  cv /= n;
  std::vector<char> candidate(current.size());
  for (std::size_t q = 0; q < current.size(); ++q)
  {
    const std::uint8_t l = labels[below[q]];
    candidate[q] = (l == amTorso::Atria || l == amTorso::Phantom::Aorta) &&
      std::hypot((static_cast<double>(q % width) - cu) * spacing[0],
        (static_cast<double>(q / width) - cv) * spacing[1]) <= radius;
  }
  std::vector<int> piece;
  std::vector<char> touched(static_cast<std::size_t>(amVoxel::SlicePieces(candidate, width, piece)), 0);
  for (std::size_t q = 0; q < current.size(); ++q)
    if (current[q] && piece[q] >= 0 && labels[below[q]] == amTorso::Atria)
      touched[piece[q]] = 1;
  next.assign(current.size(), 0);
  std::size_t area = 0;
  for (std::size_t q = 0; q < current.size(); ++q)
    area += (next[q] = piece[q] >= 0 && touched[piece[q]]);
  return area;
}
}

std::size_t amTorso::AortaOutOfAtria(const amVoxelGrid& g, int superiorAxis, int superiorSign,
  const AscendingAortaParameters& p, std::vector<std::uint8_t>& labels)
{
  if (superiorAxis < 0 || superiorAxis > 2)
    return 0;
  const int slices = g.N[superiorAxis], width = g.N[(superiorAxis + 1) % 3];
  const double spacing[2] = { g.Spacing[(superiorAxis + 1) % 3], g.Spacing[(superiorAxis + 2) % 3] };
  const double pixel = spacing[0] * spacing[1];
  const int down = superiorSign > 0 ? -1 : 1;
  // A track starts only above a slice that holds atria: most slices (all of them without atria)
  // are passed over at once.
  std::vector<char> atria(static_cast<std::size_t>(slices), 0);
  for (std::size_t v = 0; v < labels.size(); ++v)
    if (labels[v] == Atria)
    {
      int c[3];
      g.Ijk(v, c);
      atria[c[superiorAxis]] = 1;
    }
  if (std::find(atria.begin(), atria.end(), 1) == atria.end())
    return 0;
  // The aorta's cross-sections as the organ map gives them: a track starts only from these.
  const std::vector<std::uint8_t> given = labels;
  std::size_t moved = 0;
  std::vector<std::size_t> above, below;
  std::vector<char> in, current, next;
  std::vector<int> sections;
  for (int s = 0; s < slices; ++s)
  {
    if (s + down < 0 || s + down >= slices || !atria[s + down])
      continue;
    amVoxel::SliceVoxels(g, superiorAxis, s, above);
    in.resize(above.size());
    for (std::size_t q = 0; q < above.size(); ++q)
      in[q] = given[above[q]] == Phantom::Aorta;
    const int count = amVoxel::SlicePieces(in, width, sections);
    for (int c = 0; c < count; ++c)
    {
      current.assign(in.size(), 0);
      std::size_t reference = 0;
      for (std::size_t q = 0; q < in.size(); ++q)
        reference += (current[q] = sections[q] == c);
      if (reference * pixel < M_PI * 0.25 * p.MinimumDiameter * p.MinimumDiameter)
        continue;
      // The disk the next section must lie in: the tube's radius, with a margin, about the centre
      // of the section above it.
      const double radius = p.Margin * std::sqrt(reference * pixel / M_PI);
      for (int t = s + down; t >= 0 && t < slices; t += down)
      {
        amVoxel::SliceVoxels(g, superiorAxis, t, below);
        const std::size_t area = SectionBelow(current, below, labels, width, spacing, radius, next);
        if (area == 0 || area < p.SmallestArea * reference || area > p.LargestArea * reference)
          break; // the tube ends (its section shrinks into a contact) or opens into a chamber
        for (std::size_t q = 0; q < next.size(); ++q)
          if (next[q] && labels[below[q]] == Atria)
          {
            labels[below[q]] = Phantom::Aorta;
            ++moved;
          }
        current.swap(next);
      }
    }
  }
  return moved;
}
