// The recorder's block worker (app/output/background_worker.hpp): the job runs on another
// thread, wait() orders what it wrote before what the caller reads next, a job's exception
// reaches the caller once, and ending the worker waits for the run in hand.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <thread>
#include <vector>

#include "app/output/background_worker.hpp"

namespace heavesim {
namespace {

TEST(BackgroundWorker, RunsTheJobOnAnotherThreadAndWaitSeesItsWrites) {
  std::vector<double> block(4096);
  double sum = 0.0;
  std::thread::id job_thread;
  int runs = 0;
  BackgroundWorker worker([&] {
    job_thread = std::this_thread::get_id();
    std::this_thread::sleep_for(std::chrono::milliseconds(2));  // still running when start() returns
    for (double value : block) sum += value;
    ++runs;
  });
  double expected = 0.0;
  for (int round = 1; round <= 20; ++round) {
    for (std::size_t i = 0; i < block.size(); ++i) block[i] = round * 0.5 + static_cast<double>(i);
    for (double value : block) expected += value;
    worker.start();    // waits for the previous round, which read the block before this one
    if (round < 20) worker.wait();  // the caller may write the block again only after wait()
  }
  worker.wait();
  EXPECT_EQ(runs, 20);
  EXPECT_EQ(sum, expected);  // every value once, added in the same order
  EXPECT_NE(job_thread, std::this_thread::get_id());
}

TEST(BackgroundWorker, AJobsExceptionReachesTheCallerOnce) {
  std::atomic<int> runs = 0;
  BackgroundWorker worker([&] {
    if (++runs == 2) throw std::runtime_error("second run failed");
  });
  worker.start();
  EXPECT_NO_THROW(worker.wait());
  worker.start();
  EXPECT_THROW(worker.wait(), std::runtime_error);
  EXPECT_NO_THROW(worker.wait());  // reported once
  worker.start();
  EXPECT_NO_THROW(worker.wait());
  EXPECT_EQ(runs.load(), 3);
  runs = 1;
  worker.start();  // the second run again: it throws, and nobody waits for it
  EXPECT_THROW(worker.start(), std::runtime_error);  // the next start() reports it...
  EXPECT_EQ(runs.load(), 2);                         // ...and does not run the job
}

TEST(BackgroundWorker, EndingTheWorkerWaitsForTheRunInHand) {
  std::atomic<bool> finished = false;
  {
    BackgroundWorker worker([&] {
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
      finished = true;
    });
    worker.start();
  }
  EXPECT_TRUE(finished.load());
}

TEST(BackgroundWorker, AWorkerNeverStartedEndsAtOnce) {
  int runs = 0;
  { BackgroundWorker worker([&] { ++runs; }); }
  EXPECT_EQ(runs, 0);
}

}  // namespace
}  // namespace heavesim
