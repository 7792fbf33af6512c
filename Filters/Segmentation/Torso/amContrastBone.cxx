// Contrast blood and bone overlap in intensity: the blood is what connects to the seeded pools, the
// bone's cortex is what is left of the bright voxels, and its marrow what the cortex reaches.
#include "amTorsoLabels.h"

#include <algorithm>
#include <deque>

amVoxelMask amTorso::ContrastVessels(const amVoxelGrid& g, const float* hu, float level, const amVoxelMask& pools)
{
  const std::size_t n = pools.size();
  amVoxelMask bright(n);
  for (std::size_t v = 0; v < n; ++v)
    bright[v] = pools[v] || hu[v] > level;
  const amVoxelMask opened = amVoxel::Open6(g, bright);
  std::vector<int> id;
  std::vector<std::size_t> sizes;
  const int count = amVoxel::Components(g, opened, id, sizes);
  std::vector<std::uint8_t> pooled(static_cast<std::size_t>(count), 0);
  for (std::size_t v = 0; v < n; ++v)
    if (pools[v] && id[v] >= 0)
      pooled[id[v]] = 1;
  amVoxelMask vessels(n);
  for (std::size_t v = 0; v < n; ++v)
    vessels[v] = id[v] >= 0 && pooled[id[v]];
  return vessels;
}

namespace
{
bool LungLike(std::uint8_t c)
{
  return c == amTorso::LungClass || c == amTorso::AirClass;
}

// The cortex's pieces bordered mostly by lung are contrast in the lungs' vessels, not bone.
void DropPiecesInLung(const amVoxelGrid& g, const std::vector<std::uint8_t>& classes, amVoxelMask& cortex)
{
  std::vector<int> id;
  std::vector<std::size_t> sizes;
  const int count = amVoxel::Components(g, cortex, id, sizes);
  std::vector<std::size_t> border(static_cast<std::size_t>(count), 0), lung(static_cast<std::size_t>(count), 0);
  for (std::size_t v = 0; v < cortex.size(); ++v)
    if (!cortex[v])
    {
      // Each border voxel counts once per piece it touches.
      int last[26], touched = 0;
      g.AllNeighbours(v, [&](std::size_t w) {
        const int c = id[w];
        if (c < 0 || std::find(last, last + touched, c) != last + touched)
          return;
        last[touched++] = c;
        ++border[c];
        lung[c] += LungLike(classes[v]);
      });
    }
  for (std::size_t v = 0; v < cortex.size(); ++v)
    if (id[v] >= 0 && 2 * lung[id[v]] >= border[id[v]])
      cortex[v] = 0;
}
}

amVoxelMask amTorso::ClippedBone(const amVoxelGrid& g, const std::vector<std::uint8_t>& classes,
  const amVoxelMask& exterior, const amVoxelMask& nearVessels, const TissueParameters& p)
{
  const std::size_t n = classes.size();
  amVoxelMask bone(n);
  for (std::size_t v = 0; v < n; ++v)
    bone[v] = p.HU[v] > p.CortexLevel && !exterior[v] && !nearVessels[v];
  DropPiecesInLung(g, classes, bone);
  // The marrow: voxels brighter than MarrowLevel reached from the cortex through such voxels,
  // within MarrowReach of it.
  const std::vector<float> reach = amVoxel::DistanceWithin(g, bone, p.MarrowReach);
  std::deque<std::size_t> front;
  for (std::size_t v = 0; v < n; ++v)
    if (bone[v])
      front.push_back(v);
  while (!front.empty())
  {
    const std::size_t v = front.front();
    front.pop_front();
    g.FaceNeighbours(v, [&](std::size_t w) {
      if (bone[w] || exterior[w] || nearVessels[w] || LungLike(classes[w]) || p.HU[w] <= p.MarrowLevel ||
        reach[w] > p.MarrowReach)
        return;
      bone[w] = 1;
      front.push_back(w);
    });
  }
  return bone;
}
