// The holes of a mask within its slices: what a ring of the mask encloses in one slice.
#include "amVoxelGrid.h"

amVoxelMask amVoxel::SliceHoles(const amVoxelGrid& g, const amVoxelMask& mask, int axis, std::size_t maximumVoxels)
{
  amVoxelMask holes(mask.size(), 0);
  const int u = (axis + 1) % 3, w = (axis + 2) % 3;
  const int nu = g.N[u], nw = g.N[w];
  std::vector<int> id(static_cast<std::size_t>(nu) * nw);
  std::vector<std::size_t> voxel(id.size()), members, stack;
  for (int s = 0; s < g.N[axis]; ++s)
  {
    int c[3];
    c[axis] = s;
    for (int b = 0; b < nw; ++b)
      for (int a = 0; a < nu; ++a)
      {
        c[u] = a;
        c[w] = b;
        voxel[static_cast<std::size_t>(b) * nu + a] = g.Index(c[0], c[1], c[2]);
      }
    std::fill(id.begin(), id.end(), 0);
    // 4-connected pieces of the slice outside the mask, by flooding; a piece that reaches the
    // slice's border, or is larger than the bound, is no hole.
    for (std::size_t start = 0; start < id.size(); ++start)
    {
      if (id[start] || mask[voxel[start]])
        continue;
      members.clear();
      stack.assign(1, start);
      id[start] = 1;
      bool open = false;
      while (!stack.empty())
      {
        const std::size_t p = stack.back();
        stack.pop_back();
        members.push_back(p);
        const int a = static_cast<int>(p % nu), b = static_cast<int>(p / nu);
        open = open || a == 0 || b == 0 || a == nu - 1 || b == nw - 1;
        const std::size_t next[4] = { a > 0 ? p - 1 : p, a + 1 < nu ? p + 1 : p, b > 0 ? p - nu : p,
          b + 1 < nw ? p + nu : p };
        for (const std::size_t q : next)
          if (!id[q] && !mask[voxel[q]])
          {
            id[q] = 1;
            stack.push_back(q);
          }
      }
      if (!open && members.size() <= maximumVoxels)
        for (const std::size_t p : members)
          holes[voxel[p]] = 1;
    }
  }
  return holes;
}
