// The ascending aorta where the atria's label took it: the aorta's cross-sections followed down
// slice by slice while each stays the size of the tube above it.
#include "amTorsoLabels.h"

#include <algorithm>
#include <cmath>

namespace
{
/// A slice across the superior axis: its two in-plane axes and the voxel id of (u, v) in slice s.
struct Slice
{
  const amVoxelGrid& G;
  int Axis, U, V;
  Slice(const amVoxelGrid& g, int axis)
    : G(g)
    , Axis(axis)
    , U(axis == 0 ? 1 : 0)
    , V(axis == 2 ? 1 : 2)
  {
  }
  int Width() const { return this->G.N[this->U]; }
  int Height() const { return this->G.N[this->V]; }
  std::size_t Id(int s, int u, int v) const
  {
    int c[3];
    c[this->Axis] = s;
    c[this->U] = u;
    c[this->V] = v;
    return this->G.Index(c[0], c[1], c[2]);
  }
};

/// The 4-connected pieces of 'in' (width x height, row by row): their number, each pixel's piece
/// (-1 outside) in 'piece'.
int Pieces(const std::vector<char>& in, int width, int height, std::vector<int>& piece)
{
  piece.assign(in.size(), -1);
  int count = 0;
  std::vector<int> stack;
  for (int start = 0; start < static_cast<int>(in.size()); ++start)
  {
    if (!in[start] || piece[start] >= 0)
      continue;
    piece[start] = count;
    stack.assign(1, start);
    while (!stack.empty())
    {
      const int p = stack.back();
      stack.pop_back();
      const int u = p % width, v = p / width;
      const int next[4][2] = { { u - 1, v }, { u + 1, v }, { u, v - 1 }, { u, v + 1 } };
      for (const auto& q : next)
      {
        if (q[0] < 0 || q[0] >= width || q[1] < 0 || q[1] >= height)
          continue;
        const int w = q[1] * width + q[0];
        if (in[w] && piece[w] < 0)
        {
          piece[w] = count;
          stack.push_back(w);
        }
      }
    }
    ++count;
  }
  return count;
}
}

std::size_t amTorso::AortaOutOfAtria(const amVoxelGrid& g, int superiorAxis, int superiorSign,
  const AscendingAortaParameters& p, std::vector<std::uint8_t>& labels)
{
  if (superiorAxis < 0 || superiorAxis > 2)
    return 0;
  const Slice slice(g, superiorAxis);
  const int w = slice.Width(), h = slice.Height(), slices = g.N[superiorAxis];
  const double su = g.Spacing[slice.U], sv = g.Spacing[slice.V], pixel = su * sv;
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
  std::vector<char> in(static_cast<std::size_t>(w) * h);
  for (int s = 0; s < slices; ++s)
  {
    if (s + down < 0 || s + down >= slices || !atria[s + down])
      continue;
    for (int v = 0; v < h; ++v)
      for (int u = 0; u < w; ++u)
        in[v * w + u] = given[slice.Id(s, u, v)] == Phantom::Aorta;
    std::vector<int> sections;
    const int count = Pieces(in, w, h, sections);
    for (int c = 0; c < count; ++c)
    {
      std::vector<char> current(in.size());
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
        double cu = 0, cv = 0, n = 0;
        bool seeded = false;
        for (int q = 0; q < static_cast<int>(in.size()); ++q)
          if (current[q])
          {
            cu += q % w;
            cv += q / w;
            ++n;
            seeded = seeded || labels[slice.Id(t, q % w, q / w)] == Atria;
          }
        if (!seeded)
          break;
        cu /= n;
        cv /= n;
        std::vector<char> candidate(in.size());
        for (int v = 0; v < h; ++v)
          for (int u = 0; u < w; ++u)
          {
            const std::uint8_t l = labels[slice.Id(t, u, v)];
            candidate[v * w + u] =
              (l == Atria || l == Phantom::Aorta) && std::hypot((u - cu) * su, (v - cv) * sv) <= radius;
          }
        std::vector<int> candidates;
        const int k = Pieces(candidate, w, h, candidates);
        std::vector<char> touched(static_cast<std::size_t>(k), 0);
        for (std::size_t q = 0; q < in.size(); ++q)
          if (current[q] && candidates[q] >= 0 && labels[slice.Id(t, q % w, q / w)] == Atria)
            touched[candidates[q]] = 1;
        std::vector<char> next(in.size());
        std::size_t area = 0;
        for (std::size_t q = 0; q < in.size(); ++q)
          area += (next[q] = candidates[q] >= 0 && touched[candidates[q]]);
        if (area < p.SmallestArea * reference || area > p.LargestArea * reference)
          break; // the tube ends (its section shrinks into a contact) or opens into a chamber
        for (std::size_t q = 0; q < in.size(); ++q)
        {
          std::uint8_t& l = labels[slice.Id(t, static_cast<int>(q % w), static_cast<int>(q / w))];
          if (next[q] && l == Atria)
          {
            l = Phantom::Aorta;
            ++moved;
          }
        }
        current.swap(next);
      }
    }
  }
  return moved;
}
