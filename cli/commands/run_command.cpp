#include <algorithm>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <optional>

#include <fmt/format.h>

#include "app/case/case_definition.hpp"
#include "cli/commands/commands.hpp"
#include "cli/commands/result_metadata.hpp"
#include "app/output/recorder.hpp"
#include "app/run/simulation_run.hpp"
#include "app/scene/scene.hpp"
#include "kernel/integrators/integrator.hpp"

namespace heavesim {
namespace {

std::atomic<int> stop_signal{0};
extern "C" void request_stop(int signal) { stop_signal = signal; }

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

}  // namespace

int run_command(const RunOptions& options) {
  const CaseDefinition definition = load_case(options.case_path, options.overrides, options.allow_large_runs);
  Scene scene = build_scene(definition);
  if (!options.quiet) print_loop_summary(scene);

  const std::string output_path =
      options.output_path.empty() ? "results/" + definition.name + ".h5" : options.output_path;
  const std::filesystem::path output_directory = std::filesystem::path(output_path).parent_path();
  if (!output_directory.empty()) std::filesystem::create_directories(output_directory);
  ResultFile file(output_path);
  write_result_metadata(file, definition);
  write_constraint_summary(file, scene);

  std::optional<CsvWriter> csv;
  if (!options.csv_directory.empty()) {
    std::filesystem::create_directories(options.csv_directory);
    csv.emplace((std::filesystem::path(options.csv_directory) / (definition.name + ".csv")).string());
  }
  Recorder recorder(definition, scene, &file, csv ? &*csv : nullptr);

  const SolverSettings& solver = definition.solver;
  std::unique_ptr<Integrator> integrator = make_integrator(solver.integrator, *scene.system);
  ProgressLine progress(solver.t_start, solver.t_end, !options.quiet);

  stop_signal = 0;
  auto previous_int = std::signal(SIGINT, request_stop);
  auto previous_term = std::signal(SIGTERM, request_stop);
  auto restore_signals = [&]() {
    std::signal(SIGINT, previous_int);
    std::signal(SIGTERM, previous_term);
  };

  RunOutcome outcome;
  try {
    outcome = run_simulation(scene, solver, definition.output.interval, *integrator,
                             [&](double t, const VectorX& y) {
                               recorder.record(t, y);
                               progress.update(t);
                               return stop_signal == 0;
                             });
  } catch (const NumericalError& error) {
    progress.clear();
    restore_signals();
    recorder.finish();
    write_run_statistics(file, integrator->statistics(), progress.elapsed(), integrator->time() - solver.t_start);
    file.set_attribute("/", "failure_time", error.time());
    file.set_attribute("/", "failure", std::string(error.what()));
    file.set_attribute("/", "failure_suggestion", error.suggestion());
    fmt::print(stderr,
               "heavesim: numerical failure in case '{}' at t = {:.6g} s: {}\n  suggestion: {}\n"
               "  results up to t = {:.6g} s are in {} (complete = 0)\n",
               definition.name, error.time(), error.what(), error.suggestion(), integrator->time(), output_path);
    return 3;
  }
  progress.clear();
  restore_signals();
  recorder.finish();
  const IntegratorStatistics& statistics = outcome.statistics;
  const double wall = progress.elapsed();
  write_run_statistics(file, statistics, wall, outcome.time_reached - solver.t_start);
  if (!outcome.completed) {
    fmt::print(stderr, "heavesim: stopped by signal {} at t = {:.6g} s; partial results in {} (complete = 0)\n",
               static_cast<int>(stop_signal), outcome.time_reached, output_path);
    return 1;
  }
  file.set_attribute("/", "complete", 1L);
  file.flush();

  if (!options.quiet) {
    fmt::print("{}: {:.6g} s simulated in {:.3f} s wall ({:.1f}x real time), {} steps, {} evaluations, "
               "{} samples -> {}\n",
               definition.name, solver.t_end - solver.t_start, wall, (solver.t_end - solver.t_start) / wall,
               statistics.steps, statistics.rhs_evaluations, recorder.samples(), output_path);
    // Energy is a check of the integration only where nothing but gravity and joint
    // springs does work: with drivers or force elements it changes by their work.
    const std::vector<Joint>& joints = scene.model->joints;
    const bool conservative =
        scene.system->force_elements().empty() && definition.drivers.empty() &&
        std::none_of(joints.begin(), joints.end(), [](const Joint& joint) {
          return joint.limits.has_value() || (joint.spring && joint.spring->damping.cwiseAbs().maxCoeff() > 0.0);
        });
    if (definition.output.energy && conservative)
      fmt::print("  relative energy drift {:.3g}\n", recorder.relative_energy_drift());
    if (scene.model->has_constraints())
      fmt::print("  constraint drift: max |Phi| {:.3g}, max |J v| {:.3g}\n",
                 recorder.channel_maximum("/signals/constraint_residual"),
                 recorder.channel_maximum("/signals/constraint_velocity_residual"));
    for (const Recorder::JointLoad& load : recorder.joint_loads()) {
      if (load.window.count() > 1 && load.window.mean()[0] > 0.0) {
        const double mean = load.window.mean()[0], deviation = load.window.standard_deviation()[0];
        fmt::print("  reaction force at joint '{}': peak {:.6g} N; from t = {:g} s mean {:.6g} N, std {:.4g} N "
                   "(2 std / mean {:.3g} %)\n",
                   load.joint, load.peak, recorder.evaluate_after(), mean, deviation, 200.0 * deviation / mean);
      } else {
        fmt::print("  peak reaction force at joint '{}': {:.6g} N\n", load.joint, load.peak);
      }
    }
    for (const std::string& line : recorder.compensators().headlines()) fmt::print("  {}\n", line);
  }
  return 0;
}

}  // namespace heavesim
