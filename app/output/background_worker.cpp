#include "app/output/background_worker.hpp"

#include <system_error>
#include <utility>

namespace heavesim {

// Every notification is sent with the mutex held: the woken thread then waits for the
// mutex a moment (once per block), but a race detector sees the handshake whole
// (Helgrind calls a signal without the lock "dubious" and cannot order what follows it;
// tests/scripts/test_threads.py).
BackgroundWorker::~BackgroundWorker() {
  {
    std::unique_lock<std::mutex> lock(mutex_);
    settle(lock);
    stopping_ = true;
    changed_.notify_all();
  }
  if (thread_.joinable()) thread_.join();
}

std::exception_ptr BackgroundWorker::settle(std::unique_lock<std::mutex>& lock) {
  changed_.wait(lock, [this] { return !running_; });
  return std::exchange(failure_, nullptr);
}

void BackgroundWorker::wait() {
  std::unique_lock<std::mutex> lock(mutex_);
  if (const std::exception_ptr failure = settle(lock)) std::rethrow_exception(failure);
}

bool BackgroundWorker::busy() {
  const std::lock_guard<std::mutex> lock(mutex_);
  return running_;
}

void BackgroundWorker::start() {
  std::unique_lock<std::mutex> lock(mutex_);
  if (const std::exception_ptr failure = settle(lock)) std::rethrow_exception(failure);
  if (!thread_.joinable()) {
    try {
      thread_ = std::thread([this] { loop(); });
    } catch (const std::system_error&) {
      lock.unlock();
      job_();  // no second thread to be had: the same work, in line
      return;
    }
  }
  running_ = true;
  changed_.notify_all();
}

void BackgroundWorker::loop() {
  std::unique_lock<std::mutex> lock(mutex_);
  for (;;) {
    changed_.wait(lock, [this] { return running_ || stopping_; });
    if (!running_) return;  // stopping, nothing in hand
    lock.unlock();
    std::exception_ptr failure;
    try {
      job_();
    } catch (...) {
      failure = std::current_exception();
    }
    lock.lock();
    failure_ = failure;
    running_ = false;
    changed_.notify_all();
  }
}

}  // namespace heavesim
