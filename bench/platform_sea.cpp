// The free 6-DoF MSS semi in a 3-hour irregular sea (cases/hydro/semisub_6dof_irregular_sea.yaml:
// JONSWAP Hs 4 m, Tp 10 s, gamma 3.3, 200 components, seed 1, head seas), run through the
// application path (case file with overrides -> scene -> run_simulation), as in
// docs/performance.md:
//   sea     integrators and steps for the 3-hour run: process CPU time of run_simulation
//           (the minimum over repetitions) and the largest difference of the six motions
//           from a tight reference run (RK4 at h = 0.01 s, checked against Verner 6(5) at
//           rtol = atol = 1e-10);
//   memory  the radiation memory as a state-space realisation of order 4, 8, 12, 20 and
//           as a direct convolution of K(t), over the first 300 s of the same sea with
//           RK4: CPU time and the largest motion differences from a convolution with
//           kernel step and time step 0.025 s (the Cummins equation with the same 60 s
//           kernel, resolved twice as finely as the 0.05 s of the cases).
// Motions are xi = [surge, sway, heave (m); roll, pitch, yaw (rad)] of the body frame,
// world axes (rotation vector), at every output sample (0.5 s).
//
//   scripts/build.sh heavesim_platform_bench
//   build/bench/heavesim_platform_bench [sea|memory|all] [results.csv]
#include <time.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "app/run/simulation_run.hpp"
#include "app/scene/scene.hpp"
#include "validation/checks/validation_suite.hpp"

