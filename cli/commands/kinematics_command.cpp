// heavesim kinematics: the kinematic analysis of a driven mechanism over the case's time
// span (kernel/analysis/kinematic_analysis.hpp), with the driving forces and joint
// reactions the motion needs (MultibodySystem::evaluate_prescribed), into a result file
// of the same contract as a run's (docs/result-file.md).
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>
#include <variant>

#include <Eigen/SVD>
#include <fmt/format.h>

#include "app/case/case_definition.hpp"
#include "app/output/output_error.hpp"
#include "app/output/recorder.hpp"
#include "app/run/kinematic_run.hpp"
#include "app/scene/scene.hpp"
#include "cli/commands/command_support.hpp"
#include "cli/commands/commands.hpp"
#include "cli/commands/result_metadata.hpp"
#include "io/hdf5/hdf5_handle.hpp"
#include "kernel/analysis/kinematic_analysis.hpp"

namespace heavesim {
namespace {

/// Degrees of freedom of the mechanism at its assembled configuration.
struct DofReport {
  int coordinates = 0;  // nv
  int equations = 0;    // constraint rows, drivers included
  int drivers = 0;
  int rank = 0;
  int grubler() const { return coordinates - equations; }
  int free_directions() const { return coordinates - rank; }
  std::vector<std::string> free_direction_names;  // per free direction: the joints it moves
};

/// "speed 2 of joint 'rod_ball'" for velocity coordinate k.
std::string describe_speed(const Model& model, int k) {
  for (int i = 1; i < model.num_links(); ++i) {
    const Joint& joint = model.joints[i];
    if (k < joint.v_index || k >= joint.v_index + joint.nv) continue;
    return joint.nv > 1 ? fmt::format("joint '{}' speed {}", joint.name, k - joint.v_index)
                        : fmt::format("joint '{}'", joint.name);
  }
  return fmt::format("speed {}", k);
}

/// The Grübler count against the rank (scene.assembly), and the free directions: a
/// basis of the null space of J at the assembled configuration (right singular vectors
/// beyond the rank), each named by the joint speeds that carry at least a fifth of it.
DofReport dof_report(const Scene& scene) {
  const Model& model = *scene.model;
  DofReport report;
  report.coordinates = model.nv;
  report.equations = model.num_constraint_rows;
  for (const Constraint& constraint : model.constraints)
    report.drivers += constraint.is_driver() ? 1 : 0;
  report.rank = model.has_constraints() ? scene.assembly.rank.rank : 0;
  if (report.free_directions() <= 0) return report;
  MatrixX basis = MatrixX::Identity(model.nv, model.nv);
  if (model.has_constraints()) {
    const Eigen::JacobiSVD<MatrixX> svd(scene.system->data().constraint_jacobian, Eigen::ComputeFullV);
    basis = svd.matrixV();
  }
  for (int k = report.rank; k < model.nv; ++k) {
    const VectorX direction = basis.col(k).cwiseAbs();
    std::string names;
    for (int c = 0; c < model.nv; ++c)
      if (direction[c] >= 0.2 * direction.maxCoeff()) names += (names.empty() ? "" : ", ") + describe_speed(model, c);
    report.free_direction_names.push_back(names);
  }
  return report;
}

void print_dof_report(const Scene& scene, const DofReport& report, const KinematicSettings& settings) {
  const Model& model = *scene.model;
  fmt::print("degrees of freedom: {} joint coordinates, {} constraint equations ({} from drivers): Gruebler count {}; "
             "rank of the constraint Jacobian {}, so {} free direction{}\n",
             report.coordinates, report.equations, report.drivers, report.grubler(), report.rank,
             report.free_directions(), report.free_directions() == 1 ? "" : "s");
  if (model.has_constraints() && !scene.assembly.rank.redundant_rows.empty())
    fmt::print("  {} redundant equation{} (they repeat others; their multipliers are the minimum-norm split): {}\n",
               scene.assembly.rank.redundant_rows.size(), scene.assembly.rank.redundant_rows.size() == 1 ? "" : "s",
               describe_redundant_rows(model, scene.assembly.rank));
  for (std::size_t k = 0; k < report.free_direction_names.size(); ++k)
    fmt::print("  free direction {}: {} (held at the minimum-{} motion)\n", k + 1, report.free_direction_names[k],
               settings.weighting == MotionWeighting::mass ? "kinetic-energy" : "norm");
}

}  // namespace

int kinematics_command(const RunOptions& options) {
  hdf5::skip_library_exit_cleanup();
  const StopSignals signals;
  const CaseDefinition definition = load_case(options.case_path, options.overrides, options.allow_large_runs);
  if (StopSignals::received()) return stopped_before_the_run(definition.name);
  const std::string output_path = prepare_result_path(options.output_path, definition.name);
  Scene scene = build_scene(definition);
  const Model& model = *scene.model;
  MultibodySystem& system = *scene.system;
  const KinematicSettings& settings = definition.kinematics;
  const DofReport dof = dof_report(scene);
  if (!options.quiet) print_dof_report(scene, dof, settings);

  const SolverSettings& solver = definition.solver;
  const long intervals = output_interval_count(solver, definition.output.interval);
  ResultFile file(output_path, static_cast<hsize_t>(intervals + 1));
  write_result_metadata(file, definition);
  write_constraint_summary(file, scene);
  file.set_attribute("/", "analysis", std::string("kinematics"));
  file.set_attribute("/", "dof", static_cast<long>(dof.free_directions()));
  file.set_attribute("/", "rank", static_cast<long>(dof.rank));
  file.set_attribute("/", "grubler_dof", static_cast<long>(dof.grubler()));

  KinematicPoint point;
  const std::vector<Recorder::ExtraChannel> channels = {
      {"/kinematics/newton_iterations", "-", "Newton iterations of the position solve at this time point",
       [&point] { return static_cast<double>(point.newton_iterations); }},
      {"/kinematics/equation_residual", "m or rad", "max |Phi(q, t)| over every constraint row after the solve",
       [&point] { return point.equation_residual; }},
      {"/kinematics/smallest_singular_ratio", "-",
       "rank-th over largest singular value of the constraint Jacobian in the weighting metric (J L^-T, W = L L^T); "
       "near 0 at a singular configuration",
       [&point] { return point.singular_ratio; }},
      {"/kinematics/dynamic_residual", "N or N m",
       "max |M qdd + C - tau - J^T lambda|: generalized force along free directions that no constraint supplies",
       [&system] { return system.dynamic_residual().size() ? system.dynamic_residual().cwiseAbs().maxCoeff() : 0.0; }},
  };
  std::optional<CsvWriter> csv;
  if (!options.csv_directory.empty()) {
    const std::string csv_path = (std::filesystem::path(options.csv_directory) / (definition.name + ".csv")).string();
    create_parent_directory(csv_path, "CSV file");
    csv.emplace(csv_path);
  }
  Recorder recorder(definition, scene, file, csv ? &*csv : nullptr, channels);
  if (StopSignals::received()) return stopped_before_the_run(definition.name);
  ProgressLine progress(solver.t_start, solver.t_end, !options.quiet);

  // Peak |lambda| of each driver: the largest force or torque its actuator must supply.
  std::vector<std::pair<const Constraint*, double>> driver_peaks;
  for (const Constraint& constraint : model.constraints)
    if (constraint.is_driver()) driver_peaks.emplace_back(&constraint, 0.0);
  bool singular = false;
  int singular_reports = 0;
  double t_last = solver.t_start;
  KinematicOutcome outcome;
  const auto finish = [&](bool complete) {
    recorder.finish();
    file.set_attribute("/summary", "newton_iterations", outcome.newton_iterations);
    file.set_attribute("/summary", "max_equation_residual", outcome.max_equation_residual);
    file.set_attribute("/summary", "smallest_singular_ratio", outcome.smallest_singular_ratio);
    file.set_attribute("/summary", "max_dynamic_residual", outcome.max_dynamic_residual);
    file.set_attribute("/summary", "wall_time_s", progress.elapsed());
    if (complete) file.mark_complete();
    file.close();
  };
  try {
    recorder.lay_out_file();  // the layout is on disk: the file appears under its name
    try {
      outcome = run_kinematics(scene, definition, recorder.needs_reactions(),
                               [&](double t, const VectorX& y, const KinematicPoint& observed) {
        point = observed;
        const bool now_singular = point.singular_ratio < settings.singular_ratio;
        if (now_singular && !singular && !options.quiet && singular_reports < 10) {
          ++singular_reports;
          progress.clear();
          fmt::print("  singular configuration at t = {:.6g} s (ratio {:.2g}): {}\n", t, point.singular_ratio,
                     system.constraint_loss(t, 1.0).what);
        }
        singular = now_singular;
        for (auto& [driver, peak] : driver_peaks)
          peak = std::max(peak, std::abs(system.data().constraint_multipliers[driver->first_row]));
        recorder.record_evaluation(t, y);
        t_last = t;
        progress.update(t);
        return StopSignals::received() == 0;
      });
    } catch (const NumericalError& error) {
      progress.clear();
      if (csv) csv->close();
      record_failure(file, error);
      finish(false);
      fmt::print(stderr,
                 "heavesim: numerical failure in the kinematic analysis of case '{}' at t = {:.6g} s: {}\n"
                 "  suggestion: {}\n  results up to t = {:.6g} s are in {} (complete = 0)\n",
                 definition.name, error.time(), error.what(), error.suggestion(), t_last, output_path);
      return 3;
    }
    progress.clear();
    if (csv) csv->close();
    if (!outcome.completed) {
      finish(false);
      fmt::print(stderr, "heavesim: stopped by signal {} at t = {:.6g} s; partial results in {} (complete = 0)\n",
                 StopSignals::received(), t_last, output_path);
      return 1;
    }
    finish(true);
  } catch (const OutputError& error) {
    progress.clear();
    fmt::print(stderr, "heavesim: {}\n", error.what());
    if (file.published())
      fmt::print(stderr, "  the analysis stopped at t = {:.6g} s; {} keeps the first {} samples (complete = 0)\n",
                 t_last, output_path, file.samples_written());
    else
      fmt::print(stderr, "  no result file was written\n");
    return 1;
  }

  if (!options.quiet) {
    fmt::print("{}: kinematic analysis of {} time points from t = {:g} to {:g} s in {:.3f} s wall -> {}\n",
               definition.name, recorder.samples(), solver.t_start, solver.t_end, progress.elapsed(), output_path);
    fmt::print("  max |Phi| {:.3g}, {} Newton iterations ({:.2f} per time point), smallest singular-value ratio "
               "{:.3g}\n",
               outcome.max_equation_residual, outcome.newton_iterations,
               static_cast<double>(outcome.newton_iterations) / std::max(1L, outcome.points),
               outcome.smallest_singular_ratio);
    if (dof.free_directions() > 0)
      fmt::print("  largest generalized force along the free directions that no driver supplies: {:.3g} N or N m\n",
                 outcome.max_dynamic_residual);
    for (const auto& [driver, peak] : driver_peaks)
      fmt::print("  driver '{}': peak driving force or torque {:.6g} N or N m\n", driver->name, peak);
  }
  return 0;
}

}  // namespace heavesim
