/**
 * @file    amRemeshComponents.h
 * @brief   The connected components of the remesher's surface when a collapse pass begins, so a
 *          worker can tell a small closed fragment (which must not be collapsed further) without
 *          searching it.
 *
 * A collapse neither splits nor joins components and removes one vertex, so a worker bounds the
 * size of a component from below without looking at it: what it had, less what this worker
 * removed, less all it had on the other worker's side (the other worker removes only vertices
 * there).
 */
#ifndef amRemeshComponents_h
#define amRemeshComponents_h

#include "amRemeshBins.h"
#include "amRemeshWorker.h"

namespace amRemesh
{
class ANATOMESHFILTERSSURFACE_EXPORT Components
{
public:
  std::vector<int> Of;                   // per vertex: its component (-1: none)
  std::vector<std::array<int, 3>> Count; // per component: vertices in zone 0, in zone 1, in all

  /// The components of the live triangles now; every worker's Removed counts reset.
  void Find(const Surface& surface, const Bins& bins, std::array<Worker, 2>& workers);
  /// For the worker of zone 'zone': whether v's component surely has more than n live vertices,
  /// whatever the other worker has done meanwhile.
  bool SurelyMoreThan(int v, int n, const Worker& worker, int zone) const
  {
    const int c = this->Of[v];
    if (c < 0)
      return false;
    const auto& count = this->Count[c];
    return count[2] - worker.Removed[c] - count[1 - zone] > n;
  }
};
}

#endif
