// for_each_index and for_each_index_in_order (kernel/math/two_thread_loop.hpp): every
// index once, on at most the threads asked for; the in-order then()s on the caller's
// thread, in order, overlapping the other thread's items; a failure stops the loop and
// reaches the caller.
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

TEST(TwoThreadLoop, ThenRunsOnTheCallersThreadInOrderAfterItsItem) {
  for (int threads : {1, 2}) {
    for (std::size_t count : {0u, 1u, 2u, 7u, 1000u}) {
      std::vector<std::size_t> values(count, 0);
      std::vector<std::size_t> order;
      bool all_on_caller = true;
      const std::thread::id caller = std::this_thread::get_id();
      for_each_index_in_order(
          count, threads, [&](std::size_t i) { values[i] = 3 * i + 1; },
          [&](std::size_t i) {
            all_on_caller = all_on_caller && std::this_thread::get_id() == caller;
            // The item's work is done and its data visible here.
            EXPECT_EQ(values[i], 3 * i + 1) << "index " << i;
            order.push_back(i);
          });
      EXPECT_TRUE(all_on_caller) << count << " items, " << threads << " threads";
      ASSERT_EQ(order.size(), count);
      for (std::size_t i = 0; i < count; ++i) EXPECT_EQ(order[i], i);
    }
  }
}

TEST(TwoThreadLoop, ThenOverlapsTheOtherThreadsItems) {
  // 100 items of 1 ms on two threads: ~50 ms. The first then() runs once item 0 is done,
  // while items remain; run after the loop, it would follow every item.
  std::atomic<std::size_t> finished{0};
  std::size_t finished_at_first_then = 0;
  for_each_index_in_order(
      100, 2,
      [&](std::size_t) {
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
        finished.fetch_add(1);
      },
      [&](std::size_t i) {
        if (i == 0) finished_at_first_then = finished.load();
      });
  EXPECT_EQ(finished.load(), 100u);
  EXPECT_LT(finished_at_first_then, 50u);
}

TEST(TwoThreadLoop, AFailingThenStopsTheLoopAndNoLaterThenRuns) {
  for (int threads : {1, 2}) {
    std::atomic<int> taken{0};
    std::vector<std::size_t> thens;
    try {
      for_each_index_in_order(
          200, threads,
          [&](std::size_t) {
            taken.fetch_add(1);
            std::this_thread::sleep_for(std::chrono::microseconds(200));
          },
          [&](std::size_t i) {
            thens.push_back(i);
            if (i == 3) throw std::runtime_error("then 3");
          });
      ADD_FAILURE() << "no exception";
    } catch (const std::runtime_error& error) {
      EXPECT_STREQ(error.what(), "then 3");
    }
    ASSERT_FALSE(thens.empty());
    EXPECT_EQ(thens.back(), 3u) << threads << " threads";
    EXPECT_LT(taken.load(), 200) << threads << " threads";
  }
}

TEST(TwoThreadLoop, AFailingItemOnEitherThreadStopsTheThens) {
  // The caller's own failing item: the thens before it may run, none from it on.
  for (int repeat = 0; repeat < 10; ++repeat) {
    std::vector<std::size_t> thens;
    EXPECT_THROW(for_each_index_in_order(
                     50, 1,
                     [&](std::size_t i) {
                       if (i == 17) throw std::invalid_argument("item 17");
                     },
                     [&](std::size_t i) { thens.push_back(i); }),
                 std::invalid_argument);
    ASSERT_EQ(thens.size(), 17u);  // one thread: then(i) follows work(i)
    EXPECT_EQ(thens.back(), 16u);
  }
  // The other thread's: the caller holds its first item until item 17 has failed there
  // (the other thread takes items in turn from the counter, so it reaches 17 while the
  // caller waits); the then()s of the items done before the caller took its own may have
  // run, none from 17 on (items up to 16 done, 17 marked done as it failed: without the
  // stop, the caller would run then(17) once its item is done), and item 17's exception
  // is the one thrown.
  const std::thread::id caller = std::this_thread::get_id();
  for (int repeat = 0; repeat < 10; ++repeat) {
    std::atomic<bool> failed_beside{false};
    bool caller_waited = false;
    std::vector<std::size_t> thens;
    try {
      for_each_index_in_order(
          50, 2,
          [&](std::size_t i) {
            if (std::this_thread::get_id() == caller) {
              if (caller_waited) return;
              caller_waited = true;
              const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(10);
              while (!failed_beside.load() && std::chrono::steady_clock::now() < give_up)
                std::this_thread::sleep_for(std::chrono::microseconds(100));
              return;
            }
            if (i == 17) {
              failed_beside.store(true);
              throw std::invalid_argument("item 17");
            }
          },
          [&](std::size_t i) { thens.push_back(i); });
      ADD_FAILURE() << "no exception";
    } catch (const std::invalid_argument& error) {
      EXPECT_STREQ(error.what(), "item 17");
    }
    EXPECT_TRUE(failed_beside.load()) << "repeat " << repeat << ": item 17 not on the other thread";
    for (std::size_t k = 0; k < thens.size(); ++k) EXPECT_EQ(thens[k], k) << "repeat " << repeat;
    EXPECT_LE(thens.size(), 17u) << "repeat " << repeat << ": a then() from the failed item on";
  }
}

}  // namespace
}  // namespace heavesim::test_two_thread_loop
