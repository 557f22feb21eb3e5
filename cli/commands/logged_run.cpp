#include "cli/commands/logged_run.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>

#include <fmt/format.h>

#include "app/output/output_error.hpp"
#include "cli/commands/command_support.hpp"

namespace heavesim {
namespace {

/// Standard output and error sent to `path` while it lives (the run's log), then restored.
class CapturedOutput {
 public:
  explicit CapturedOutput(const std::string& path) {
    std::fflush(stdout);
    std::fflush(stderr);
    const int log = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (log < 0) throw OutputError(path, "cannot create the run log", std::strerror(errno));
    saved_out_ = ::dup(STDOUT_FILENO);
    saved_err_ = ::dup(STDERR_FILENO);
    ::dup2(log, STDOUT_FILENO);
    ::dup2(log, STDERR_FILENO);
    ::close(log);
  }
  ~CapturedOutput() {
    std::fflush(stdout);
    std::fflush(stderr);
    ::dup2(saved_out_, STDOUT_FILENO);
    ::dup2(saved_err_, STDERR_FILENO);
    ::close(saved_out_);
    ::close(saved_err_);
  }
  CapturedOutput(const CapturedOutput&) = delete;
  CapturedOutput& operator=(const CapturedOutput&) = delete;

 private:
  int saved_out_ = -1, saved_err_ = -1;
};

/// The last line of the log that reports an error ("heavesim: ..."), else its last line.
std::string last_error_line(const std::string& log_path) {
  std::ifstream in(log_path);
  std::string line, last, last_error;
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    last = line;
    if (line.rfind("heavesim:", 0) == 0) last_error = line;
  }
  return last_error.empty() ? last : last_error;
}

const char* status_of(int exit_code) {
  switch (exit_code) {
    case 0: return run_status::complete;
    case 2: return run_status::input_error;
    case 3: return run_status::numerical_failure;
    default: return StopSignals::received() ? run_status::stopped : run_status::error;
  }
}

}  // namespace

void run_logged(const RunOptions& options, const std::string& log_path, RunRecord& record) {
  RunOptions quiet = options;
  quiet.quiet = true;
  const auto start = std::chrono::steady_clock::now();
  {
    const CapturedOutput captured(log_path);
    record.exit_code = exit_code_reporting_errors([&] { return run_command(quiet); });
  }
  record.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  record.status = status_of(record.exit_code);
  if (record.exit_code != 0) record.message = last_error_line(log_path);
}

SweepProgress::SweepProgress(int count, bool enabled) : count_(count), enabled_(enabled && isatty(STDERR_FILENO)) {}

void SweepProgress::finished(const RunRecord& record) {
  ++done_;
  failed_ += record.status != run_status::complete;
  if (!enabled_) return;
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const double eta = wall * (count_ - done_) / done_;
  fmt::print(stderr, "\r  sweep: {} / {} runs ({} failed)   wall {:.1f} s   ETA {:.1f} s   ", done_, count_, failed_, wall,
             eta);
  shown_ = true;
}

void SweepProgress::clear() {
  if (shown_) fmt::print(stderr, "\r{:72}\r", "");
}

}  // namespace heavesim
