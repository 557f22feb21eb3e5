// heavesim sweep: read a sweep file, check every resolved case, run them in worker
// processes (-j N) or MPI ranks (under mpirun), each through run_command exactly as
// `heavesim run` would (in-process, quiet, its output captured in DIR/logs/<run>.log),
// and write the index (docs/sweeps.md).
#include <filesystem>
#include <string>

#include <fmt/format.h>

#include "app/case/case_definition.hpp"
#include "app/output/output_error.hpp"
#include "app/scene/scene.hpp"
#include "app/sweep/run_record.hpp"
#include "app/sweep/sweep_index.hpp"
#include "app/sweep/sweep_plan.hpp"
#include "app/sweep/task_distribution.hpp"
#include "cli/commands/command_support.hpp"
#include "cli/commands/commands.hpp"
#include "cli/commands/logged_run.hpp"
#include "io/hdf5/hdf5_handle.hpp"

namespace heavesim {
namespace {

/// Checks `run`'s case as `heavesim check` would (load, build the scene); "" when good,
/// else the message, placed in the sweep file where the offending value is written.
std::string check_run(const SweepPlan& plan, const PlannedRun& run) {
  try {
    const CaseDefinition definition = load_case(run.base_case, run.overrides());
    build_scene(definition);
  } catch (const InputError& error) {
    return error_in_sweep(run, plan.columns, error).what();
  } catch (const std::exception&) {
    // Anything else (an assembly that fails numerically) is the run's own failure: it is
    // recorded when the run meets it.
  }
  return "";
}

RunRecord execute_run(const SweepDefinition& sweep, const PlannedRun& run, const std::string& directory, bool resume,
                      bool side_by_side, int worker) {
  RunRecord record;
  record.result_file = "runs/" + run.name + ".h5";
  record.hash = run.hash;
  record.rank_or_worker = worker;
  const std::string result_path = (std::filesystem::path(directory) / record.result_file).string();
  if (resume && result_is_current(result_path, run.hash)) {
    record.status = run_status::complete;
    record.exit_code = 0;
    record.reused = true;
    read_result_quantities(result_path, sweep.statistics, sweep.duration, record);
    for (const auto& [name, value] : record.summary)
      if (name == "wall_time_s") record.wall_time_s = value;
    return record;
  }
  const std::string log_path = (std::filesystem::path(directory) / "logs" / (run.name + ".log")).string();
  RunOptions options;
  options.case_path = run.base_case;
  options.output_path = result_path;
  options.overrides = run.overrides();
  options.samples_beside = !side_by_side;
  run_logged(options, log_path, record);
  if (record.exit_code == 0) {
    try {
      read_result_quantities(result_path, sweep.statistics, sweep.duration, record);
    } catch (const std::exception& error) {
      record.message = std::string("the result file could not be read back: ") + error.what();
    }
  }
  return record;
}

}  // namespace

int sweep_command(const SweepOptions& options) {
  // Before anything touches HDF5 (workers fork first; the index is written last).
  hdf5::skip_library_exit_cleanup();
  const std::unique_ptr<TaskDistribution> distribution =
      started_by_mpirun() ? make_mpi_distribution() : make_process_pool(options.jobs);
  const bool coordinator = distribution->coordinator();
  SweepDefinition sweep;
  SweepPlan plan;
  try {
    sweep = read_sweep_file(options.sweep_path);
    plan = make_plan(sweep);
  } catch (const InputError&) {
    if (!coordinator) return 2;  // rank 0 reports it
    throw;
  }
  const int count = static_cast<int>(plan.runs.size());
  const std::string directory = options.output_directory.empty()
                                    ? "results/" + std::filesystem::path(options.sweep_path).stem().string()
                                    : options.output_directory;
  for (const char* folder : {"runs", "logs"}) {
    std::error_code error;
    std::filesystem::create_directories(std::filesystem::path(directory) / folder, error);
    if (error) throw OutputError(directory, "cannot create the sweep directory", error.message());
  }
  const StopSignals signals;
  const auto stop_requested = [] { return StopSignals::received() != 0; };

  // 1. Every resolved case checked before the first run: bad input is exit 2 up front.
  TaskCallbacks check;
  check.run = [&](int index, int) { return check_run(plan, plan.runs[static_cast<std::size_t>(index)]); };
  check.crashed = [](int, int, int signal) { return fmt::format("crashed with signal {} while checking", signal); };
  check.finished = [](int, const std::string&) {};
  check.stop_requested = stop_requested;
  const std::vector<std::optional<std::string>> checks = distribution->run(count, check);
  bool good = true;
  if (coordinator) {
    int refused = 0;
    std::string first;
    for (const std::optional<std::string>& message : checks)
      if (message && !message->empty() && refused++ == 0) first = *message;
    if (refused > 0) {
      fmt::print(stderr, "heavesim: bad input: {}\n", first);
      if (refused > 1) fmt::print(stderr, "  ({} of the {} runs are refused; nothing was run)\n", refused, count);
      good = false;
    }
  }
  if (!distribution->broadcast(good)) return 2;
  if (StopSignals::received()) return stopped_before_the_run(std::filesystem::path(options.sweep_path).stem().string());

  // 2. The runs.
  SweepProgress progress(count, coordinator && !options.quiet);
  TaskCallbacks runs;
  // Runs side by side (workers, ranks) take a core each: their samples are evaluated in line.
  const bool side_by_side = options.jobs > 1 || started_by_mpirun();
  runs.run = [&](int index, int worker) {
    return encode(execute_run(sweep, plan.runs[static_cast<std::size_t>(index)], directory, options.resume,
                              side_by_side, worker));
  };
  runs.crashed = [&](int index, int worker, int signal) {
    RunRecord record;
    record.status = run_status::crashed;
    record.exit_code = 128 + signal;
    record.result_file = "runs/" + plan.runs[static_cast<std::size_t>(index)].name + ".h5";
    record.hash = plan.runs[static_cast<std::size_t>(index)].hash;
    record.rank_or_worker = worker;
    record.message = fmt::format("the worker running it was killed by signal {} ({})", signal, strsignal(signal));
    return encode(record);
  };
  runs.finished = [&](int, const std::string& bytes) { progress.finished(decode(bytes)); };
  runs.stop_requested = stop_requested;
  const std::vector<std::optional<std::string>> results = distribution->run(count, runs);
  progress.clear();
  if (!coordinator) return 0;

  std::vector<RunRecord> records;
  int complete = 0, reused = 0, pending = 0, stopped = 0;
  for (int i = 0; i < count; ++i) {
    RunRecord record;
    if (results[static_cast<std::size_t>(i)]) {
      record = decode(*results[static_cast<std::size_t>(i)]);
    } else {
      record.result_file = "runs/" + plan.runs[static_cast<std::size_t>(i)].name + ".h5";
      record.hash = plan.runs[static_cast<std::size_t>(i)].hash;
    }
    complete += record.status == run_status::complete;
    reused += record.reused;
    pending += record.status == run_status::pending;
    stopped += record.status == run_status::stopped;
    records.push_back(std::move(record));
  }
  write_sweep_index(directory, sweep, plan, records);
  if (!options.quiet) {
    fmt::print("sweep {}: {} runs on {} {}: {} complete ({} already complete, not rerun), {} failed{}{}; index {}/index.h5\n",
               options.sweep_path, count, distribution->size(), started_by_mpirun() ? "MPI ranks" : "workers", complete,
               reused, count - complete - pending - stopped, stopped ? fmt::format(", {} stopped", stopped) : "",
               pending ? fmt::format(", {} not run", pending) : "", directory);
    for (int i = 0; i < count; ++i)
      if (records[static_cast<std::size_t>(i)].status != run_status::complete &&
          records[static_cast<std::size_t>(i)].status != run_status::pending)
        fmt::print("  {} ({}): {}: {}\n", plan.runs[static_cast<std::size_t>(i)].name,
                   plan.runs[static_cast<std::size_t>(i)].describe(plan.columns), records[static_cast<std::size_t>(i)].status,
                   records[static_cast<std::size_t>(i)].message);
  }
  if (pending > 0) {
    fmt::print(stderr, "heavesim: sweep stopped by signal {}; {} runs not run (status pending, index complete = 0)\n",
               StopSignals::received(), pending);
    return 1;
  }
  return complete == count ? 0 : 4;
}

}  // namespace heavesim
