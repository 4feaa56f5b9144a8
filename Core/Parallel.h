// Parallel.h: a deterministic parallel loop for the core (no VTK, no OpenMP).
#ifndef quadcover_Parallel_h
#define quadcover_Parallel_h

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <cstdlib>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace quadcover
{
/// Number of worker threads the core uses: QUADCOVER_NUM_THREADS if set (>= 1), else the
/// hardware concurrency.
inline int defaultThreadCount()
{
  if (const char* env = std::getenv("QUADCOVER_NUM_THREADS"))
  {
    const int n = std::atoi(env);
    if (n >= 1)
    {
      return n;
    }
  }
  const unsigned hw = std::thread::hardware_concurrency();
  return hw == 0 ? 1 : static_cast<int>(hw);
}

/// The worker threads asked for: numThreads, or defaultThreadCount() when it is 0 or less.
inline int threadCount(int numThreads)
{
  return numThreads > 0 ? numThreads : defaultThreadCount();
}

/// Calls first() and second(), on two threads when numThreads (0: defaultThreadCount()) is
/// above 1; both have returned when it returns. An exception in either is rethrown (the first's
/// when both throw).
template<typename First, typename Second>
void runBoth(First&& first, Second&& second, int numThreads)
{
  if (threadCount(numThreads) == 1)
  {
    first();
    second();
    return;
  }
  std::exception_ptr failed;
  std::thread worker([&second, &failed]() {
    try
    {
      second();
    }
    catch (...)
    {
      failed = std::current_exception();
    }
  });
  try
  {
    first();
  }
  catch (...)
  {
    worker.join();
    throw;
  }
  worker.join();
  if (failed)
  {
    std::rethrow_exception(failed);
  }
}

/// runBoth(first, second), except that on two threads, once first has returned, this thread
/// calls report() every 10 ms until second has returned (and returns as soon as it has): the
/// calling thread's progress reports, and the cancel they may throw, go on while the other
/// thread works. An exception from first or report is rethrown once second has returned (they
/// should tell second to stop first). On one thread: first(), then second().
template<typename First, typename Second, typename Report>
void runBothReporting(First&& first, Second&& second, Report&& report, int numThreads)
{
  if (threadCount(numThreads) == 1)
  {
    first();
    second();
    return;
  }
  bool ended = false; // under mutex
  std::mutex mutex;
  std::condition_variable wake;
  runBoth(
    [&]() {
      first();
      std::unique_lock<std::mutex> lock(mutex);
      while (!wake.wait_for(lock, std::chrono::milliseconds(10), [&]() { return ended; }))
      {
        lock.unlock();
        report();
        lock.lock();
      }
    },
    [&]() {
      struct End // also when second throws: the first thread must not wait for ever
      {
        bool& ended;
        std::mutex& mutex;
        std::condition_variable& wake;
        ~End()
        {
          {
            const std::lock_guard<std::mutex> lock(mutex);
            ended = true;
          }
          wake.notify_one();
        }
      } end{ ended, mutex, wake };
      second();
    },
    numThreads);
}

/// Calls body(begin, end, threadIndex) on contiguous blocks covering [0, n). Each index is
/// visited exactly once; as long as body writes only to its own indices the result does not
/// depend on the number of threads.
template<typename Body>
void parallelFor(int n, int numThreads, Body&& body)
{
  numThreads = threadCount(numThreads);
  const int minBlock = 2048;
  numThreads = std::max(1, std::min(numThreads, (n + minBlock - 1) / minBlock));
  if (numThreads == 1)
  {
    body(0, n, 0);
    return;
  }
  std::vector<std::thread> workers;
  workers.reserve(numThreads - 1);
  const int block = (n + numThreads - 1) / numThreads;
  for (int t = 1; t < numThreads; ++t)
  {
    const int b = std::min(n, t * block);
    const int e = std::min(n, b + block);
    workers.emplace_back([&body, b, e, t]() { body(b, e, t); });
  }
  body(0, std::min(n, block), 0);
  for (auto& w : workers)
  {
    w.join();
  }
}
}

#endif
