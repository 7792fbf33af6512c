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
#include <atomic>

class ANATOMESHFILTERSCORE_EXPORT amThreading
{
public:
  static void Initialize();

  /// vtkSMPTools::For for short loops run many times (solver vector work): below 'serial'
  /// iterations the body runs on the calling thread, as waking the pool would cost more than the
  /// loop itself. Chunks are disjoint, so the result never depends on the thread count.
  template<typename Functor>
  static void For(vtkIdType first, vtkIdType last, Functor&& f, vtkIdType serial = 50000)
  {
    if (last - first < serial)
      f(first, last);
    else
      vtkSMPTools::For(first, last, std::max<vtkIdType>(8192, (last - first) / 64), f);
  }

  /// The smallest i in [first, last) for which ok(i) is false, or 'last' when there is none: ok
  /// runs on the threads (each chunk stops at its first failure), so a check over millions of
  /// voxels names the same first bad one as the serial loop would. ok may write i's own output.
  template<typename Functor>
  static vtkIdType FirstFailure(vtkIdType first, vtkIdType last, Functor&& ok)
  {
    std::atomic<vtkIdType> failed(last);
    vtkSMPTools::For(first, last, [&](vtkIdType i0, vtkIdType i1) {
      for (vtkIdType i = i0; i < i1; ++i)
        if (!ok(i))
        {
          vtkIdType seen = failed.load();
          while (i < seen && !failed.compare_exchange_weak(seen, i))
          {
          }
          return;
        }
    });
    return failed.load();
  }

  /// std::sort with both halves sorted at once on the threads, then merged (VTK's STDThread
  /// backend sorts on one thread). Elements that compare equal may come out in another order
  /// than std::sort would leave them: for orders where equal elements are alike.
  template<typename Iterator>
  static void Sort(Iterator first, Iterator last)
  {
    if (last - first < 100000)
    {
      std::sort(first, last);
      return;
    }
    const Iterator middle = first + (last - first) / 2;
    vtkSMPTools::For(0, 2, 1, [&](vtkIdType h0, vtkIdType h1) {
      for (vtkIdType h = h0; h < h1; ++h)
        std::sort(h == 0 ? first : middle, h == 0 ? middle : last);
    });
    std::inplace_merge(first, middle, last);
  }
};

#endif
