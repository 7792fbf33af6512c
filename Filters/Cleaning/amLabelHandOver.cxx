// Voxels a label gives up, handed to their neighbours.
#include "amLabelCleaning.h"

#include <array>

void amLabelCleaning::HandOver(
  const int dims[3], std::vector<unsigned char>& out, std::vector<vtkIdType>& released, int from)
{
  const vtkIdType n = static_cast<vtkIdType>(out.size());
  const vtkIdType sx = 1, sy = dims[0], sz = static_cast<vtkIdType>(dims[0]) * dims[1];
  if (released.empty())
    return;
  std::vector<char> pending(static_cast<size_t>(n), 0);
  for (vtkIdType id : released)
    pending[id] = 1;
  while (!released.empty())
  {
    std::vector<std::pair<vtkIdType, unsigned char>> assign;
    std::vector<vtkIdType> still;
    for (vtkIdType id : released)
    {
      const int i = static_cast<int>(id % dims[0]), j = static_cast<int>((id / dims[0]) % dims[1]),
                k = static_cast<int>(id / sz);
      std::array<int, 256> votes{};
      int best = -1, bestVotes = 0;
      for (int dk = -1; dk <= 1; ++dk)
        for (int dj = -1; dj <= 1; ++dj)
          for (int di = -1; di <= 1; ++di)
          {
            const int ii = i + di, jj = j + dj, kk = k + dk;
            if ((!di && !dj && !dk) || ii < 0 || jj < 0 || kk < 0 || ii >= dims[0] || jj >= dims[1] || kk >= dims[2])
              continue;
            const vtkIdType nid = kk * sz + jj * sy + ii * sx;
            if (pending[nid] || out[nid] == from)
              continue;
            const int c = ++votes[out[nid]];
            if (c > bestVotes || (c == bestVotes && out[nid] < best))
            {
              best = out[nid];
              bestVotes = c;
            }
          }
      if (best >= 0)
        assign.emplace_back(id, static_cast<unsigned char>(best));
      else
        still.push_back(id);
    }
    if (assign.empty())
    {
      for (vtkIdType id : still)
        out[id] = 0;
      break;
    }
    for (const auto& a : assign)
    {
      out[a.first] = a.second;
      pending[a.first] = 0;
    }
    released.swap(still);
  }
}
