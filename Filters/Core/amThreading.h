/**
 * @class   amThreading
 * @brief   Selects a multi-threaded vtkSMPTools backend once per process.
 *
 * ParaView 5.11's VTK defaults to the Sequential SMP backend, which leaves the second core idle.
 * Filters call amThreading::Initialize() in their constructor: unless the user chose a backend
 * through VTK_SMP_BACKEND_IN_USE, it switches to STDThread. Results never depend on the thread
 * count (every parallel loop in Anatomesh writes disjoint outputs or reduces deterministically).
 */
#ifndef amThreading_h
#define amThreading_h

#include "AnatomeshFiltersCoreModule.h" // export macro
#include "vtkSMPTools.h"

#include <algorithm>

class ANATOMESHFILTERSCORE_EXPORT amThreading
{
public:
  static void Initialize();

  /// vtkSMPTools::For for short loops run many times (solver vector work): below 'serial'
  /// iterations the body runs on the calling thread, as waking the pool would cost more than the
  /// loop itself. Chunks are disjoint, so the result never depends on the thread count.
  template <typename Functor>
  static void For(vtkIdType first, vtkIdType last, Functor&& f, vtkIdType serial = 50000)
  {
    if (last - first < serial)
      f(first, last);
    else
      vtkSMPTools::For(first, last, std::max<vtkIdType>(8192, (last - first) / 64), f);
  }
};

#endif
