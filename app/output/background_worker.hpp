#pragma once
// One fixed job run on a second thread, one run at a time: the result file's block writes
// and the recorder's block statistics (moments, Welch spectra, cycle counts of ~200
// columns) go to one each while the integration and the next block's samples go on
// (docs/performance.md, "Recording on two cores"); the result file's release of the file
// it replaces runs once on another.
//
// The caller hands the job its data before start() and does not touch them again until
// wait() has returned (the mutex orders the two threads' accesses). The thread starts with
// the first start() and ends with the worker; if it cannot be started (the system's thread
// limit), start() runs the job on the caller's thread. A job's exception is kept and
// thrown by the next wait() or start().
#include <condition_variable>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>

namespace heavesim {

class BackgroundWorker {
 public:
  explicit BackgroundWorker(std::function<void()> job) : job_(std::move(job)) {}
  /// Waits for a run in hand and ends the thread; reports nothing (call wait() for that).
  ~BackgroundWorker();
  BackgroundWorker(const BackgroundWorker&) = delete;
  BackgroundWorker& operator=(const BackgroundWorker&) = delete;

  /// Waits for the previous run (throwing what it threw), then runs the job once more.
  void start();
  /// Returns when no run is in hand; throws what the last run threw (once).
  void wait();
  /// Whether a run is in hand (started, not yet finished): a glance that does not wait,
  /// for a caller that has other work to do meanwhile.
  bool busy();

 private:
  void loop();
  /// Waits under `lock` until no run is in hand; the kept exception, if any, is taken.
  std::exception_ptr settle(std::unique_lock<std::mutex>& lock);

  std::function<void()> job_;
  std::mutex mutex_;
  std::condition_variable changed_;
  bool running_ = false, stopping_ = false;
  std::exception_ptr failure_;
  std::thread thread_;
};

}  // namespace heavesim
