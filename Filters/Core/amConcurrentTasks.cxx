#include "amConcurrentTasks.h"

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

void amConcurrentTasks::Run(std::size_t count, int workers, const Task& task,
  const std::function<void(double)>& progress, const std::function<bool()>& abort)
{
  if (count == 0)
    return;
  const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
  const std::size_t threads =
    std::min<std::size_t>(count, workers > 0 ? static_cast<std::size_t>(workers) : static_cast<std::size_t>(cores));
  std::unique_ptr<std::atomic<double>[]> fractions(new std::atomic<double>[count]);
  for (std::size_t i = 0; i < count; ++i)
    fractions[i] = 0.0;
  std::atomic<bool> stop(false);
  std::atomic<std::size_t> next(0);
  std::vector<std::exception_ptr> errors(count);
  std::mutex mutex;
  std::condition_variable finished;
  std::size_t running = threads;

  auto work = [&]() {
    for (std::size_t i = next++; i < count; i = next++)
    {
      try
      {
        task(i, fractions[i], stop);
      }
      catch (...)
      {
        errors[i] = std::current_exception();
      }
      fractions[i] = 1.0;
    }
    std::lock_guard<std::mutex> lock(mutex);
    --running;
    finished.notify_all();
  };
  std::vector<std::thread> pool;
  pool.reserve(threads);
  for (std::size_t t = 0; t < threads; ++t)
    pool.emplace_back(work);

  std::unique_lock<std::mutex> lock(mutex);
  while (running > 0)
  {
    finished.wait_for(lock, std::chrono::milliseconds(200), [&]() { return running == 0; });
    lock.unlock();
    if (abort && !stop && abort())
      stop = true;
    if (progress)
    {
      double sum = 0.0;
      for (std::size_t i = 0; i < count; ++i)
        sum += std::min(1.0, std::max(0.0, fractions[i].load()));
      progress(sum / static_cast<double>(count));
    }
    lock.lock();
  }
  lock.unlock();
  for (std::thread& t : pool)
    t.join();
  for (const std::exception_ptr& e : errors)
    if (e)
      std::rethrow_exception(e);
}