namespace heavesim::bench {
namespace {

using Vector6 = Eigen::Matrix<double, 6, 1>;

double cpu_seconds() {
  timespec now{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

struct Run {
  std::string label;
  double cpu = std::numeric_limits<double>::infinity();  // s, the minimum over repetitions
  IntegratorStatistics statistics;
  int memory_states = 0;
  std::vector<Vector6> xi;
  std::string note;
};

const char* sea_case = "cases/hydro/semisub_6dof_irregular_sea.yaml";

/// Runs the sea case with `overrides`, `repetitions` times; keeps the motions of the last.
Run run(const std::string& label, const std::vector<std::string>& overrides, int repetitions) {
  Run result;
  result.label = label;
  try {
    const CaseDefinition definition = load_case(validation::project_file(sea_case), overrides);
    for (int repetition = 0; repetition < repetitions; ++repetition) {
      Scene scene = build_scene(definition);  // outside the timing: reading the BEM files, realising K(t)
      result.memory_states = scene.system->size() - scene.model->nq - scene.model->nv;
      std::unique_ptr<Integrator> integrator = make_integrator(definition.solver.integrator, *scene.system);
      result.xi.clear();
      result.xi.reserve(static_cast<std::size_t>((definition.solver.t_end - definition.solver.t_start) /
                                                 definition.output.interval) + 2);
      const double start = cpu_seconds();
      const RunOutcome outcome =
          run_simulation(scene, definition.solver, definition.output.interval, *integrator, [&](double, const VectorX& y) {
            const Eigen::AngleAxisd rotation(Eigen::Quaterniond(y[3], y[4], y[5], y[6]));
            Vector6 xi;
            xi << y.head<3>(), rotation.angle() * rotation.axis();
            result.xi.push_back(xi);
            return true;
          });
      result.cpu = std::min(result.cpu, cpu_seconds() - start);
      result.statistics = outcome.statistics;
    }
  } catch (const std::exception& failure) {
    result.note = failure.what();
    result.note = result.note.substr(0, result.note.find('\n'));
  }
  return result;
}

/// Largest |difference| per motion over the record.
Vector6 largest_difference(const Run& a, const Run& b) {
  Vector6 d = Vector6::Zero();
  if (a.xi.size() != b.xi.size()) return Vector6::Constant(std::numeric_limits<double>::infinity());
  for (std::size_t k = 0; k < a.xi.size(); ++k) d = d.cwiseMax((a.xi[k] - b.xi[k]).cwiseAbs());
  return d;
}

Vector6 largest_motion(const Run& run) {
  Vector6 m = Vector6::Zero();
  for (const Vector6& xi : run.xi) m = m.cwiseMax(xi.cwiseAbs());
  return m;
}

struct Table {
  std::ofstream csv;
  explicit Table(const std::string& path) : csv(path) {
    csv << "study,configuration,memory_states,cpu_s,steps,rhs_evaluations,max_surge_m,max_sway_m,max_heave_m,max_roll_rad,"
           "max_pitch_rad,max_yaw_rad,diff_surge_m,diff_sway_m,diff_heave_m,diff_roll_rad,diff_pitch_rad,diff_yaw_rad,"
           "diff_to,note\n";
  }
  void write(const std::string& study, const Run& run, const Run& reference) {
    const Vector6 m = largest_motion(run), d = largest_difference(run, reference);
    csv << fmt::format("{},{},{},{:.4f},{},{},{:.6e},{:.6e},{:.6e},{:.6e},{:.6e},{:.6e},{:.3e},{:.3e},{:.3e},{:.3e},{:.3e},{:.3e},{},\"{}\"\n",
                       study, run.label, run.memory_states, run.cpu, run.statistics.steps, run.statistics.rhs_evaluations,
                       m[0], m[1], m[2], m[3], m[4], m[5], d[0], d[1], d[2], d[3], d[4], d[5], reference.label, run.note);
    csv.flush();
    fmt::print("{:34} states {:4}  cpu {:8.3f} s  steps {:8}  evals {:8} | max diff: surge {:8.2e} m  heave {:8.2e} m  "
               "pitch {:8.2e} rad  roll {:8.2e} rad  (heave {:.2f} m, pitch {:.4f} rad){}\n",
               run.label, run.memory_states, run.cpu, run.statistics.steps, run.statistics.rhs_evaluations, d[0], d[2], d[4],
               d[3], m[2], m[4], run.note.empty() ? "" : "  " + run.note);
    std::fflush(stdout);
  }
};

std::vector<std::string> fixed_step(const std::string& integrator, double step) {
  return {"solver.integrator=" + integrator, fmt::format("solver.step={}", step)};
}
std::vector<std::string> tolerance(const std::string& integrator, double tol) {
  return {"solver.integrator=" + integrator, fmt::format("solver.rtol={}", tol), fmt::format("solver.atol={}", tol)};
}

void sea_study(Table& table) {
  fmt::print("3-hour 6-DoF irregular sea (state-space memory, order 12)\n");
  const Run reference = run("rk4 h=0.01 (reference)", fixed_step("rk4", 0.01), 1);
  table.write("sea", reference, reference);
  const Run check = run("verner6 tol=1e-10", tolerance("verner6", 1e-10), 1);
  table.write("sea", check, reference);
  // RK4's steps divide the output interval (0.5 s), so that no step is shortened to land on
  // an output time.
  for (double h : {0.05, 0.1, 0.25, 0.5}) table.write("sea", run(fmt::format("rk4 h={:g}", h), fixed_step("rk4", h), 3), reference);
  for (double tol : {1e-5, 1e-6, 1e-7})
    table.write("sea", run(fmt::format("dopri5 tol={:g}", tol), tolerance("dopri5", tol), 1), reference);
  for (double tol : {1e-5, 1e-6, 1e-7})
    table.write("sea", run(fmt::format("verner6 tol={:g}", tol), tolerance("verner6", tol), 1), reference);
}

void memory_study(Table& table) {
  fmt::print("radiation memory, first 300 s of the sea, rk4\n");
  const std::vector<std::string> first_300_s = {"solver.t_end=300"};
  const auto with = [&](std::vector<std::string> a, const std::vector<std::string>& b) {
    a.insert(a.end(), first_300_s.begin(), first_300_s.end());
    a.insert(a.end(), b.begin(), b.end());
    return a;
  };
  const auto convolution = [](double step) {
    return std::vector<std::string>{"forces[radiation].memory=convolution", fmt::format("forces[radiation].kernel_step={}", step)};
  };
  const Run reference = run("convolution dt=h=0.025 (reference)", with(fixed_step("rk4", 0.025), convolution(0.025)), 1);
  table.write("memory", reference, reference);
  for (double step : {0.05, 0.1})
    table.write("memory", run(fmt::format("convolution dt=h={:g}", step), with(fixed_step("rk4", step), convolution(step)), 2),
                reference);
  for (int order : {4, 8, 12, 20})
    for (double h : {0.05, 0.25})
      table.write("memory",
                  run(fmt::format("state space order {} h={:g}", order, h),
                      with(fixed_step("rk4", h), {fmt::format("forces[radiation].state_space_order={}", order)}), 2),
                  reference);
}

}  // namespace
}  // namespace heavesim::bench

int main(int argc, char** argv) {
  using namespace heavesim::bench;
  const std::string what = argc > 1 ? argv[1] : "all", csv_path = argc > 2 ? argv[2] : "platform_sea.csv";
  Table table(csv_path);
  if (what == "sea" || what == "all") sea_study(table);
  if (what == "memory" || what == "all") memory_study(table);
  fmt::print("wrote {}\n", csv_path);
  return 0;
}
