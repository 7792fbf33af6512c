#include "amLabelModeFilter.h"

#include "vtkSMPTools.h"

#include <array>
#include <atomic>

std::size_t amLabelMode::Pass(const int dims[3], int radius, std::vector<unsigned char>& labels)
{
  const std::vector<unsigned char> before = labels;
  const std::size_t sy = dims[0], sz = static_cast<std::size_t>(dims[0]) * dims[1];
  std::atomic<std::size_t> changed{ 0 };
  vtkSMPTools::For(0, dims[2], [&](int k0, int k1) {
    std::size_t local = 0;
    std::array<int, 256> count{};
    for (int k = k0; k < k1; ++k)
      for (int j = 0; j < dims[1]; ++j)
        for (int i = 0; i < dims[0]; ++i)
        {
          // f(label) for every voxel of the neighbourhood inside the image.
          auto around = [&](auto&& f) {
            for (int z = k - radius; z <= k + radius; ++z)
              for (int y = j - radius; y <= j + radius; ++y)
                for (int x = i - radius; x <= i + radius; ++x)
                  if (x >= 0 && y >= 0 && z >= 0 && x < dims[0] && y < dims[1] && z < dims[2])
                    f(before[z * sz + y * sy + x]);
          };
          const unsigned char own = before[k * sz + j * sy + i];
          int best = own;
          around([&](int l) { ++count[l]; });
          // The mode (the smaller label between equals); a tie with the voxel's own label keeps it.
          around([&](int l) {
            if (count[l] > count[best] || (count[l] == count[best] && l < best))
              best = l;
          });
          if (count[best] == count[own])
            best = own;
          around([&](int l) { count[l] = 0; });
          if (best != own)
          {
            labels[k * sz + j * sy + i] = static_cast<unsigned char>(best);
            ++local;
          }
        }
    changed += local;
  });
  return changed;
}
