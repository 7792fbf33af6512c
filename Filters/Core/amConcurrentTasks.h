/**
 * @class   amConcurrentTasks
 * @brief   Runs independent tasks (one organ each, say) on worker threads while the calling thread
 *          reports their progress and watches for an abort.
 *
 * A filter may not call UpdateProgress from another thread: its observers (ParaView's progress
 * bar, a Python callback holding the GIL) expect the thread that runs the pipeline. So the
 * workers only store their fraction done, and the calling thread wakes a few times a second to
 * report the mean and to pass an abort on. Each task writes its own result slot, so the results
 * never depend on the number of workers or on which one ran a task.
 */
#ifndef amConcurrentTasks_h
#define amConcurrentTasks_h

#include "AnatomeshFiltersCoreModule.h" // export macro

#include <atomic>
#include <cstddef>
#include <functional>

class ANATOMESHFILTERSCORE_EXPORT amConcurrentTasks
{
public:
  /// Task i: sets 'fraction' (0..1) as it goes and stops early when 'abort' becomes true. It must
  /// not throw (an exception is caught and rethrown on the calling thread after every worker ends).
  using Task = std::function<void(std::size_t i, std::atomic<double>& fraction, const std::atomic<bool>& abort)>;

  /// Runs tasks 0..count-1 on up to 'workers' threads (0: one per core, never more than count).
  /// 'progress' (may be empty) is told the mean fraction on the calling thread; 'abort' (may be
  /// empty) is asked there too, and once it says yes every task sees its abort flag set.
  static void Run(std::size_t count, int workers, const Task& task, const std::function<void(double)>& progress,
    const std::function<bool()>& abort);
};

#endif
