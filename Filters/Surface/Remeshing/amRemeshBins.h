/**
 * @file    amRemeshBins.h
 * @brief   Bins of the remesher's live triangles, so that every local operation can find the
 *          triangles its new ones might cross; and the split plane of the two workers.
 *
 * The bins are kept in three maps: bins before the split plane (index along SplitAxis below
 * SplitIndex), after it, and on it (zones 0, 1, 2), so that two workers can each change the
 * triangles of one side. They stay exact: every change of a triangle moves it to the bins of its
 * new box, and a triangle that dies leaves them, so an entry in a worker's side names a triangle
 * touching that side, which the other worker cannot change.
 */
#ifndef amRemeshBins_h
#define amRemeshBins_h

#include "amRemeshBinTable.h"
#include "amRemeshSurface.h"

#include <array>
#include <cmath>
#include <vector>

namespace amRemesh
{
class ANATOMESHFILTERSSURFACE_EXPORT Bins
{
public:
  explicit Bins(const Surface& surface)
    : S(surface)
  {
  }
  Bins(const Bins&) = delete;
  Bins& operator=(const Bins&) = delete;

  double Size = 1.0;           // bin side
  std::array<BinTable, 3> Map; // per zone: key -> triangles
  int SplitAxis = 0;
  long long SplitIndex = 0;
  /// Per triangle slot: the range of bins (index box lo 0..2, hi 3..5) it is in (lo > hi: none).
  std::vector<std::array<int, 6>> BinnedIn;
  /// Per triangle slot: its bounding box when it was last binned (lo 0..2, hi 3..5), rounded
  /// outwards to floats: the crossing check's first test reads this one small record; the
  /// triangle and its three corners are read only for the triangles that pass it.
  std::vector<std::array<float, 6>> BinnedBox;

  int ZoneOf(long long index) const { return index < this->SplitIndex ? 0 : (index > this->SplitIndex ? 1 : 2); }
  /// The zone of the bins holding point x.
  int ZoneAt(const Vec3& x) const
  {
    return this->ZoneOf(static_cast<long long>(std::floor(x[this->SplitAxis] / this->Size)));
  }
  /// Whether the box lies in zone z's bins.
  bool BoxInZone(const Vec3& lo, const Vec3& hi, int z) const { return this->ZoneAt(lo) == z && this->ZoneAt(hi) == z; }
  static long long Key(long long i, long long j, long long k)
  {
    return ((i + (1 << 20)) << 42) | ((j + (1 << 20)) << 21) | (k + (1 << 20));
  }
  static void Box(const Vec3* p, Vec3& lo, Vec3& hi)
  {
    lo = p[0].cwiseMin(p[1]).cwiseMin(p[2]);
    hi = p[0].cwiseMax(p[1]).cwiseMax(p[2]);
  }
  /// Calls f(key, zone) for every bin the box touches.
  template<typename F>
  void ForBins(const Vec3& lo, const Vec3& hi, F f) const
  {
    long long l[3], h[3];
    for (int d = 0; d < 3; ++d)
    {
      l[d] = static_cast<long long>(std::floor(lo[d] / this->Size));
      h[d] = static_cast<long long>(std::floor(hi[d] / this->Size));
    }
    for (long long i = l[0]; i <= h[0]; ++i)
      for (long long j = l[1]; j <= h[1]; ++j)
        for (long long k = l[2]; k <= h[2]; ++k)
        {
          const long long index[3] = { i, j, k };
          f(Key(i, j, k), this->ZoneOf(index[this->SplitAxis]));
        }
  }
  /// The bin range of triangle t now; its float box into 'box' when given.
  std::array<int, 6> Range(int t, std::array<float, 6>* box = nullptr) const;
  /// Calls f(key, zone) for the bins of range r outside range 'except' (null: none).
  template<typename F>
  void ForRange(const std::array<int, 6>& r, const std::array<int, 6>* except, F f) const
  {
    for (long long i = r[0]; i <= r[3]; ++i)
      for (long long j = r[1]; j <= r[4]; ++j)
        for (long long k = r[2]; k <= r[5]; ++k)
        {
          if (except && i >= (*except)[0] && i <= (*except)[3] && j >= (*except)[1] && j <= (*except)[4] &&
            k >= (*except)[2] && k <= (*except)[5])
            continue;
          const long long index[3] = { i, j, k };
          f(Key(i, j, k), this->ZoneOf(index[this->SplitAxis]));
        }
  }
  /// Live triangle t (new, or changed since it was last binned) into the bins its box touches,
  /// and out of those it no longer touches.
  void Add(int t);
  /// Triangle t out of every bin (it dies).
  void Remove(int t);
  /// The triangles ts binned again after a change.
  void Update(const std::vector<int>& ts)
  {
    for (int t : ts)
      this->Add(t);
  }
  /// Every live triangle binned anew, at the size that fits the triangles now, with the split
  /// plane across the longest side of the bounding box at the median vertex.
  void Rebuild();
  /// Every live triangle binned anew at the present size and split plane (the triangles were
  /// renumbered: the zones stay where they were).
  void Rebin();
  /// Rebuild where the bins no longer fit the triangles: their size off by more than a quarter.
  /// (The bins stay exact without it, and the split plane stays where it was.)
  void RebuildIfStale();
  /// The bin size that fits the triangles now: twice their mean edge length.
  double FittingSize() const;
  /// The Morton code of the cube of side 'cell' holding x (21 bits per axis).
  static unsigned long long MortonCode(const Vec3& x, double cell);

private:
  void RemoveFromBins(int t, const std::array<int, 6>& r, const std::array<int, 6>* except);
  const Surface& S;
};
}

#endif
