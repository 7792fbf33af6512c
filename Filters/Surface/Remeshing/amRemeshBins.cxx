#include "amRemeshBins.h"

#include "vtkSMPTools.h"

#include <algorithm>
#include <limits>

namespace amRemesh
{
std::array<int, 6> Bins::Range(int t, std::array<float, 6>* box) const
{
  Vec3 p[3], lo, hi;
  for (int k = 0; k < 3; ++k)
    p[k] = this->S.P[this->S.T[t].V[k]];
  Box(p, lo, hi);
  if (box)
    for (int d = 0; d < 3; ++d)
    {
      float l = static_cast<float>(lo[d]), h = static_cast<float>(hi[d]);
      (*box)[d] = l > lo[d] ? std::nextafter(l, -std::numeric_limits<float>::infinity()) : l;
      (*box)[d + 3] = h < hi[d] ? std::nextafter(h, std::numeric_limits<float>::infinity()) : h;
    }
  std::array<int, 6> r;
  for (int d = 0; d < 3; ++d)
  {
    r[d] = static_cast<int>(std::floor(lo[d] / this->Size));
    r[d + 3] = static_cast<int>(std::floor(hi[d] / this->Size));
  }
  return r;
}

void Bins::RemoveFromBins(int t, const std::array<int, 6>& r, const std::array<int, 6>* except)
{
  this->ForRange(r, except, [&](long long key, int zone) {
    std::vector<int>* found = this->Map[zone].Find(key);
    if (!found)
      return;
    auto& list = *found;
    auto at = std::find(list.begin(), list.end(), t);
    if (at != list.end())
    {
      *at = list.back();
      list.pop_back();
    }
  });
}

void Bins::Add(int t)
{
  if (this->BinnedIn.size() <= static_cast<size_t>(t))
  {
    this->BinnedIn.resize(this->S.T.size(), { 0, 0, 0, -1, -1, -1 });
    this->BinnedBox.resize(this->S.T.size(), { 1, 1, 1, 0, 0, 0 });
  }
  const std::array<int, 6> r = this->Range(t, &this->BinnedBox[t]), old = this->BinnedIn[t];
  const bool had = old[0] <= old[3];
  if (had && r == old)
    return;
  if (had)
    this->RemoveFromBins(t, old, &r);
  this->ForRange(r, had ? &old : nullptr, [&](long long key, int zone) { this->Map[zone][key].push_back(t); });
  this->BinnedIn[t] = r;
}

void Bins::Remove(int t)
{
  if (static_cast<size_t>(t) >= this->BinnedIn.size() || this->BinnedIn[t][0] > this->BinnedIn[t][3])
    return;
  this->RemoveFromBins(t, this->BinnedIn[t], nullptr);
  this->BinnedIn[t] = { 0, 0, 0, -1, -1, -1 };
  this->BinnedBox[t] = { 1, 1, 1, 0, 0, 0 };
}

void Bins::RebuildIfStale()
{
  const double size = this->FittingSize();
  if (size > 1.25 * this->Size || size < 0.8 * this->Size || this->BinnedIn.size() != this->S.T.size())
    this->Rebuild();
}

unsigned long long Bins::MortonCode(const Vec3& x, double cell)
{
  auto spread = [](unsigned long long v) {
    v &= 0x1fffff;
    v = (v | v << 32) & 0x1f00000000ffffULL;
    v = (v | v << 16) & 0x1f0000ff0000ffULL;
    v = (v | v << 8) & 0x100f00f00f00f00fULL;
    v = (v | v << 4) & 0x10c30c30c30c30c3ULL;
    v = (v | v << 2) & 0x1249249249249249ULL;
    return v;
  };
  unsigned long long code = 0;
  for (int d = 0; d < 3; ++d)
    code |= spread(static_cast<unsigned long long>(static_cast<long long>(std::floor(x[d] / cell)) + (1 << 20))) << d;
  return code;
}

double Bins::FittingSize() const
{
  // Summed in blocks of a fixed size on the threads, then the blocks in order: the same sum
  // whatever the number of threads (every pass asks, and most slots are dead ones).
  const auto& T = this->S.T;
  const auto& P = this->S.P;
  const size_t block = 1 << 14, nBlocks = (T.size() + block - 1) / block;
  std::vector<double> sums(nBlocks, 0.0);
  std::vector<long long> counts(nBlocks, 0);
  vtkSMPTools::For(0, static_cast<vtkIdType>(nBlocks), [&](vtkIdType b0, vtkIdType b1) {
    for (vtkIdType b = b0; b < b1; ++b)
      for (size_t i = b * block; i < std::min(T.size(), static_cast<size_t>(b + 1) * block); ++i)
        if (T[i].Alive)
          for (int k = 0; k < 3; ++k, ++counts[b])
            sums[b] += (P[T[i].V[(k + 1) % 3]] - P[T[i].V[k]]).norm();
  });
  double sum = 0;
  long long n = 0;
  for (size_t b = 0; b < nBlocks; ++b)
  {
    sum += sums[b];
    n += counts[b];
  }
  return n ? std::max(2.0 * sum / n, 1e-6) : 1.0;
}

void Bins::Rebuild()
{
  const auto& S = this->S;
  this->Size = this->FittingSize();
  // The split: across the longest side of the bounding box, at the median vertex.
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  std::vector<double> along;
  for (size_t v = 0; v < S.P.size(); ++v)
    if (S.VAlive[v] && !S.VT[v].empty())
    {
      lo = lo.cwiseMin(S.P[v]);
      hi = hi.cwiseMax(S.P[v]);
    }
  if (lo[0] <= hi[0])
  {
    (hi - lo).maxCoeff(&this->SplitAxis);
    for (size_t v = 0; v < S.P.size(); ++v)
      if (S.VAlive[v] && !S.VT[v].empty())
        along.push_back(S.P[v][this->SplitAxis]);
    std::nth_element(along.begin(), along.begin() + along.size() / 2, along.end());
    this->SplitIndex = static_cast<long long>(std::floor(along[along.size() / 2] / this->Size));
  }
  this->Rebin();
}

void Bins::Rebin()
{
  const auto& S = this->S;
  // Emptied and filled on two threads, one for the bins before the split plane and on it, one
  // for those after it (each bin lists its triangles in their order, as Add would one by one).
  this->BinnedIn.assign(S.T.size(), { 0, 0, 0, -1, -1, -1 });
  this->BinnedBox.assign(S.T.size(), { 1, 1, 1, 0, 0, 0 });
  vtkSMPTools::For(0, 2, 1, [&](vtkIdType z0, vtkIdType z1) {
    for (vtkIdType z = z0; z < z1; ++z)
    {
      for (int zone : { 0, 1, 2 })
        if ((zone == 1) == (z == 1))
          this->Map[zone].Clear();
      for (size_t t = 0; t < S.T.size(); ++t)
        if (S.T[t].Alive)
        {
          const std::array<int, 6> r = this->Range(static_cast<int>(t), z == 0 ? &this->BinnedBox[t] : nullptr);
          if (z == 0)
            this->BinnedIn[t] = r;
          this->ForRange(r, nullptr, [&](long long key, int zone) {
            if ((zone == 1) == (z == 1))
              this->Map[zone][key].push_back(static_cast<int>(t));
          });
        }
    }
  });
}
}
