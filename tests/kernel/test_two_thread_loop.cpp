// for_each_index (kernel/math/two_thread_loop.hpp): every index once, on at most the
// threads asked for; a failure stops the loop and reaches the caller.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <mutex>
#include <set>
#include <stdexcept>
#include <thread>
#include <vector>

#include "kernel/math/two_thread_loop.hpp"

namespace heavesim::test_two_thread_loop {
namespace {

TEST(TwoThreadLoop, EveryIndexOnceOnAtMostTheThreadsAskedFor) {
  for (int threads : {1, 2}) {
    for (std::size_t count : {0u, 1u, 2u, 7u, 1000u}) {
      std::vector<std::atomic<int>> visits(count);
      std::mutex mutex;
      std::set<std::thread::id> seen;
      for_each_index(count, threads, [&](std::size_t i) {
        visits[i].fetch_add(1);
        const std::lock_guard lock(mutex);
        seen.insert(std::this_thread::get_id());
      });
      for (std::size_t i = 0; i < count; ++i)
        EXPECT_EQ(visits[i].load(), 1) << "index " << i << " of " << count << ", " << threads << " threads";
      EXPECT_LE(seen.size(), static_cast<std::size_t>(threads));
      // One thread asked for, or one item: all on the caller's thread.
      if ((threads == 1 || count == 1) && count > 0) {
        EXPECT_EQ(seen.size(), 1u);
        EXPECT_EQ(*seen.begin(), std::this_thread::get_id());
      }
    }
  }
}

TEST(TwoThreadLoop, AFailureStopsBothThreadsAndReachesTheCaller) {
  // The first item taken fails; every other item takes 1 ms. Without the stop the other
  // thread would go on through the 200 items (~0.2 s); with it, it finishes the one in hand.
  for (int repeat = 0; repeat < 10; ++repeat) {
    std::atomic<int> taken{0};
    EXPECT_THROW(for_each_index(200, 2,
                                [&](std::size_t) {
                                  if (taken.fetch_add(1) == 0) throw std::runtime_error("first item");
                                  std::this_thread::sleep_for(std::chrono::milliseconds(1));
                                }),
                 std::runtime_error);
    EXPECT_LE(taken.load(), 3) << "repeat " << repeat;
  }
  // Whichever thread takes it, the failing item's exception is the one thrown.
  for (int repeat = 0; repeat < 10; ++repeat) {
    try {
      for_each_index(50, 2, [&](std::size_t i) {
        if (i == 17) throw std::invalid_argument("item 17");
      });
      ADD_FAILURE() << "no exception";
    } catch (const std::invalid_argument& error) {
      EXPECT_STREQ(error.what(), "item 17");
    }
  }
}

}  // namespace
}  // namespace heavesim::test_two_thread_loop
