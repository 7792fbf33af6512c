// Dropped voxels go to the most frequent label around them, front by front.
#include "amVoxelGrid.h"

#include <array>

namespace
{
// One front: each pending voxel with a non-pending neighbour it may take is decided.
void DecideFront(const amVoxelGrid& g, const std::vector<std::uint8_t>& labels, const std::vector<std::size_t>& pending,
  const std::function<bool(std::size_t, std::uint8_t)>& refuses,
  std::vector<std::pair<std::size_t, std::uint8_t>>& decided, std::vector<std::size_t>& rest)
{
  decided.clear();
  rest.clear();
  for (const std::size_t v : pending)
  {
    std::array<int, 256> votes{};
    int best = -1;
    g.AllNeighbours(v, [&](std::size_t w) {
      const std::uint8_t l = labels[w];
      if (l == amVoxel::Pending || (refuses && refuses(v, l)))
        return;
      ++votes[l];
      // The most votes; on a tie the smaller label, so the result is order-free.
      if (best < 0 || votes[l] > votes[best] || (votes[l] == votes[best] && l < best))
        best = l;
    });
    if (best >= 0)
      decided.emplace_back(v, static_cast<std::uint8_t>(best));
    else
      rest.push_back(v);
  }
}
}

std::size_t amVoxel::HandOver(const amVoxelGrid& g, std::vector<std::uint8_t>& labels,
  const std::function<bool(std::size_t, std::uint8_t)>& refuses)
{
  std::vector<std::size_t> pending;
  for (std::size_t v = 0; v < labels.size(); ++v)
    if (labels[v] == amVoxel::Pending)
      pending.push_back(v);
  const std::size_t total = pending.size();
  std::vector<std::pair<std::size_t, std::uint8_t>> decided;
  std::vector<std::size_t> rest;
  while (!pending.empty())
  {
    DecideFront(g, labels, pending, refuses, decided, rest);
    // Voxels that only refused labels reach take them.
    if (decided.empty() && refuses)
      DecideFront(g, labels, pending, nullptr, decided, rest);
    if (decided.empty())
    {
      // A grid of nothing but pending voxels: they become background.
      for (const std::size_t v : rest)
        labels[v] = 0;
      break;
    }
    for (const auto& d : decided)
      labels[d.first] = d.second;
    pending.swap(rest);
  }
  return total;
}
