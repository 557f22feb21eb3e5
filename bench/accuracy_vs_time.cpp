// Accuracy against run time (work-precision) for every integrator on these problems:
//   double_pendulum  V3, two uniform rods released horizontal, 10 s (chaotic)
//   three_link       V4, three rods released horizontal, 5 s (chaotic: the reference
//                    itself loses digits beyond ~5 s, as in validation K3)
//   slider_crank     L1, SUNDIALS' idaSlCrank_dns mechanism, 10 s
//   four_bar         L2, IFToMM A02 N = 1 through ten singular passes, 10 s
//   a01_pendulum     IFToMM A01, point mass released horizontal, 10 s: P1 x, y [m]
//   a03_andrews      IFToMM A03, Andrews' squeezing mechanism, 0.03 s: the test set's
//                    mixed error at 0.03 s, 10^-mescd
//   a04_bricard      IFToMM A04, Bricard's mechanism (1 redundant row), 10 s: P3 [m]
//   a05_governor     IFToMM A05, stiff flyball governor, 10 s: slider s [m]
// (the IFToMM accuracy measure: the largest coordinate error over the samples).
// Each configuration runs the whole application path (YAML case with overrides ->
// scene -> integrator); the error is the largest deviation from an independent
// reference over the output samples (oracles integrated by ARKODE Fehlberg 8(7) at
// 1e-13, validation/oracles), the time is process CPU time of run_simulation (initial
// conditions, integration, copying the state at each output time), the minimum over
// repetitions. The SUNDIALS example idaSlCrank_dns itself (compiled from the copy
// libsundials-dev installs, its main renamed) runs in the same process for the
// side-by-side ratio of issue #3.
//
//   build/bench/heavesim_accuracy_vs_time [results.csv [problem [integrator [key=value ...]]]]
// The key=value arguments are case overrides (as `heavesim run --set`) for every run, e.g.
// solver.constraint_tolerance=1e-7 for the slider-crank's IDA at a looser loop closure.
//   /usr/bin/python3 scripts/plot_accuracy_vs_time.py results.csv docs/figures/work_precision.png
#include <time.h>
#include <unistd.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "app/run/simulation_run.hpp"
#include "app/scene/scene.hpp"
#include "samples/planar_chains.hpp"
#include "validation/checks/validation_suite.hpp"
#include "kernel/algorithms/kinematics.hpp"
#include "kernel/elements/body_point.hpp"
#include "validation/oracles/andrews_reference.hpp"
#include "validation/oracles/bricard_mechanism.hpp"
#include "validation/oracles/flyball_governor.hpp"
#include "validation/oracles/four_bar_parallelogram.hpp"
#include "validation/oracles/iftomm_accuracy.hpp"
#include "validation/oracles/simple_pendulum.hpp"
#include "validation/oracles/planar_chain_oracle.hpp"
#include "validation/oracles/reference_integrator.hpp"
#include "validation/oracles/slider_crank.hpp"

#ifdef HEAVESIM_HAVE_IDA_SLIDER_CRANK_EXAMPLE
extern "C" int idaSlCrank_dns_main(void);
#endif

