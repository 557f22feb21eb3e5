#pragma once
// What the index keeps of one run: how it ended, where its files are, and the quantities
// read back from its result file (every scalar of /summary, the response statistics of
// the sweep's channels). A worker fills it and sends it to the coordinator as bytes.
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace heavesim {

/// A run's status in the index (docs/sweeps.md).
namespace run_status {
inline constexpr const char* pending = "pending";                      // not run (the sweep was stopped first)
inline constexpr const char* complete = "complete";                    // exit 0, complete = 1
inline constexpr const char* input_error = "input_error";              // exit 2
inline constexpr const char* numerical_failure = "numerical_failure";  // exit 3
inline constexpr const char* stopped = "stopped";                      // exit 1 after SIGINT/SIGTERM
inline constexpr const char* error = "error";                          // exit 1 otherwise (a write that failed)
inline constexpr const char* crashed = "crashed";                      // killed by a signal
}  // namespace run_status

struct ChannelStatistic {
  std::string channel;         // /joints/td_string/reaction_force
  std::string field;           // a name of stats::statistic_fields()
  std::string unit;            // of the field
  std::vector<double> columns; // one value per column of the channel
};

struct RunRecord {
  static constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  std::string status = run_status::pending;
  int exit_code = -1;
  double wall_time_s = nan;
  std::string result_file;  // relative to the sweep directory
  std::string hash;
  std::string message;      // the last error line of the run's log; empty when complete
  int rank_or_worker = -1;
  bool reused = false;      // a resumed sweep found it complete (not written to the index)
  std::vector<std::pair<std::string, double>> summary;  // /summary's scalar numeric attributes
  std::vector<ChannelStatistic> statistics;
};

/// The record as bytes (for a pipe or MPI) and back.
std::string encode(const RunRecord& record);
RunRecord decode(const std::string& bytes);

/// Whether `result_path` holds a complete run (complete = 1) of the case whose run hash is `hash`.
bool result_is_current(const std::string& result_path, const std::string& hash);

/// Fills `record`'s summary and statistics from a result file: every scalar numeric
/// attribute of /summary, and for each of `channels` the response statistics of its
/// evaluation window (statistics_window_start on) with the most probable maxima over
/// `duration` s, by the same code as the recorder and `heavesim stats`. A channel the
/// file lacks is left out (NaN in the index).
void read_result_quantities(const std::string& result_path, const std::vector<std::string>& channels, double duration,
                            RunRecord& record);

}  // namespace heavesim
