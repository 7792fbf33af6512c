// The basins of a depth map: a watershed by flooding with merges by dynamics.
#include "amVoxelGrid.h"

#include <algorithm>
#include <numeric>

namespace
{
std::uint32_t Root(std::vector<std::uint32_t>& parent, std::uint32_t v)
{
  while (parent[v] != v)
  {
    parent[v] = parent[parent[v]];
    v = parent[v];
  }
  return v;
}
}

int amVoxel::Basins(const amVoxelGrid& g, const amVoxelMask& mask, const std::vector<float>& depth, double dynamic,
  std::vector<int>& basin)
{
  // The flood works on the mask's voxels alone, numbered in index order (a mask is a small part
  // of the grid: its arrays stay small).
  const std::size_t n = g.Size();
  std::vector<std::int32_t> number(n, -1);
  std::vector<std::size_t> voxel;
  for (std::size_t v = 0; v < n; ++v)
    if (mask[v])
    {
      number[v] = static_cast<std::int32_t>(voxel.size());
      voxel.push_back(v);
    }
  const std::uint32_t m = static_cast<std::uint32_t>(voxel.size());
  std::vector<float> level(m);
  for (std::uint32_t q = 0; q < m; ++q)
    level[q] = depth[voxel[q]];
  // Deepest first; equal depths in index order, so the result does not depend on the sort.
  std::vector<std::uint32_t> order(m);
  std::iota(order.begin(), order.end(), 0u);
  std::stable_sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return level[a] > level[b]; });
  constexpr std::uint32_t none = static_cast<std::uint32_t>(-1);
  std::vector<std::uint32_t> parent(m, none);
  std::vector<float> peak(m, 0.0f);
  std::vector<std::uint32_t> roots;
  // Calls f(neighbour) for the face neighbours in the mask.
  const auto neighbours = [&](std::uint32_t q, auto&& f) {
    g.FaceNeighbours(voxel[q], [&](std::size_t w) {
      if (number[w] >= 0)
        f(static_cast<std::uint32_t>(number[w]));
    });
  };
  const auto flood = [&](std::uint32_t v) {
    roots.clear();
    neighbours(v, [&](std::uint32_t w) {
      if (parent[w] != none)
        roots.push_back(Root(parent, w));
    });
    std::sort(roots.begin(), roots.end());
    roots.erase(std::unique(roots.begin(), roots.end()), roots.end());
    parent[v] = v;
    peak[v] = level[v];
    if (roots.empty())
      return;
    // The flood that rose highest takes the voxel; a flood that rose less than the dynamic above
    // this level is a ripple of its neighbour's and merges into it. Two floods that each rose at
    // least the dynamic stay apart: the voxel is where they meet.
    std::uint32_t highest = roots[0];
    for (const std::uint32_t r : roots)
      if (peak[r] > peak[highest])
        highest = r;
    parent[v] = highest;
    for (const std::uint32_t r : roots)
      if (r != highest && peak[r] - level[v] < dynamic)
        parent[r] = highest;
  };
  // Level by level; within a level (a plateau, such as a tube's axis) the floods advance breadth
  // first from what is already flooded, so a plateau is shared by distance, then what no flood
  // reaches starts floods of its own.
  std::vector<char> waiting(m, 0);
  std::vector<std::uint32_t> queue;
  for (std::size_t first = 0; first < order.size();)
  {
    std::size_t last = first;
    while (last < order.size() && level[order[last]] == level[order[first]])
      waiting[order[last++]] = 1;
    queue.clear();
    for (std::size_t q = first; q < last; ++q)
    {
      bool reached = false;
      neighbours(order[q], [&](std::uint32_t w) { reached = reached || parent[w] != none; });
      if (reached)
      {
        queue.push_back(order[q]);
        waiting[order[q]] = 0;
      }
    }
    for (std::size_t q = first;; ++q)
    {
      for (std::size_t h = 0; h < queue.size(); ++h)
      {
        flood(queue[h]);
        neighbours(queue[h], [&](std::uint32_t w) {
          if (waiting[w])
          {
            waiting[w] = 0;
            queue.push_back(w);
          }
        });
      }
      queue.clear();
      while (q < last && !waiting[order[q]])
        ++q;
      if (q == last)
        break;
      waiting[order[q]] = 0;
      queue.push_back(order[q]);
    }
    first = last;
  }
  basin.assign(n, -1);
  std::vector<int> numberOfRoot(m, -1);
  int count = 0;
  for (std::uint32_t q = 0; q < m; ++q)
  {
    const std::uint32_t r = Root(parent, q);
    if (numberOfRoot[r] < 0)
      numberOfRoot[r] = count++;
    basin[voxel[q]] = numberOfRoot[r];
  }
  return count;
}
