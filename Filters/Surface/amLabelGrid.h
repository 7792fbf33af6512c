/**
 * @file    amLabelGrid.h
 * @brief   A label map as the label surface extractor reads it: per voxel the rank of its label
 *          among the distinct labels, the geometry (extent, origin, spacing, direction), and the
 *          voxel corners on the surface with the number of copies of each one's vertex.
 */
#ifndef amLabelGrid_h
#define amLabelGrid_h

#include "amLabelCorners.h"

#include "vtkType.h"

#include <algorithm>
#include <cstdint>
#include <vector>

struct amLabelGrid
{
  int N[3];
  int Extent[6];
  double Origin[3], Spacing[3], Direction[9];
  // Each voxel holds the rank of its label among the distinct labels (ranks keep the order of
  // the values); Values[rank] is the label. Outside the image: the background's rank.
  std::vector<std::uint16_t> Labels;
  std::vector<int> Values;
  int Background; // rank of the background label

  int Label(int i, int j, int k) const
  {
    if (i < 0 || j < 0 || k < 0 || i >= this->N[0] || j >= this->N[1] || k >= this->N[2])
      return this->Background;
    return this->Labels[(static_cast<size_t>(k) * this->N[1] + j) * this->N[0] + i];
  }
  // Corner entries of one row of corners (fixed j, k), sorted by i.
  struct Entry
  {
    int I;
    int Copies;
    vtkIdType Base;
  };
  std::vector<vtkIdType> RowStart; // (N[1] + 1) * (N[2] + 1) + 1
  std::vector<Entry> Entries;
  const Entry* Find(int ci, int cj, int ck) const
  {
    const size_t row = static_cast<size_t>(ck) * (this->N[1] + 1) + cj;
    const Entry* b = this->Entries.data() + this->RowStart[row];
    const Entry* e = this->Entries.data() + this->RowStart[row + 1];
    const Entry* it = std::lower_bound(b, e, ci, [](const Entry& x, int v) { return x.I < v; });
    return (it != e && it->I == ci) ? it : nullptr;
  }
  void CornerLabels(int ci, int cj, int ck, int lab[8]) const
  {
    for (int o = 0; o < 8; ++o)
      lab[o] = this->Label(
        ci - 1 + amLabelCorners::Bit(o, 0), cj - 1 + amLabelCorners::Bit(o, 1), ck - 1 + amLabelCorners::Bit(o, 2));
  }
  /// True when the 8 voxels around the corner hold one label; otherwise fills lab.
  bool UniformCorner(int ci, int cj, int ck, int lab[8]) const
  {
    if (ci > 0 && cj > 0 && ck > 0 && ci < this->N[0] && cj < this->N[1] && ck < this->N[2])
    {
      // Interior corner: most are inside one region; test without bounds checks.
      const size_t sy = this->N[0], sz = static_cast<size_t>(this->N[0]) * this->N[1];
      const std::uint16_t* v =
        this->Labels.data() + ((static_cast<size_t>(ck) - 1) * this->N[1] + (cj - 1)) * this->N[0] + (ci - 1);
      const std::uint16_t l0 = v[0];
      if (v[1] == l0 && v[sy] == l0 && v[sy + 1] == l0 && v[sz] == l0 && v[sz + 1] == l0 && v[sz + sy] == l0 &&
        v[sz + sy + 1] == l0)
        return true;
    }
    this->CornerLabels(ci, cj, ck, lab);
    for (int o = 1; o < 8; ++o)
      if (lab[o] != lab[0])
        return false;
    return true;
  }
  vtkIdType Corner(int ci, int cj, int ck) const
  {
    return (static_cast<vtkIdType>(ck) * (this->N[1] + 1) + cj) * (this->N[0] + 1) + ci;
  }
  /// World position of a continuous voxel index (voxel centres at whole numbers).
  void World(const double ijk[3], float out[3]) const
  {
    double idx[3];
    for (int d = 0; d < 3; ++d)
      idx[d] = (ijk[d] + this->Extent[2 * d]) * this->Spacing[d];
    for (int r = 0; r < 3; ++r)
      out[r] = static_cast<float>(this->Origin[r] + this->Direction[3 * r] * idx[0] +
        this->Direction[3 * r + 1] * idx[1] + this->Direction[3 * r + 2] * idx[2]);
  }
};

#endif
