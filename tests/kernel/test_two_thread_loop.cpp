// for_each_index_on_two_threads (kernel/math/two_thread_loop.hpp): every index once, on
// up to two threads; a failure stops the loop and reaches the caller.
#include <gtest/gtest.h>

#include <atomic>
#include <mutex>
#include <set>
#include <stdexcept>
#include <thread>
#include <vector>

#include "kernel/math/two_thread_loop.hpp"

namespace heavesim::test_two_thread_loop {
namespace {

TEST(TwoThreadLoop, EveryIndexOnceOnAtMostTwoThreads) {
  for (std::size_t count : {0u, 1u, 2u, 7u, 1000u}) {
    std::vector<std::atomic<int>> visits(count);
    std::mutex mutex;
    std::set<std::thread::id> threads;
    for_each_index_on_two_threads(count, [&](std::size_t i) {
      visits[i].fetch_add(1);
      const std::lock_guard lock(mutex);
      threads.insert(std::this_thread::get_id());
    });
    for (std::size_t i = 0; i < count; ++i) EXPECT_EQ(visits[i].load(), 1) << "index " << i << " of " << count;
    EXPECT_LE(threads.size(), 2u);
    // One item is the caller's own: no second thread for it.
    if (count == 1) {
      EXPECT_EQ(*threads.begin(), std::this_thread::get_id());
    }
  }
}

TEST(TwoThreadLoop, AFailureOnEitherThreadReachesTheCallerAndStopsTheLoop) {
  // Every item fails: whichever thread takes the first one throws, and the other takes
  // at most the one it already had.
  for (int repeat = 0; repeat < 20; ++repeat) {
    std::atomic<int> started{0};
    EXPECT_THROW(for_each_index_on_two_threads(1000,
                                               [&](std::size_t i) {
                                                 started.fetch_add(1);
                                                 throw std::runtime_error("item " + std::to_string(i));
                                               }),
                 std::runtime_error);
    EXPECT_LE(started.load(), 2);
  }
  // One item of many fails: its message is the one thrown, and no item after the
  // failure's is taken by the thread that failed.
  try {
    for_each_index_on_two_threads(50, [&](std::size_t i) {
      if (i == 17) throw std::invalid_argument("item 17");
    });
    ADD_FAILURE() << "no exception";
  } catch (const std::invalid_argument& error) {
    EXPECT_STREQ(error.what(), "item 17");
  }
}

}  // namespace
}  // namespace heavesim::test_two_thread_loop
