/**
 * @file    amRemeshScheduler.h
 * @brief   Runs a pass of local operations on two workers, one on each side of the bins' split
 *          plane, then the rest serially: the same result whatever the thread count.
 */
#ifndef amRemeshScheduler_h
#define amRemeshScheduler_h

#include "amRemeshWorker.h"

#include "vtkSMPTools.h"

#include <array>
#include <vector>

namespace amRemesh
{
/// Runs op on the items 0 .. n-1 on two workers, one on each side of the split plane, then
/// serially. Each worker takes, in order, the items whose zone (zoneOf) is its side's; op
/// returns 1 (done), 0 (refused) or -1 (left for the serial pass). A worker's op must change
/// and read only what lies in its side's bins (the stars it changes, and the bins its crossing
/// check reads): then neither worker reads what the other changes, and each side's result does
/// not depend on the other's timing. The items left, and those in no zone (2), follow serially,
/// in order. While a worker runs, CurrentWorker() and CurrentZone() are its side. Returns the
/// number of items done.
template<typename ZoneOfItem, typename Op>
int OnTwoWorkers(Surface& surface, size_t n, ZoneOfItem zoneOf, Op op)
{
  surface.SizeDirty(); // Touch must not resize the flags on a worker
  std::vector<char> later(n, 1);
  std::array<std::vector<size_t>, 2> side, taken; // taken: what each worker did not leave
  for (size_t i = 0; i < n; ++i)
  {
    const int z = zoneOf(i);
    if (z < 2)
      side[z].push_back(i);
  }
  std::array<int, 2> doneBy = { 0, 0 };
  vtkSMPTools::For(0, 2, 1, [&](vtkIdType z0, vtkIdType z1) {
    for (vtkIdType z = z0; z < z1; ++z)
    {
      const int worker = CurrentWorker(), zone = CurrentZone();
      CurrentWorker() = static_cast<int>(z);
      CurrentZone() = static_cast<int>(z);
      int done = 0; // counted here, written once (the workers' items interleave)
      for (size_t i : side[z])
      {
        const int r = op(i);
        if (r >= 0)
          taken[z].push_back(i);
        done += r > 0;
      }
      doneBy[z] = done;
      CurrentWorker() = worker;
      CurrentZone() = zone;
    }
  });
  for (const auto& list : taken)
    for (size_t i : list)
      later[i] = 0;
  int done = doneBy[0] + doneBy[1];
  for (size_t i = 0; i < n; ++i)
    if (later[i])
      done += op(i) > 0;
  return done;
}
}

#endif
