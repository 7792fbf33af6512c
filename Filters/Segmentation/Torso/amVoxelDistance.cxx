// Exact Euclidean distance transform (P. Felzenszwalb and D. Huttenlocher, Distance Transforms
// of Sampled Functions, 2012): the squared distance is a lower envelope of parabolas per axis.
#include "amVoxelGrid.h"

#include "vtkSMPTools.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace
{
// Lines across the first axis transformed together (a cache line of floats).
constexpr int Tile = 16;

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

namespace
{
// The distance of every voxel to the nearest voxel of the mask (inverted: outside it).
std::vector<float> Transform(const amVoxelGrid& g, const amVoxelMask& mask, bool inverted)
{
  // Squared distances are kept in single precision between the axes (a voxel's are sums of
  // squared multiples of the spacing: whole numbers at whole-millimetre voxels, exact in float),
  // and the map becomes the distances in place.
  const float inf = std::numeric_limits<float>::infinity();
  const vtkIdType count = static_cast<vtkIdType>(mask.size());
  std::vector<float> sq(mask.size());
  vtkSMPTools::For(0, count, [&](vtkIdType i0, vtkIdType i1) {
    for (vtkIdType i = i0; i < i1; ++i)
      sq[i] = (mask[i] != 0) != inverted ? 0.0f : inf;
  });
  const std::size_t stride[3] = { 1, static_cast<std::size_t>(g.N[0]), static_cast<std::size_t>(g.N[0]) * g.N[1] };
  for (int a = 0; a < 3; ++a)
  {
    // The lines along axis a are independent: on the threads, each with its own buffers. Across
    // the first axis, the lines go in tiles of neighbours along it, read and written together:
    // each cache line read is then used whole.
    const int n = g.N[a];
    const int b = a == 0 ? 1 : 0, c = a == 2 ? 1 : 2;
    const int width = a == 0 ? 1 : Tile;
    const vtkIdType tilesPerRow = (g.N[b] + width - 1) / width;
    vtkSMPTools::For(0, tilesPerRow * g.N[c], [&](vtkIdType t0, vtkIdType t1) {
      std::vector<std::vector<double>> f(width, std::vector<double>(n));
      std::vector<double> d, z;
      std::vector<int> v;
      for (vtkIdType tile = t0; tile < t1; ++tile)
      {
        const int first = static_cast<int>(tile % tilesPerRow) * width;
        const int lines = std::min(width, g.N[b] - first);
        const std::size_t start = first * stride[b] + (tile / tilesPerRow) * stride[c];
        for (int t = 0; t < n; ++t)
        {
          const float* from = sq.data() + start + t * stride[a];
          for (int l = 0; l < lines; ++l)
            f[l][t] = from[l * stride[b]];
        }
        for (int l = 0; l < lines; ++l)
        {
          Envelope(f[l], d, g.Spacing[a], v, z);
          f[l].swap(d);
          d.resize(n);
        }
        for (int t = 0; t < n; ++t)
        {
          float* to = sq.data() + start + t * stride[a];
          for (int l = 0; l < lines; ++l)
            to[l * stride[b]] = static_cast<float>(f[l][t]);
        }
      }
    });
  }
  vtkSMPTools::For(0, count, [&](vtkIdType i0, vtkIdType i1) {
    for (vtkIdType i = i0; i < i1; ++i)
      sq[i] = sq[i] == inf ? std::numeric_limits<float>::max() : std::sqrt(sq[i]);
  });
  return sq;
}
}

std::vector<float> amVoxel::Distance(const amVoxelGrid& g, const amVoxelMask& mask)
{
  return Transform(g, mask, false);
}

namespace
{
// The box of the mask's voxels grown by margin voxels on every side, inside the grid; false when
// the mask is empty.
bool GrownBox(const amVoxelGrid& g, const amVoxelMask& mask, const int margin[3], int lo[3], int hi[3])
{
  for (int a = 0; a < 3; ++a)
  {
    lo[a] = g.N[a];
    hi[a] = -1;
  }
  for (int k = 0; k < g.N[2]; ++k)
    for (int j = 0; j < g.N[1]; ++j)
    {
      const std::uint8_t* row = mask.data() + g.Index(0, j, k);
      int first = -1, last = -1;
      for (int i = 0; i < g.N[0]; ++i)
        if (row[i])
        {
          first = first < 0 ? i : first;
          last = i;
        }
      if (first < 0)
        continue;
      lo[0] = std::min(lo[0], first);
      hi[0] = std::max(hi[0], last);
      lo[1] = std::min(lo[1], j);
      hi[1] = std::max(hi[1], j);
      lo[2] = std::min(lo[2], k);
      hi[2] = std::max(hi[2], k);
    }
  if (hi[0] < 0)
    return false;
  for (int a = 0; a < 3; ++a)
  {
    lo[a] = std::max(0, lo[a] - margin[a]);
    hi[a] = std::min(g.N[a] - 1, hi[a] + margin[a]);
  }
  return true;
}

// The distance transform of a mask (inside: inverted) over a box of the grid, written into the
// grid's map; the rest of the map keeps its value.
void DistanceInBox(const amVoxelGrid& g, const amVoxelMask& mask, bool inverted, const int lo[3], const int hi[3],
  std::vector<float>& out)
{
  amVoxelGrid box;
  for (int a = 0; a < 3; ++a)
  {
    box.N[a] = hi[a] - lo[a] + 1;
    box.Spacing[a] = g.Spacing[a];
  }
  if (box.Size() == g.Size())
  {
    out = Transform(g, mask, inverted);
    return;
  }
  amVoxelMask part(box.Size());
  for (int k = 0; k < box.N[2]; ++k)
    for (int j = 0; j < box.N[1]; ++j)
      for (int i = 0; i < box.N[0]; ++i)
        part[box.Index(i, j, k)] = mask[g.Index(i + lo[0], j + lo[1], k + lo[2])];
  const std::vector<float> d = Transform(box, part, inverted);
  for (int k = 0; k < box.N[2]; ++k)
    for (int j = 0; j < box.N[1]; ++j)
      std::copy_n(d.data() + box.Index(0, j, k), box.N[0], out.data() + g.Index(lo[0], j + lo[1], k + lo[2]));
}
}

std::vector<float> amVoxel::DistanceWithin(const amVoxelGrid& g, const amVoxelMask& mask, double reach)
{
  // A voxel outside the mask's box grown by more than reach lies farther than reach from it along
  // one axis at least; inside, the mask's voxels are all there, so the transform is exact.
  std::vector<float> out(mask.size(), std::numeric_limits<float>::max());
  int margin[3], lo[3], hi[3];
  for (int a = 0; a < 3; ++a)
    margin[a] = static_cast<int>(std::ceil(reach / g.Spacing[a])) + 1;
  if (GrownBox(g, mask, margin, lo, hi))
    DistanceInBox(g, mask, false, lo, hi, out);
  return out;
}

std::vector<float> amVoxel::Depth(const amVoxelGrid& g, const amVoxelMask& region)
{
  // The region's box grown by a voxel holds, on each side, a face of voxels outside the region no
  // farther than anything beyond it: the transform over the box is the one over the grid.
  std::vector<float> out(region.size(), 0.0f);
  const int margin[3] = { 1, 1, 1 };
  int lo[3], hi[3];
  if (GrownBox(g, region, margin, lo, hi))
    DistanceInBox(g, region, true, lo, hi, out);
  return out;
}
