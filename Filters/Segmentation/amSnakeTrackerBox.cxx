#include "amSnakeTracker.h"

#include "amSnakeLevelSet.h"

#include "vtkSMPTools.h"

#include <algorithm>
#include <cstring>

using namespace amSnakeLevelSet;

namespace
{
/// The box (first voxel, size) of the mask's inside grown by 'margin' voxels and clamped to the
/// region; false when the mask is empty.
bool InsideBox(const unsigned char* mask, const int size[3], int margin, int lo[3], int box[3])
{
  // Per slice: the first and last row and column of the inside, then the slices together (in
  // order: the same box whatever the threads).
  const int nx = size[0], ny = size[1], nz = size[2];
  std::vector<std::array<int, 4>> slice(static_cast<size_t>(nz), { nx, -1, ny, -1 });
  vtkSMPTools::For(0, nz, [&](vtkIdType k0, vtkIdType k1) {
    for (vtkIdType k = k0; k < k1; ++k)
    {
      std::array<int, 4>& s = slice[k];
      for (int j = 0; j < ny; ++j)
      {
        const unsigned char* row = mask + (static_cast<size_t>(k) * ny + j) * nx;
        const unsigned char* first = std::find(row, row + nx, 1);
        if (first == row + nx)
          continue;
        const int last = nx - 1 -
          static_cast<int>(std::find(std::reverse_iterator<const unsigned char*>(row + nx),
                             std::reverse_iterator<const unsigned char*>(row), 1) -
            std::reverse_iterator<const unsigned char*>(row + nx));
        s = { std::min(s[0], static_cast<int>(first - row)), std::max(s[1], last), std::min(s[2], j),
          std::max(s[3], j) };
      }
    }
  });
  int hi[3] = { -1, -1, -1 };
  lo[0] = nx;
  lo[1] = ny;
  lo[2] = nz;
  for (int k = 0; k < nz; ++k)
    if (slice[k][1] >= 0)
    {
      lo[0] = std::min(lo[0], slice[k][0]);
      hi[0] = std::max(hi[0], slice[k][1]);
      lo[1] = std::min(lo[1], slice[k][2]);
      hi[1] = std::max(hi[1], slice[k][3]);
      lo[2] = std::min(lo[2], k);
      hi[2] = k;
    }
  if (hi[2] < 0)
    return false;
  for (int a = 0; a < 3; ++a)
  {
    lo[a] = std::max(0, lo[a] - margin);
    box[a] = std::min(size[a] - 1, hi[a] + margin) - lo[a] + 1;
  }
  return true;
}

/// Copies a box of one grid into a box of another of the same size (x rows in one piece).
template<typename T>
void CopyBox(const T* from, const int fromSize[3], const int fromLo[3], T* to, const int toSize[3], const int toLo[3],
  const int box[3])
{
  vtkSMPTools::For(0, box[2], [&](vtkIdType k0, vtkIdType k1) {
    for (vtkIdType k = k0; k < k1; ++k)
      for (int j = 0; j < box[1]; ++j)
      {
        const size_t f =
          ((static_cast<size_t>(k) + fromLo[2]) * fromSize[1] + (j + fromLo[1])) * fromSize[0] + fromLo[0];
        const size_t t = ((static_cast<size_t>(k) + toLo[2]) * toSize[1] + (j + toLo[1])) * toSize[0] + toLo[0];
        std::memcpy(to + t, from + f, sizeof(T) * static_cast<size_t>(box[0]));
      }
  });
}
}

int amSnakeTracker::EvolveInBox(double lo, double hi, const std::vector<unsigned char>& initial, int iterations,
  const std::function<void(double)>& progress)
{
  // The sparse field's layers and the curvature's neighbourhood reach a few voxels beyond the
  // front; a front that ends within 'guard' voxels of the box's side came near enough to have
  // read the side's boundary condition. A margin within the guard leaves no room to evolve.
  constexpr int guard = 6;
  const int margin = this->P.BoxMargin;
  int blo[3], bsize[3];
  if (margin <= guard || !InsideBox(initial.data(), this->Size, margin, blo, bsize))
    return BoxTooSmall;
  const size_t n = static_cast<size_t>(bsize[0]) * bsize[1] * bsize[2];
  if (n == this->InsideMask.size())
    return BoxTooSmall; // the box is the whole region
  const int origin[3] = { 0, 0, 0 };
  auto feature = NewImage<FloatImage<3>>(bsize, this->Spacing);
  auto mask = NewImage<MaskImage<3>>(bsize, this->Spacing);
  CopyBox(this->Feature.data(), this->Size, blo, feature->GetBufferPointer(), bsize, origin, bsize);
  CopyBox(initial.data(), this->Size, blo, mask->GetBufferPointer(), bsize, origin, bsize);
  auto phi = PhiFromMask(mask);
  MaskImage<3>::Pointer inside;
  try
  {
    long long elapsed = 0;
    inside = Evolve<3>(feature, phi, lo, hi, LevelSetParameters(this->P), iterations, progress, &elapsed);
    // Counted only when kept: a box given up is evolved again on the whole region.
    int elo[3], esize[3];
    if (InsideBox(inside->GetBufferPointer(), bsize, 0, elo, esize))
      for (int a = 0; a < 3; ++a)
      {
        const bool lowSide = blo[a] > 0 && elo[a] < guard;
        const bool highSide = blo[a] + bsize[a] < this->Size[a] && elo[a] + esize[a] > bsize[a] - guard;
        if (lowSide || highSide)
          return BoxTooSmall;
      }
    this->Elapsed += elapsed;
    ++this->Boxed;
  }
  catch (const itk::ExceptionObject& e)
  {
    this->Error = e.GetDescription();
    return BoxFailed;
  }
  std::fill(this->InsideMask.begin(), this->InsideMask.end(), 0);
  CopyBox(inside->GetBufferPointer(), bsize, origin, this->InsideMask.data(), this->Size, blo, bsize);
  return BoxDone;
}
