// The basins of a depth map: a watershed by flooding with merges by dynamics.
#include "amVoxelGrid.h"

#include <algorithm>
#include <numeric>

namespace
{
std::size_t Root(std::vector<std::size_t>& parent, std::size_t v)
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
  const std::size_t n = g.Size();
  std::vector<std::size_t> order;
  for (std::size_t v = 0; v < n; ++v)
    if (mask[v])
      order.push_back(v);
  // Deepest first; equal depths in index order, so the result does not depend on the sort.
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return depth[a] > depth[b]; });
  constexpr std::size_t none = static_cast<std::size_t>(-1);
  std::vector<std::size_t> parent(n, none);
  std::vector<float> peak(n, 0.0f);
  std::vector<std::size_t> roots;
  const auto flood = [&](std::size_t v) {
    roots.clear();
    g.FaceNeighbours(v, [&](std::size_t w) {
      if (parent[w] != none)
        roots.push_back(Root(parent, w));
    });
    std::sort(roots.begin(), roots.end());
    roots.erase(std::unique(roots.begin(), roots.end()), roots.end());
    parent[v] = v;
    peak[v] = depth[v];
    if (roots.empty())
      return;
    // The flood that rose highest takes the voxel; a flood that rose less than the dynamic above
    // this level is a ripple of its neighbour's and merges into it. Two floods that each rose at
    // least the dynamic stay apart: the voxel is where they meet.
    std::size_t highest = roots[0];
    for (const std::size_t r : roots)
      if (peak[r] > peak[highest])
        highest = r;
    parent[v] = highest;
    for (const std::size_t r : roots)
      if (r != highest && peak[r] - depth[v] < dynamic)
        parent[r] = highest;
  };
  // Level by level; within a level (a plateau, such as a tube's axis) the floods advance breadth
  // first from what is already flooded, so a plateau is shared by distance, then what no flood
  // reaches starts floods of its own.
  std::vector<char> waiting(n, 0);
  std::vector<std::size_t> queue;
  for (std::size_t first = 0; first < order.size();)
  {
    std::size_t last = first;
    while (last < order.size() && depth[order[last]] == depth[order[first]])
      waiting[order[last++]] = 1;
    queue.clear();
    for (std::size_t q = first; q < last; ++q)
    {
      bool reached = false;
      g.FaceNeighbours(order[q], [&](std::size_t w) { reached = reached || parent[w] != none; });
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
        g.FaceNeighbours(queue[h], [&](std::size_t w) {
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
  std::vector<int> number(n, -1);
  int count = 0;
  for (std::size_t v = 0; v < n; ++v)
    if (mask[v])
    {
      const std::size_t r = Root(parent, v);
      if (number[r] < 0)
        number[r] = count++;
      basin[v] = number[r];
    }
  return count;
}
