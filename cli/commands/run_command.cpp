#include <algorithm>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "app/case/case_definition.hpp"
#include "app/case/case_node.hpp"
#include "cli/commands/commands.hpp"
#include "cli/commands/command_support.hpp"
#include "cli/commands/result_metadata.hpp"
#include "app/output/output_error.hpp"
#include "app/output/recorder.hpp"
#include "app/run/simulation_run.hpp"
#include "app/scene/scene.hpp"
#include "io/hdf5/hdf5_handle.hpp"
#include "kernel/integrators/integrator.hpp"

namespace heavesim {
namespace {

/// A run that stopped before t_end (signal, numerical failure, a CSV that could not be
/// written): statistics and run summary written, complete = 0, file closed.
void close_incomplete(ResultFile& file, Recorder& recorder, const IntegratorStatistics& statistics, double wall,
                      double simulated) {
  recorder.finish();
  write_run_statistics(file, statistics, wall, simulated);
  file.close();
}

/// The time [s] the recorded samples reach: the last one's, the start before the first.
double recorded_until(const Recorder& recorder, const SolverSettings& solver) {
  return recorder.samples() > 0 ? recorder.last_sample_time() : solver.t_start;
}

}  // namespace

int run_command(const RunOptions& options) {
  // Before anything touches HDF5 (a BEM file read while loading does).
  hdf5::skip_library_exit_cleanup();
  const StopSignals signals;
  // Kept until the recorder's definition is read from it too (below), then dropped.
  std::optional<CaseNode> case_tree(resolved_case_tree(options.case_path, options.overrides));
  const CaseDefinition definition = read_case(*case_tree, options.case_path, options.allow_large_runs);
  if (StopSignals::received()) return stopped_before_the_run(definition.name);
  // The output place is checked (created) before the scene is built.
  const std::string output_path = prepare_result_path(options.output_path, definition.name);
  // The scene is built (and the run-size limits checked, app/scene/run_size.hpp) before
  // the file reserves room for every sample.
  Scene scene = build_scene(definition);
  if (!options.quiet) print_loop_summary(scene);
  if (!options.quiet && scene.equilibrium) print_equilibrium_summary(scene);
  const SolverSettings& solver = definition.solver;
  ResultFile file(output_path, static_cast<hsize_t>(output_sample_count(solver, definition.output.interval)));
  write_result_metadata(file, definition);
  write_constraint_summary(file, scene);

  std::optional<CsvWriter> csv;
  std::string csv_path;
  if (!options.csv_directory.empty()) {
    csv_path = (std::filesystem::path(options.csv_directory) / (definition.name + ".csv")).string();
    create_parent_directory(csv_path, "CSV file");
    csv.emplace(csv_path);
  }
  // The samples are evaluated on a second build of the scene, on a second thread beside
  // the integration, where that gives the same numbers (Recorder::why_samples_in_line).
  // Its case is read again from the same tree (the files are not parsed twice): the two
  // scenes share nothing (an expression of t, a driver's or a load's, keeps its
  // evaluation workspace).
  std::optional<CaseDefinition> recording_definition;
  std::optional<Scene> recording_scene;
  if (options.samples_beside && Recorder::why_samples_in_line(definition, scene).empty()) {
    recording_definition.emplace(read_case(*case_tree, options.case_path, options.allow_large_runs));
    recording_scene.emplace(build_scene(*recording_definition));
  }
  case_tree.reset();
  Recorder recorder(recording_definition ? *recording_definition : definition,
                    recording_scene ? *recording_scene : scene, file, csv ? &*csv : nullptr);
  // The integrating thread evaluates samples too, on its own scene between its steps,
  // whenever a batch of them would otherwise wait for the recorder's thread.
  if (recording_scene) recorder.evaluate_on_second_thread(&scene);
  std::unique_ptr<Integrator> integrator = make_integrator(solver.integrator, *scene.system);
  if (StopSignals::received()) return stopped_before_the_run(definition.name);
  ProgressLine progress(solver.t_start, solver.t_end, !options.quiet);

  RunOutcome outcome;
  try {
    // The file's series, on disk under its name before the first sample is written; with
    // the samples beside, on the recorder's thread while the first steps are integrated.
    recorder.lay_out_file();
    try {
      outcome = run_simulation(scene, solver, definition.output.interval, *integrator,
                               [&](double t, const VectorX& y) {
                                 recorder.record(t, y);
                                 progress.update(t);
                                 return StopSignals::received() == 0;
                               });
      try {
        recorder.record_queued_samples();
      } catch (const NumericalError& error) {
        throw integrator->explain(error);  // as run_simulation explains a sample's failure
      }
    } catch (const NumericalError& integration_error) {
      progress.clear();
      // The samples before the failure still queued for the recorder's thread; a failure
      // among them came first, and is the one to report.
      NumericalError error = integration_error;
      try {
        recorder.record_queued_samples();
      } catch (const NumericalError& earlier) {
        error = integrator->explain(earlier);
      }
      if (csv) csv->close();
      record_failure(file, error);
      // A sample that failed on the recorder's thread did so before the integrator's time.
      close_incomplete(file, recorder, integrator->statistics(), progress.elapsed(),
                       std::min(integrator->time(), error.time()) - solver.t_start);
      fmt::print(stderr,
                 "heavesim: numerical failure in case '{}' at t = {:.6g} s: {}\n  suggestion: {}\n"
                 "  results up to t = {:.6g} s are in {} (complete = 0)\n",
                 definition.name, error.time(), error.what(), error.suggestion(), recorded_until(recorder, solver),
                 output_path);
      return 3;
    }
    progress.clear();
    // The CSV closes first: if its last write fails, the result file is still open to be
    // closed as a stopped run's (below).
    if (csv) csv->close();
    if (!outcome.completed) {
      close_incomplete(file, recorder, outcome.statistics, progress.elapsed(), outcome.time_reached - solver.t_start);
      fmt::print(stderr, "heavesim: stopped by signal {} at t = {:.6g} s; partial results in {} (complete = 0)\n",
                 StopSignals::received(), outcome.time_reached, output_path);
      return 1;
    }
    recorder.finish();
    write_run_statistics(file, outcome.statistics, progress.elapsed(), outcome.time_reached - solver.t_start);
    file.mark_complete();  // last: everything else is on disk first
    file.close();
  } catch (const OutputError& error) {
    progress.clear();
    fmt::print(stderr, "heavesim: {}\n", error.what());
    if (error.path() != output_path) {
      // The CSV failed; the result file is still whole: close it as a stopped run's.
      close_incomplete(file, recorder, integrator->statistics(), progress.elapsed(),
                       recorded_until(recorder, solver) - solver.t_start);
      fmt::print(stderr, "  the run stopped at t = {:.6g} s; results up to there are in {} (complete = 0)\n",
                 recorded_until(recorder, solver), output_path);
    } else if (file.published()) {
      fmt::print(stderr, "  the run stopped at t = {:.6g} s; {} keeps the first {} samples (samples_written, complete = 0)\n",
                 recorded_until(recorder, solver), output_path, file.samples_written());
    } else {
      fmt::print(stderr, "  no result file was written\n");
    }
    return 1;
  }

  const IntegratorStatistics& statistics = outcome.statistics;
  const double wall = progress.elapsed();
  if (!options.quiet) {
    fmt::print("{}: {:.6g} s simulated in {:.3f} s wall ({:.1f}x real time), {} steps, {} evaluations, "
               "{} samples -> {}\n",
               definition.name, solver.t_end - solver.t_start, wall, (solver.t_end - solver.t_start) / wall,
               statistics.steps, statistics.rhs_evaluations, recorder.samples(), output_path);
    if (recording_scene)
      fmt::print("  samples evaluated beside the integration: {} on the recorder's thread, {} on the integrating "
                 "one while that was busy\n",
                 recorder.samples() - recorder.samples_evaluated_by_caller(), recorder.samples_evaluated_by_caller());
    if (definition.output.energy && recorder.energy_is_conserved())
      fmt::print("  relative energy drift {:.3g}\n", recorder.relative_energy_drift());
    if (scene.model->has_constraints())
      fmt::print("  constraint drift: max |Phi| {:.3g}, max |J v| {:.3g}\n",
                 recorder.channel_maximum("/signals/constraint_residual"),
                 recorder.channel_maximum("/signals/constraint_velocity_residual"));
    // A joint whose peak is round-off beside the largest (the free joint of a floating
    // platform, which the water holds) carries nothing: its std / mean is noise.
    double largest_peak = 0.0;
    for (const Recorder::JointLoad& load : recorder.joint_loads()) largest_peak = std::max(largest_peak, load.peak);
    std::vector<std::string> idle;
    for (const Recorder::JointLoad& load : recorder.joint_loads()) {
      if (load.peak <= 1e-6 * largest_peak) {
        idle.push_back(load.joint);
        continue;
      }
      if (load.window.count() > 1 && load.window.mean()[0] > 0.0) {
        const double mean = load.window.mean()[0], deviation = load.window.standard_deviation()[0];
        fmt::print("  reaction force at joint '{}': peak {:.6g} N; from t = {:g} s mean {:.6g} N, std {:.4g} N "
                   "(2 std / mean {:.3g} %)\n",
                   load.joint, load.peak, recorder.evaluate_after(), mean, deviation, 200.0 * deviation / mean);
      } else {
        fmt::print("  peak reaction force at joint '{}': {:.6g} N\n", load.joint, load.peak);
      }
    }
    if (!idle.empty())
      fmt::print("  carrying nothing (peak below 1e-6 of the largest): {}\n", fmt::join(idle, ", "));
    for (const std::string& line : recorder.compensators().headlines()) fmt::print("  {}\n", line);
  }
  return 0;
}

}  // namespace heavesim
