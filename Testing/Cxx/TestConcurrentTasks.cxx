#include "amConcurrentTasks.h"

#include <gtest/gtest.h>

#include <chrono>
#include <mutex>
#include <set>
#include <stdexcept>
#include <thread>
#include <vector>

TEST(ConcurrentTasks, EveryTaskOnceEachInItsSlotOnAnyNumberOfWorkers)
{
  for (int workers : { 0, 1, 2, 3, 8 })
  {
    std::vector<int> slot(7, 0);
    std::mutex mutex;
    std::set<std::thread::id> threads;
    amConcurrentTasks::Run(
      slot.size(), workers,
      [&](std::size_t i, std::atomic<double>& fraction, const std::atomic<bool>&) {
        {
          std::lock_guard<std::mutex> lock(mutex);
          threads.insert(std::this_thread::get_id());
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
        fraction = 0.5;
        slot[i] += static_cast<int>(i * i);
      },
      nullptr, nullptr);
    for (std::size_t i = 0; i < slot.size(); ++i)
      EXPECT_EQ(slot[i], static_cast<int>(i * i)) << workers << " workers";
    EXPECT_FALSE(threads.count(std::this_thread::get_id())) << "tasks run on worker threads";
    if (workers == 1)
      EXPECT_EQ(threads.size(), 1u);
    if (workers >= 2 && std::thread::hardware_concurrency() >= 2)
      EXPECT_GE(threads.size(), 2u) << workers << " workers";
  }
}

TEST(ConcurrentTasks, ProgressAndAbortOnTheCallingThread)
{
  const std::thread::id caller = std::this_thread::get_id();
  std::vector<double> reported;
  int asked = 0;
  std::atomic<int> aborted(0);
  amConcurrentTasks::Run(
    2, 2,
    [&](std::size_t, std::atomic<double>& fraction, const std::atomic<bool>& abort) {
      for (int step = 1; step <= 200 && !abort; ++step)
      {
        fraction = step / 200.0;
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
      }
      if (abort)
        ++aborted;
    },
    [&](double f) {
      EXPECT_EQ(std::this_thread::get_id(), caller);
      reported.push_back(f);
    },
    [&]() {
      EXPECT_EQ(std::this_thread::get_id(), caller);
      return ++asked >= 3; // abort after about 0.6 s of the tasks' 2 s
    });
  ASSERT_GE(reported.size(), 2u);
  for (std::size_t k = 1; k < reported.size(); ++k)
    EXPECT_GE(reported[k], reported[k - 1]);
  EXPECT_GT(reported.front(), 0.0);
  EXPECT_LT(reported[reported.size() - 2], 0.9) << "aborted well before the end";
  EXPECT_GE(asked, 3);
  EXPECT_EQ(aborted.load(), 2) << "both tasks see the abort";
}

TEST(ConcurrentTasks, ATaskExceptionReachesTheCallerAfterTheOthersEnd)
{
  std::vector<int> done(4, 0);
  EXPECT_THROW(amConcurrentTasks::Run(
                 done.size(), 2,
                 [&](std::size_t i, std::atomic<double>&, const std::atomic<bool>&) {
                   if (i == 1)
                     throw std::runtime_error("task 1");
                   done[i] = 1;
                 },
                 nullptr, nullptr),
    std::runtime_error);
  EXPECT_EQ(done, std::vector<int>({ 1, 0, 1, 1 }));
  amConcurrentTasks::Run(0, 2, nullptr, nullptr, nullptr); // nothing to run: no call
}