namespace heavesim::bench {
namespace {

double cpu_seconds() {
  timespec now{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

/// Times `work` (CPU seconds): the minimum over repetitions, repeated until about
/// 0.3 s have been spent (at least 3, at most 50 runs) so that short runs are not
/// dominated by timer and scheduler noise.
double minimum_cpu_time(const std::function<void()>& work) {
  double best = std::numeric_limits<double>::infinity(), spent = 0.0;
  for (int repetition = 0; repetition < 50 && (repetition < 3 || spent < 0.3); ++repetition) {
    const double start = cpu_seconds();
    work();
    const double elapsed = cpu_seconds() - start;
    best = std::min(best, elapsed);
    spent += elapsed;
  }
  return best;
}

/// Joint positions at the output times, and the largest error of a run against the reference.
using ErrorMeasure =
    std::function<double(const Model& model, const std::vector<double>& times, const std::vector<VectorX>& q)>;

struct Problem {
  std::string name;
  std::string case_path;
  double t_end;            // s
  double output_interval;  // s
  ErrorMeasure error;
  std::string error_units;
  bool closed_loop = false;   // adds IDA with KLU
  double step_scale = 1.0;    // fixed steps (rk4, hht) are the default list times this
};

/// World positions of a body point at every sample, by the kinematics of the run's q.
std::vector<Vector3> body_point_positions(const Model& model, const std::vector<VectorX>& q, const std::string& body,
                                          const Vector3& point_body) {
  Data data(model);
  const BodyPoint point = BodyPoint::on_body(model, body, point_body);
  std::vector<Vector3> positions;
  for (const VectorX& configuration : q) {
    update_positions(model, data, configuration);
    positions.push_back(point.position_world(data));
  }
  return positions;
}

/// The coordinate of `joint` in every sample.
std::vector<double> joint_coordinate(const Model& model, const std::vector<VectorX>& q, const std::string& joint) {
  const int index = model.joints[model.joint_index(joint)].q_index;
  std::vector<double> values;
  for (const VectorX& configuration : q) values.push_back(configuration[index]);
  return values;
}

/// IFToMM A01: the mass P1 (the bob's body point (1, 0, 0)) against the exact motion.
double a01_pendulum_error(const Model& model, const std::vector<double>& times, const std::vector<VectorX>& q) {
  std::vector<Eigen::Vector2d> positions;
  for (const Vector3& p : body_point_positions(model, q, "bob", Vector3(1, 0, 0))) positions.emplace_back(p.x(), p.y());
  return oracle::iftomm_max_error(positions, oracle::pendulum_mass_positions(M_PI / 2, 1.0, 9.81, times));
}

/// IFToMM A03: the test set's mixed error 10^-mescd of the 7 angles at t = 0.03 s.
double a03_andrews_error(const Model& model, const std::vector<double>&, const std::vector<VectorX>& q) {
  std::array<double, oracle::andrews_coordinates> last{};
  for (int i = 0; i < oracle::andrews_coordinates; ++i)
    last[i] = q.back()[model.joints[model.joint_index(oracle::andrews_joint_names[i])].q_index];
  return std::pow(10.0, -oracle::mixed_error_significant_digits(last, oracle::andrews_reference_positions));
}

/// IFToMM A04: P3 (rod3's frame origin) against the independent formulation, after t = 0.
ErrorMeasure a04_bricard_error() {
  auto reference = std::make_shared<std::vector<Vector3>>();  // the oracle's, computed once
  return [reference](const Model& model, const std::vector<double>& times, const std::vector<VectorX>& q) {
    if (reference->empty())
      for (const oracle::BricardSample& sample :
           oracle::bricard_samples(std::vector<double>(times.begin() + 1, times.end()), 1e-12))
        reference->push_back(sample.p3);
    const std::vector<Vector3> p3 = body_point_positions(model, q, "rod3", Vector3::Zero());
    return oracle::iftomm_max_error(std::vector<Vector3>(p3.begin() + 1, p3.end()), *reference);
  };
}

/// IFToMM A05: the slider coordinate s against the reduced Lagrange model, after t = 0.
ErrorMeasure a05_governor_error() {
  auto reference = std::make_shared<std::vector<double>>();
  return [reference](const Model& model, const std::vector<double>& times, const std::vector<VectorX>& q) {
    if (reference->empty())
      for (const oracle::FlyballGovernorState& state : oracle::flyball_governor_states(
               oracle::FlyballGovernorParameters{}, std::vector<double>(times.begin() + 1, times.end()), 1e-12))
        reference->push_back(state.slider_height);
    const std::vector<double> s = joint_coordinate(model, q, "slide");
    double error = 0.0;
    for (std::size_t k = 1; k < s.size(); ++k) error = std::max(error, std::abs(s[k] - (*reference)[k - 1]));
    return error;
  };
}

double max_abs_difference(const std::vector<VectorX>& a, const std::vector<VectorX>& b) {
  double error = 0.0;
  for (std::size_t k = 0; k < a.size(); ++k) error = std::max(error, (a[k] - b[k]).cwiseAbs().maxCoeff());
  return error;
}

/// Planar pendulum of n unit rods released at rest, all horizontal: absolute angles
/// against the planar-chain oracle (validation K3's reference).
ErrorMeasure pendulum_error(int links) {
  return [links](const Model&, const std::vector<double>& times, const std::vector<VectorX>& q) {
    const oracle::PlanarChainOracle reference(oracle::unit_rods(links));
    Eigen::VectorXd y0 = Eigen::VectorXd::Zero(2 * links);
    y0.head(links).setConstant(M_PI / 2);
    const oracle::Rhs rhs = [&](double, const Eigen::VectorXd& y, Eigen::VectorXd& ydot) {
      ydot.head(links) = y.tail(links);
      ydot.tail(links) = reference.accelerations(y.head(links), y.tail(links), VectorX::Zero(links));
    };
    const std::vector<Eigen::VectorXd> exact = oracle::integrate_reference(rhs, 0.0, y0, times, 1e-13, 1e-13);
    std::vector<VectorX> run_absolute, exact_absolute;
    for (std::size_t k = 0; k < times.size(); ++k) {
      run_absolute.push_back(samples::absolute_from_relative(q[k]));
      exact_absolute.push_back(exact[k].head(links));
    }
    return max_abs_difference(run_absolute, exact_absolute);
  };
}

double slider_crank_error(const Model&, const std::vector<double>& times, const std::vector<VectorX>& q) {
  const std::vector<Eigen::Vector3d> exact = oracle::slider_crank_positions({}, times, 1e-13);
  double error = 0.0;
  for (std::size_t k = 0; k < times.size(); ++k) error = std::max(error, (q[k].head<3>() - exact[k]).cwiseAbs().maxCoeff());
  return error;
}

/// First crank angle of A02 N = 1 (coordinate 0, pivot0) against the exact
/// parallelogram motion: for the 1 m crank this is the tip B0's position error in m.
double four_bar_error(const Model&, const std::vector<double>& times, const std::vector<VectorX>& q) {
  const std::vector<double> later(times.begin() + 1, times.end());
  const std::vector<double> exact = oracle::four_bar_crank_angles(1, 9.81, later, 1e-13);
  double error = 0.0;
  for (std::size_t k = 0; k < later.size(); ++k) error = std::max(error, 2.0 * std::abs(std::sin(0.5 * (q[k + 1][0] - exact[k]))));
  return error;
}

struct Method {
  std::string integrator;     // case key solver.integrator
  std::string linear_solver;  // "dense", "sparse" or "" (not IDA)
  bool fixed_step;            // parameter is a step [s], else rtol = atol
  std::vector<double> parameters;
};

std::vector<Method> methods(bool closed_loop) {
  const std::vector<double> tolerances = {1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10, 1e-11, 1e-12};
  std::vector<Method> list = {
      {"rk4", "", true, {1e-2, 5e-3, 2e-3, 1e-3, 5e-4, 2e-4, 1e-4}},
      {"dopri5", "", false, tolerances},
      {"verner6", "", false, tolerances},
      {"fehlberg8", "", false, tolerances},
      {"ida", "dense", false, {1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10}},
      {"hht", "", true, {2e-3, 1e-3, 5e-4, 2e-4, 1e-4}},
  };
  if (closed_loop) list.push_back({"ida", "sparse", false, {1e-4, 1e-6, 1e-8, 1e-10}});
  return list;
}

struct Result {
  double error = std::numeric_limits<double>::infinity();
  double cpu = 0.0;  // s
  IntegratorStatistics statistics;
  std::string note;  // why a run failed
};

std::vector<std::string> extra_overrides;  // key=value from the command line, for every run

Result measure(const Problem& problem, const Method& method, double parameter) {
  std::vector<std::string> overrides = extra_overrides;
  overrides.insert(overrides.end(), {"solver.integrator=" + method.integrator, fmt::format("solver.t_end={}", problem.t_end),
                                        fmt::format("output.interval={}", problem.output_interval)});
  if (!method.linear_solver.empty()) overrides.push_back("solver.linear_solver=" + method.linear_solver);
  if (method.fixed_step) {
    overrides.push_back(fmt::format("solver.step={}", parameter * problem.step_scale));
    // HHT's Newton iterations converge to a tolerance well below its truncation error.
    overrides.insert(overrides.end(), {"solver.rtol=1e-10", "solver.atol=1e-10"});
  } else {
    overrides.insert(overrides.end(), {fmt::format("solver.rtol={}", parameter), fmt::format("solver.atol={}", parameter)});
  }
  const CaseDefinition definition = load_case(validation::project_file(problem.case_path), overrides);
  Scene scene = build_scene(definition);
  std::unique_ptr<Integrator> integrator = make_integrator(definition.solver.integrator, *scene.system);
  const std::size_t samples = static_cast<std::size_t>(std::lround(problem.t_end / problem.output_interval)) + 1;
  const int nq = scene.model->nq;
  std::vector<double> times(samples, 0.0);
  std::vector<VectorX> q(samples, VectorX::Zero(nq));
  std::size_t count = 0;
  RunOutcome outcome;
  Result result;
  const auto run = [&] {
    count = 0;
    outcome = run_simulation(scene, definition.solver, problem.output_interval, *integrator, [&](double t, const VectorX& y) {
      times[count] = t;
      q[count] = y.head(nq);
      ++count;
      return true;
    });
  };
  try {
    run();  // also warms caches
    result.cpu = minimum_cpu_time(run);
  } catch (const NumericalError& failure) {
    result.note = failure.what();
    result.note = result.note.substr(0, result.note.find('\n'));
    return result;
  }
  result.statistics = outcome.statistics;
  result.error = problem.error(*scene.model, times, q);
  return result;
}

/// CSV field: quoted, inner quotes doubled.
std::string quoted(const std::string& text) {
  std::string out = "\"";
  for (char c : text) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

#ifdef HEAVESIM_HAVE_IDA_SLIDER_CRANK_EXAMPLE
/// Runs the SUNDIALS example with its standard output sent to `path`.
void run_example_to(const char* path) {
  std::fflush(stdout);
  const int saved = dup(STDOUT_FILENO);
  if (!std::freopen(path, "w", stdout)) return;
  idaSlCrank_dns_main();
  std::fflush(stdout);
  dup2(saved, STDOUT_FILENO);
  close(saved);
  clearerr(stdout);
}

/// The example's own error against the oracle, from its printout (5 significant digits,
/// below its error at rtol = 1e-6), and its CPU time (printing included, as ours
/// includes copying the state at each output time).
Result measure_example() {
  const std::string printout = "/tmp/heavesim_idaSlCrank_dns.out";
  run_example_to(printout.c_str());
  std::vector<double> times;
  std::vector<VectorX> q;
  for (const auto& [t, positions] : oracle::read_ida_slider_crank_printout(printout)) {
    times.push_back(t);
    q.push_back(positions);
  }
  Result result;
  result.error = slider_crank_error(Model(), times, q);
  result.cpu = minimum_cpu_time([] { run_example_to("/dev/null"); });
  return result;
}
#endif

}  // namespace
}  // namespace heavesim::bench

int main(int argc, char** argv) {
  using namespace heavesim;
  using namespace heavesim::bench;
  const std::string csv_path = argc > 1 ? argv[1] : "accuracy_vs_time.csv";
  const std::string only_problem = argc > 2 ? argv[2] : "", only_integrator = argc > 3 ? argv[3] : "";
  for (int a = 4; a < argc; ++a) extra_overrides.emplace_back(argv[a]);
  const std::vector<Problem> problems = {
      {"double_pendulum", "cases/validation/two_link_horizontal.yaml", 10.0, 0.1, pendulum_error(2), "rad"},
      {"three_link", "cases/validation/three_link.yaml", 5.0, 0.1, pendulum_error(3), "rad"},
      {"slider_crank", "cases/validation/slider_crank.yaml", 10.0, 0.25, slider_crank_error, "rad or m", true},
      {"four_bar", "cases/validation/iftomm_a02_n1.yaml", 10.0, 0.1, four_bar_error, "m", true},
      {"a01_pendulum", "cases/validation/iftomm_a01_pendulum.yaml", 10.0, 0.1, a01_pendulum_error, "m"},
      {"a03_andrews", "cases/validation/iftomm_a03_andrews.yaml", 0.03, 1e-3, a03_andrews_error, "mixed", true, 0.01},
      {"a04_bricard", "cases/validation/iftomm_a04_bricard.yaml", 10.0, 0.1, a04_bricard_error(), "m", true},
      {"a05_governor", "cases/validation/iftomm_a05_flyball_governor.yaml", 10.0, 0.1, a05_governor_error(), "m", false,
       0.1},
  };
  std::ofstream csv(csv_path);
  csv << "problem,integrator,linear_solver,parameter_name,parameter,error,error_units,cpu_s,steps,rhs_evaluations,"
         "jacobian_evaluations,note\n";
  const auto write = [&](const Problem& problem, const std::string& integrator, const std::string& linear_solver,
                         const std::string& parameter_name, double parameter, const Result& result) {
    csv << fmt::format("{},{},{},{},{:g},{:.6e},{},{:.6e},{},{},{},{}\n", problem.name, integrator, linear_solver,
                       parameter_name, parameter, result.error, quoted(problem.error_units), result.cpu,
                       result.statistics.steps, result.statistics.rhs_evaluations, result.statistics.jacobian_evaluations,
                       quoted(result.note));
    fmt::print("{:16} {:10} {:6} {:4}={:<7g} error {:9.2e}  cpu {:9.3f} ms  steps {:7}{}\n", problem.name, integrator,
               linear_solver, parameter_name, parameter, result.error, 1e3 * result.cpu, result.statistics.steps,
               result.note.empty() ? "" : "  " + result.note);
    std::fflush(stdout);
  };

  for (const Problem& problem : problems) {
    if (!only_problem.empty() && problem.name != only_problem) continue;
    const bool closed_loop = problem.closed_loop;
    struct Best {
      std::string label;
      double cpu = std::numeric_limits<double>::infinity();
    } best;
    for (const Method& method : methods(closed_loop)) {
      if (!only_integrator.empty() && method.integrator != only_integrator) continue;
      for (double parameter : method.parameters) {
        const Result result = measure(problem, method, parameter);
        const double shown = method.fixed_step ? parameter * problem.step_scale : parameter;  // the step used
        write(problem, method.integrator, method.linear_solver, method.fixed_step ? "h" : "tol", shown, result);
        if (result.error <= 1e-6 && result.cpu < best.cpu)
          best = {fmt::format("{}{} {}={:g}", method.integrator, method.linear_solver.empty() ? "" : " " + method.linear_solver,
                              method.fixed_step ? "h" : "tol", shown),
                  result.cpu};
      }
    }
#ifdef HEAVESIM_HAVE_IDA_SLIDER_CRANK_EXAMPLE
    if (problem.name == "slider_crank") {
      const Result example = measure_example();
      write(problem, "idaSlCrank_dns", "dense", "tol", 1e-6, example);
      const Result ours = measure(problem, {"ida", "dense", false, {}}, 1e-6);
      fmt::print("slider_crank at rtol = atol = 1e-6: heavesim IDA {:.3f} ms (error {:.2e}), idaSlCrank_dns {:.3f} ms "
                 "(error {:.2e}): ratio {:.2f}\n",
                 1e3 * ours.cpu, ours.error, 1e3 * example.cpu, example.error, ours.cpu / example.cpu);
      const IntegratorStatistics& counts = ours.statistics;
      fmt::print("heavesim IDA: {} steps, {} residuals, {} Newton iterations, {} convergence failures, {} error test "
                 "failures, {} Jacobian evaluations (the example prints its own at the end of {})\n",
                 counts.steps, counts.rhs_evaluations, counts.nonlinear_iterations, counts.convergence_failures,
                 counts.error_test_failures, counts.jacobian_evaluations, "/tmp/heavesim_idaSlCrank_dns.out");
    }
#endif
    fmt::print("{}: fastest to error <= 1e-6: {} in {:.3f} ms CPU\n\n", problem.name, best.label, 1e3 * best.cpu);
  }
  fmt::print("wrote {}\n", csv_path);
  return 0;
}
