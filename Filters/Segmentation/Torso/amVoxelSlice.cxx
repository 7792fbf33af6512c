// A slice of the grid: its voxels, pixel by pixel, and the 4-connected pieces of a mask on it.
#include "amVoxelGrid.h"

void amVoxel::SliceVoxels(const amVoxelGrid& g, int axis, int s, std::vector<std::size_t>& voxel)
{
  const int u = (axis + 1) % 3, w = (axis + 2) % 3;
  const int nu = g.N[u], nw = g.N[w];
  voxel.resize(static_cast<std::size_t>(nu) * nw);
  int c[3];
  c[axis] = s;
  for (int b = 0; b < nw; ++b)
    for (int a = 0; a < nu; ++a)
    {
      c[u] = a;
      c[w] = b;
      voxel[static_cast<std::size_t>(b) * nu + a] = g.Index(c[0], c[1], c[2]);
    }
}

int amVoxel::SlicePieces(const std::vector<char>& in, int width, std::vector<int>& id)
{
  const std::size_t n = in.size(), nu = static_cast<std::size_t>(width);
  id.assign(n, -1);
  int count = 0;
  std::vector<std::size_t> stack;
  for (std::size_t start = 0; start < n; ++start)
  {
    if (!in[start] || id[start] >= 0)
      continue;
    id[start] = count;
    stack.assign(1, start);
    while (!stack.empty())
    {
      const std::size_t p = stack.back();
      stack.pop_back();
      const std::size_t a = p % nu;
      const std::size_t next[4] = { a > 0 ? p - 1 : p, a + 1 < nu ? p + 1 : p, p >= nu ? p - nu : p,
        p + nu < n ? p + nu : p };
      for (const std::size_t q : next)
        if (in[q] && id[q] < 0)
        {
          id[q] = count;
          stack.push_back(q);
        }
    }
    ++count;
  }
  return count;
}
