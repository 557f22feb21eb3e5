// The one-machine task distribution: `jobs` forked worker processes. Each worker reads a
// task index from its pipe, runs it in-process and writes the record back; the parent
// polls the result pipes and hands the next index to whichever worker answered (dynamic
// scheduling). A worker that dies (a signal: segmentation fault, abort, OOM kill) is seen
// as end-of-file on its result pipe; its task is recorded as crashed and a fresh worker
// takes its place. Workers are forked before the parent uses HDF5 (the library keeps
// global state that a fork would copy half-used).
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <stdexcept>

#include "app/sweep/task_distribution.hpp"

namespace heavesim {
namespace {

bool write_all(int fd, const void* data, std::size_t size) {
  const char* bytes = static_cast<const char*>(data);
  while (size > 0) {
    const ssize_t written = ::write(fd, bytes, size);
    if (written < 0 && errno == EINTR) continue;
    if (written <= 0) return false;
    bytes += written;
    size -= static_cast<std::size_t>(written);
  }
  return true;
}

bool read_all(int fd, void* data, std::size_t size) {
  char* bytes = static_cast<char*>(data);
  while (size > 0) {
    const ssize_t got = ::read(fd, bytes, size);
    if (got < 0 && errno == EINTR) continue;
    if (got <= 0) return false;
    bytes += got;
    size -= static_cast<std::size_t>(got);
  }
  return true;
}

struct Worker {
  pid_t pid = -1;
  int task_fd = -1;    // parent writes task indices
  int result_fd = -1;  // parent reads records
  int task = -1;       // the task it runs, -1 when idle
};

class ProcessPool final : public TaskDistribution {
 public:
  explicit ProcessPool(int jobs) : jobs_(jobs) {}

  std::vector<std::optional<std::string>> run(int count, const TaskCallbacks& callbacks) override {
    std::vector<std::optional<std::string>> records(static_cast<std::size_t>(count));
    std::vector<Worker> workers(static_cast<std::size_t>(std::min(jobs_, std::max(count, 1))));
    int next = 0;
    // A write to the pipe of a worker that has just died must fail (EPIPE), not kill the sweep.
    struct sigaction ignore {}, previous {};
    ignore.sa_handler = SIG_IGN;
    ::sigaction(SIGPIPE, &ignore, &previous);
    for (std::size_t w = 0; w < workers.size(); ++w) spawn(workers, w, callbacks);
    for (Worker& worker : workers) hand_out(worker, next, count, callbacks);

    bool forwarded = false;
    for (;;) {
      std::vector<pollfd> polled;
      std::vector<std::size_t> owner;
      for (std::size_t w = 0; w < workers.size(); ++w)
        if (workers[w].task >= 0) {
          polled.push_back({workers[w].result_fd, POLLIN, 0});
          owner.push_back(w);
        }
      if (polled.empty()) break;
      if (callbacks.stop_requested() && !forwarded) {
        // A SIGTERM sent to the sweep alone reaches its workers too (Ctrl-C reaches the
        // whole process group anyway): each running case stops and closes its file.
        for (const Worker& worker : workers)
          if (worker.task >= 0) ::kill(worker.pid, SIGTERM);
        forwarded = true;
      }
      if (::poll(polled.data(), polled.size(), 200) < 0) {
        if (errno == EINTR) continue;
        throw std::runtime_error(std::string("poll: ") + std::strerror(errno));
      }
      for (std::size_t k = 0; k < polled.size(); ++k) {
        if (!(polled[k].revents & (POLLIN | POLLHUP | POLLERR))) continue;
        Worker& worker = workers[owner[k]];
        const int task = worker.task;
        std::uint64_t size = 0;
        std::string record;
        bool received = read_all(worker.result_fd, &size, sizeof size);
        if (received) {
          record.resize(size);
          received = read_all(worker.result_fd, record.data(), size);
        }
        if (received) {
          worker.task = -1;
        } else {
          // End of file: the worker died while running `task`.
          int status = 0;
          ::waitpid(worker.pid, &status, 0);
          const int signal = WIFSIGNALED(status) ? WTERMSIG(status) : 0;
          record = callbacks.crashed(task, static_cast<int>(owner[k]), signal);
          close_pipes(worker);
          worker.task = -1;
          spawn(workers, owner[k], callbacks);
        }
        records[static_cast<std::size_t>(task)] = record;
        callbacks.finished(task, record);
        hand_out(worker, next, count, callbacks);
      }
    }
    for (Worker& worker : workers) retire(worker);
    ::sigaction(SIGPIPE, &previous, nullptr);
    return records;
  }

  bool coordinator() const override { return true; }
  bool broadcast(bool value) override { return value; }
  int size() const override { return jobs_; }

 private:
  /// Gives `worker` the next task, or nothing when all are handed out or the sweep stops.
  void hand_out(Worker& worker, int& next, int count, const TaskCallbacks& callbacks) {
    if (next >= count || callbacks.stop_requested()) return;
    const std::int32_t index = next;
    if (!write_all(worker.task_fd, &index, sizeof index)) throw std::runtime_error("a sweep worker's task pipe closed");
    worker.task = next++;
  }

  static void spawn(std::vector<Worker>& workers, std::size_t number, const TaskCallbacks& callbacks) {
    Worker& worker = workers[number];
    int tasks[2], results[2];
    if (::pipe(tasks) != 0 || ::pipe(results) != 0) throw std::runtime_error(std::string("pipe: ") + std::strerror(errno));
    const pid_t pid = ::fork();
    if (pid < 0) throw std::runtime_error(std::string("fork: ") + std::strerror(errno));
    if (pid == 0) {
      ::close(tasks[1]);
      ::close(results[0]);
      // The other workers' pipes: a copy held here would keep them from seeing end-of-file.
      for (Worker& other : workers)
        if (&other != &worker) close_pipes(other);
      std::int32_t index = 0;
      while (read_all(tasks[0], &index, sizeof index)) {
        const std::string record = callbacks.run(index, static_cast<int>(number));
        const std::uint64_t size = record.size();
        if (!write_all(results[1], &size, sizeof size) || !write_all(results[1], record.data(), record.size())) break;
      }
      // No exit handlers or destructors of the parent's objects in the copy.
      ::_exit(0);
    }
    ::close(tasks[0]);
    ::close(results[1]);
    worker.pid = pid;
    worker.task_fd = tasks[1];
    worker.result_fd = results[0];
  }

  static void close_pipes(Worker& worker) {
    if (worker.task_fd >= 0) ::close(worker.task_fd);
    if (worker.result_fd >= 0) ::close(worker.result_fd);
    worker.task_fd = worker.result_fd = -1;
  }

  /// Closing the task pipe ends the worker's loop; then it is reaped.
  static void retire(Worker& worker) {
    close_pipes(worker);
    if (worker.pid > 0) {
      int status = 0;
      while (::waitpid(worker.pid, &status, 0) < 0 && errno == EINTR) {
      }
    }
    worker.pid = -1;
  }

  int jobs_;
};

}  // namespace

std::unique_ptr<TaskDistribution> make_process_pool(int jobs) { return std::make_unique<ProcessPool>(std::max(jobs, 1)); }

}  // namespace heavesim
