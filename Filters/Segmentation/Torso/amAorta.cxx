// The aorta where no click gives it: the contrast-filled tube that runs down in front of the spine.
#include "amTorsoLabels.h"

#include <cmath>

namespace
{
double World(const double row[4], const int c[3])
{
  return row[0] * c[0] + row[1] * c[1] + row[2] * c[2] + row[3];
}
}

amVoxelMask amTorso::AortaFromContrast(const amVoxelGrid& g, const amVoxelMask& contrast,
  const std::vector<std::uint8_t>& labels, const double world[3][4], int superiorAxis, const AortaParameters& p,
  AortaReport& report)
{
  const std::size_t n = labels.size();
  amVoxelMask aorta(n, 0);
  report = AortaReport();
  if (superiorAxis < 0 || superiorAxis > 2)
    return aorta;
  // The column's centre in each slice: the mean world x, y of its spine voxels.
  const int slices = g.N[superiorAxis];
  std::vector<double> sx(slices, 0.0), sy(slices, 0.0), count(slices, 0.0);
  for (std::size_t v = 0; v < n; ++v)
    if (labels[v] == Phantom::Spine)
    {
      int c[3];
      g.Ijk(v, c);
      sx[c[superiorAxis]] += World(world[0], c);
      sy[c[superiorAxis]] += World(world[1], c);
      ++count[c[superiorAxis]];
    }
  for (int s = 0; s < slices; ++s)
    if (count[s] > 0)
    {
      sx[s] /= count[s];
      sy[s] /= count[s];
    }
  // The contrast's pieces, opened by a ball: contacts thinner than its diameter cut (the pulmonary
  // artery under the arch, a vein beside the aorta, partial volume at a chamber's wall).
  const std::vector<float> depth = amVoxel::Depth(g, contrast);
  amVoxelMask core(n);
  for (std::size_t v = 0; v < n; ++v)
    core[v] = depth[v] > p.Opening;
  const std::vector<float> fromCore = amVoxel::DistanceWithin(g, core, p.Opening);
  amVoxelMask opened(n);
  for (std::size_t v = 0; v < n; ++v)
    opened[v] = contrast[v] && fromCore[v] <= p.Opening;
  std::vector<int> id;
  std::vector<std::size_t> sizes;
  const int pieces = amVoxel::Components(g, opened, id, sizes);
  // Each piece's voxels in front of the column, within Reach of its centre, and the slices they
  // span: the descending aorta runs beside the vertebral bodies the whole length of the chest.
  std::vector<std::size_t> near(pieces, 0);
  std::vector<std::vector<char>> along(pieces);
  for (std::size_t v = 0; v < n; ++v)
  {
    if (id[v] < 0)
      continue;
    int c[3];
    g.Ijk(v, c);
    const int s = c[superiorAxis];
    if (count[s] == 0)
      continue;
    const double dx = World(world[0], c) - sx[s], dy = World(world[1], c) - sy[s];
    if (dy >= 0.0 || std::hypot(dx, dy) > p.Reach)
      continue; // behind the column's centre (LPS: y grows to the back), or too far from it
    ++near[id[v]];
    if (along[id[v]].empty())
      along[id[v]].assign(slices, 0);
    along[id[v]][s] = 1;
  }
  int best = -1;
  for (int c = 0; c < pieces; ++c)
    if (near[c] > 0 && (best < 0 || near[c] > near[best]))
      best = c;
  if (best < 0)
    return aorta;
  std::size_t spanned = 0;
  for (const char a : along[best])
    spanned += a != 0;
  report.Length = spanned * g.Spacing[superiorAxis];
  report.Volume = sizes[best] * g.VoxelVolume();
  if (report.Length < p.MinimumLength || report.Volume < p.MinimumVolume)
    return aorta;
  report.Found = true;
  // The piece, with the contrast voxels beside it that the opening took (its wall's corners).
  for (std::size_t v = 0; v < n; ++v)
    if (id[v] == best)
    {
      aorta[v] = 1;
      g.FaceNeighbours(v, [&](std::size_t w) {
        if (contrast[w] && id[w] < 0)
          aorta[w] = 1;
      });
    }
  return aorta;
}
