#pragma once
// One case run in this process as `heavesim run --quiet` would, its standard output and
// error captured in a log file: what a worker of `heavesim sweep` and `heavesim rao`
// does with each of its runs (app/sweep/task_distribution.hpp hands them out).
#include <chrono>
#include <string>

#include "app/sweep/run_record.hpp"
#include "cli/commands/commands.hpp"

namespace heavesim {

/// Runs `options` (quiet) with stdout and stderr sent to `log_path`, and fills `record`'s
/// exit_code, status, wall_time_s and, for a failed run, message (the log's last error line).
void run_logged(const RunOptions& options, const std::string& log_path, RunRecord& record);

/// Progress on stderr: runs finished of N, failures, wall time and ETA, one updating line
/// (only on a terminal).
class SweepProgress {
 public:
  SweepProgress(int count, bool enabled);
  void finished(const RunRecord& record);
  void clear();

 private:
  int count_, done_ = 0, failed_ = 0;
  bool enabled_, shown_ = false;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

}  // namespace heavesim
