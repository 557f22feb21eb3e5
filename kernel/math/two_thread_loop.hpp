#pragma once
// A loop over independent items on the calling thread and one more, for work that runs
// when nothing else does and would otherwise leave the second core idle: the end of a
// run's statistics (app/output/recorder.cpp: the channels' spectra, cycle counts and
// extreme-value fits) and a radiation memory's realisations before the run
// (hydro/elements/element_factories.cpp: a symmetric eigenproblem per mode pair).
#include <atomic>
#include <cstddef>
#include <exception>
#include <system_error>
#include <thread>

namespace heavesim {

/// Calls work(i) once for every i in [0, count). The two threads take the indices in
/// turn from one counter, so a costly item does not leave the other thread idle; each
/// item's work must touch only that item's data. In line when count < 2 or no thread can
/// be had. A failure stops both threads from taking more items; the caller's is thrown,
/// else the other thread's.
template <typename Work>
void for_each_index_on_two_threads(std::size_t count, Work&& work) {
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
  if (count > 1) {
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
