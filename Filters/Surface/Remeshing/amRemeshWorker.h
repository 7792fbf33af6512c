/**
 * @file    amRemeshWorker.h
 * @brief   What one of the remesher's two workers uses besides the surface: scratch space of the
 *          checks, hints found by the last check, counters; and which worker the calling thread is.
 */
#ifndef amRemeshWorker_h
#define amRemeshWorker_h

#include "amRemeshSurface.h"

#include <array>
#include <vector>

namespace amRemesh
{
/// A live triangle near an operation's new triangles, as the crossing check reads it.
struct NearTriangle
{
  int Id;
  std::array<int, 3> V;
  Vec3 X[3], Lo, Hi;
};

/// On a cache line of its own: the two workers' counters must not share one.
struct alignas(64) Worker
{
  // Hints found by the last ClustersStayNear (owner, entry, triangle), kept if the operation is.
  std::vector<std::array<int, 3>> PendingHints;
  std::vector<NearTriangle> Near; // the live triangles near the last operation's
  std::vector<int> Stamp;         // per triangle: the last crossing check that saw it
  int StampValue = 0;
  int LastHit = -1; // the live triangle the last refused operation would have crossed
  long long Collapses = 0, Moves = 0, Flips = 0;
  std::vector<int> Removed; // per component (see Components): vertices this worker removed
  // Collapse's work vectors, kept (a collapse uses a dozen; none outlives the call, and nothing
  // called from Collapse collapses).
  struct
  {
    std::vector<int> Edge, Na, Nb, Common, Apex, Changed, Removed, Sheets, Affected;
    std::vector<std::array<int, 3>> Ids;
    std::vector<std::array<Vec3, 3>> Pos;
    std::vector<std::array<Vec3, 4>> Swept;
  } C;
};

/// Which worker the calling thread is (passes on two workers run one per side of the split
/// plane, see OnTwoWorkers; everything else runs as worker 0).
inline int& CurrentWorker()
{
  thread_local int worker = 0;
  return worker;
}
/// The zone (side of the split plane) the calling thread may change; -1: any.
inline int& CurrentZone()
{
  thread_local int zone = -1;
  return zone;
}
}

#endif
