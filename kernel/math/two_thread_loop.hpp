#pragma once
// A loop over independent items on the calling thread and at most one more, for work that
// runs when nothing else does and would otherwise leave a second core idle: the end of a
// run's statistics (app/output/recorder.cpp: the channels' spectra, cycle counts and
// extreme-value fits) and a radiation memory's realisations before the run
// (hydro/elements/element_factories.cpp: a symmetric eigenproblem per mode pair).
#include <sched.h>

#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <exception>
#include <mutex>
#include <system_error>
#include <thread>
#include <utility>
#include <vector>

namespace heavesim {

/// The cores this process may run on: its affinity mask (a run pinned to one core, by
/// `taskset` or a cluster's scheduler, has no second core), else the machine's.
inline int usable_cores() {
  cpu_set_t cores;
  if (sched_getaffinity(0, sizeof cores, &cores) == 0) return CPU_COUNT(&cores);
  return static_cast<int>(std::thread::hardware_concurrency());
}

/// Calls work(i) once for every i in [0, count), and then(i) after it: work(i) with
/// `threads` = 2 on the calling thread and one more, which take the indices in turn from
/// one counter (a costly item does not leave the other thread idle); with 1, or when
/// count < 2 or no thread can be had, all on the caller's. then(i) always runs on the
/// calling thread, in index order, as soon as work(0 .. i) are done: the caller runs the
/// ready then()s between its own items, and waits only when the other thread holds the
/// next one. So a then() that must stay on one thread (a file's writes) overlaps the other
/// thread's work instead of following all of it. Each work(i) must touch only item i's
/// data; then(i) runs while the other thread may be in a work(j), so it may touch item i's
/// data and what no work() touches. A failure (of a work on either thread, or of a then)
/// stops both threads from taking more items (each finishes the one in hand), and no
/// then() starts once it is recorded: the then()s of items done before it may not run
/// either (a then() already started runs to its end). The caller's failure is thrown, else
/// the other thread's: with several failing items, which one is reported depends on the
/// threads' timing.
template <typename Work, typename Then>
void for_each_index_in_order(std::size_t count, int threads, Work&& work, Then&& then) {
  std::atomic<std::size_t> next{0};
  // Which items are done and whether a failure stopped the loop, under the mutex, every
  // notification sent with it held: a race detector sees each hand-over whole, and
  // then(i) sees what work(i) wrote (tests/scripts/test_threads.py runs a drilling case,
  // whose end of run is this loop, under Helgrind, which does not follow atomics' orders).
  std::mutex mutex;
  std::condition_variable changed;
  std::vector<char> done(count, 0);
  bool stopped = false;
  const auto stop = [&] {  // under the mutex
    stopped = true;
    next.store(count);  // neither thread takes another item
  };
  std::exception_ptr helper_failure;
  std::thread helper;
  if (threads >= 2 && count > 1) {
    try {
      helper = std::thread([&] {
        for (std::size_t i = next.fetch_add(1); i < count; i = next.fetch_add(1)) {
          try {
            work(i);
          } catch (...) {
            helper_failure = std::current_exception();  // read by the caller after the join
          }
          const std::lock_guard lock(mutex);
          done[i] = 1;
          if (helper_failure) stop();
          changed.notify_all();
        }
      });
    } catch (const std::system_error&) {
      // No second thread to be had: the caller takes every item.
    }
  }
  std::exception_ptr own_failure;
  try {
    std::size_t next_then = 0;
    std::unique_lock lock(mutex);
    for (;;) {
      while (!stopped && next_then < count && done[next_then] != 0) {
        const std::size_t i = next_then++;
        lock.unlock();
        then(i);
        lock.lock();
      }
      if (stopped || next_then == count) break;
      lock.unlock();
      const std::size_t i = next.fetch_add(1);
      if (i < count) {
        work(i);
        lock.lock();
        done[i] = 1;
        continue;
      }
      lock.lock();
      // Nothing left to take: the next then() waits for the item the other thread holds.
      changed.wait(lock, [&] { return stopped || done[next_then] != 0; });
    }
  } catch (...) {
    own_failure = std::current_exception();
    const std::lock_guard lock(mutex);
    stop();
  }
  if (helper.joinable()) helper.join();
  if (own_failure) std::rethrow_exception(own_failure);
  if (helper_failure) std::rethrow_exception(helper_failure);
}

/// for_each_index_in_order with nothing to do after each item.
template <typename Work>
void for_each_index(std::size_t count, int threads, Work&& work) {
  for_each_index_in_order(count, threads, std::forward<Work>(work), [](std::size_t) {});
}

}  // namespace heavesim
