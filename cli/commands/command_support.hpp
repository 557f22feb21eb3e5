#pragma once
// What the commands that compute over time (run, kinematics) share: the progress line,
// stopping on SIGINT/SIGTERM with the result file closed, and the output directories.
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <csignal>
#include <functional>
#include <string>

#include <fmt/format.h>

#include "app/output/result_file.hpp"
#include "kernel/math/numerical_error.hpp"

namespace heavesim {

/// The signal that asked the current command to stop (0: none).
std::atomic<int>& stop_signal_value();
extern "C" void request_stop_signal(int signal);


/// Progress on stderr (simulated time, wall time, ETA) once a run takes over 1 s.
class ProgressLine {
 public:
  ProgressLine(double t_start, double t_end, bool enabled)
      : t_start_(t_start), t_end_(t_end), enabled_(enabled && isatty(STDERR_FILENO)),
        start_(std::chrono::steady_clock::now()) {}
  void update(double t) {
    if (!enabled_) return;
    const double wall = elapsed();
    if (wall < 1.0 || wall - last_shown_ < 0.2) return;
    last_shown_ = wall;
    const double fraction = (t - t_start_) / (t_end_ - t_start_);
    const double eta = fraction > 0.0 ? wall * (1.0 - fraction) / fraction : 0.0;
    fmt::print(stderr, "\r  t = {:.2f} / {:.2f} s   wall {:.1f} s   ETA {:.1f} s   ", t, t_end_, wall, eta);
    shown_ = true;
  }
  void clear() {
    if (shown_) fmt::print(stderr, "\r{:60}\r", "");
  }
  double elapsed() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }

 private:
  double t_start_, t_end_;
  bool enabled_;
  std::chrono::steady_clock::time_point start_;
  double last_shown_ = 0.0;
  bool shown_ = false;
};

/// SIGINT and SIGTERM ask the run to stop (it then closes its file, complete = 0) from
/// the first instruction of `run` on: a signal while the case loads or the scene is built
/// stops before the run, with nothing written. SIGXFSZ is ignored so that a file growing
/// past the file-size limit (ulimit -f) fails its write with EFBIG, reported like a full
/// disk, instead of killing the process. The previous dispositions come back at the end.
class StopSignals {
 public:
  StopSignals() {
    stop_signal_value() = 0;
    previous_int_ = std::signal(SIGINT, request_stop_signal);
    previous_term_ = std::signal(SIGTERM, request_stop_signal);
    previous_file_size_ = std::signal(SIGXFSZ, SIG_IGN);
  }
  ~StopSignals() {
    std::signal(SIGINT, previous_int_);
    std::signal(SIGTERM, previous_term_);
    std::signal(SIGXFSZ, previous_file_size_);
  }
  StopSignals(const StopSignals&) = delete;
  StopSignals& operator=(const StopSignals&) = delete;
  static int received() { return stop_signal_value(); }

 private:
  void (*previous_int_)(int) = SIG_DFL;
  void (*previous_term_)(int) = SIG_DFL;
  void (*previous_file_size_)(int) = SIG_DFL;
};

/// Runs a command and turns what it throws into the product's exit codes and messages:
/// InputError 2 ("heavesim: bad input: ..."), NumericalError 3 (time, suggestion), any
/// other exception 1. main() runs every command through it; the sweep runs each case so.
int exit_code_reporting_errors(const std::function<int()>& command);

/// "stopped by signal N before the run of case ... started"; returns exit code 1.
int stopped_before_the_run(const std::string& case_name);

/// The directory of `path`, created if missing; an OutputError (exit 1) if it cannot be.
void create_parent_directory(const std::string& path, const char* what);

/// Marks `file` as failed by `error`: root attributes failure_time, failure and
/// failure_suggestion (docs/result-file.md).
void record_failure(ResultFile& file, const NumericalError& error);

/// A command's result file: `requested` (-o), else results/<case name><suffix>.h5, with
/// its directory created: a result that cannot be written is known before any work.
std::string prepare_result_path(const std::string& requested, const std::string& case_name,
                                const std::string& suffix = "");

}  // namespace heavesim
