#pragma once
// A loop over independent items on the calling thread and at most one more, for work that
// runs when nothing else does and would otherwise leave a second core idle: the end of a
// run's statistics (app/output/recorder.cpp: the channels' spectra, cycle counts and
// extreme-value fits) and a radiation memory's realisations before the run
// (hydro/elements/element_factories.cpp: a symmetric eigenproblem per mode pair).
#include <sched.h>

#include <atomic>
#include <cstddef>
#include <exception>
#include <system_error>
#include <thread>

namespace heavesim {

/// The cores this process may run on: its affinity mask (a run pinned to one core, by
/// `taskset` or a cluster's scheduler, has no second core), else the machine's.
inline int usable_cores() {
  cpu_set_t cores;
  if (sched_getaffinity(0, sizeof cores, &cores) == 0) return CPU_COUNT(&cores);
  return static_cast<int>(std::thread::hardware_concurrency());
}

/// Calls work(i) once for every i in [0, count): with `threads` = 2 on the calling thread
/// and one more, which take the indices in turn from one counter (a costly item does not
/// leave the other thread idle); with 1, or when count < 2 or no thread can be had, all
/// on the caller's. Each item's work must touch only that item's data. A failure stops
/// both threads from taking more items (each finishes the one in hand); the caller's
/// failure is thrown, else the other thread's: with several failing items, which one is
/// reported depends on the threads' timing.
template <typename Work>
void for_each_index(std::size_t count, int threads, Work&& work) {
  std::atomic<std::size_t> next{0};
  auto take_items = [&] {
    for (std::size_t i = next.fetch_add(1); i < count; i = next.fetch_add(1)) {
      try {
        work(i);
      } catch (...) {
        next.store(count);  // neither thread takes another item
        throw;
      }
    }
  };
  std::exception_ptr helper_failure;
  std::thread helper;
  if (threads >= 2 && count > 1) {
    try {
      helper = std::thread([&] {
        try {
          take_items();
        } catch (...) {
          helper_failure = std::current_exception();
        }
      });
    } catch (const std::system_error&) {
      // No second thread to be had: the caller takes every item.
    }
  }
  std::exception_ptr own_failure;
  try {
    take_items();
  } catch (...) {
    own_failure = std::current_exception();
  }
  if (helper.joinable()) helper.join();
  if (own_failure) std::rethrow_exception(own_failure);
  if (helper_failure) std::rethrow_exception(helper_failure);
}

}  // namespace heavesim
