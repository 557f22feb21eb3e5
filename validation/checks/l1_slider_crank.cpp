// L1: the slider-crank of SUNDIALS' idaSlCrank_dns example through the whole
// application path (YAML case with a revolute loop joint, a spring-damper and a push;
// assembly; every integrator) against the minimal-coordinate oracle integrated by
// ARKODE Fehlberg 8(7) at 1e-13, and IDA at the example's own tolerances against the
// output the example prints (shipped with libsundials-dev).
#include <cmath>
#include <filesystem>

#include <fmt/format.h>

#include "validation/checks/validation_suite.hpp"
#include "validation/oracles/slider_crank.hpp"

namespace heavesim::validation {
namespace {

constexpr const char* case_path = "cases/validation/slider_crank.yaml";
constexpr const char* example_output = "/usr/share/doc/libsundials-dev/examples/ida/serial/idaSlCrank_dns.out";

struct Samples {
  std::vector<double> times;
  std::vector<Eigen::Vector3d> positions;  // crank angle, slider position, rod angle
};

Samples run(const std::vector<std::string>& overrides) {
  Samples samples;
  run_case(case_path, overrides, [&](double t, const MultibodySystem& system) {
    samples.times.push_back(t);
    const VectorX& q = system.configuration();
    samples.positions.emplace_back(q[0], q[1], q[2]);
  });
  return samples;
}

double max_error(const Samples& run, const std::vector<Eigen::Vector3d>& reference) {
  double error = 0.0;
  for (std::size_t k = 0; k < run.times.size(); ++k)
    error = std::max(error, (run.positions[k] - reference[k]).cwiseAbs().maxCoeff());
  return error;
}

}  // namespace

std::vector<ValidationRow> check_l1_slider_crank() {
  std::vector<ValidationRow> rows;
  const oracle::SliderCrankParameters parameters;
  std::vector<double> times;
  for (int k = 0; k <= 40; ++k) times.push_back(0.25 * k);
  const std::vector<Eigen::Vector3d> reference = oracle::slider_crank_positions(parameters, times, 1e-13);

  const std::vector<std::pair<std::string, std::vector<std::string>>> runs = {
      {"IDA GGL, dense, rtol = atol = 1e-10", {"solver.rtol=1e-10", "solver.atol=1e-10"}},
      {"IDA GGL, KLU sparse, rtol = atol = 1e-10",
       {"solver.rtol=1e-10", "solver.atol=1e-10", "solver.linear_solver=sparse"}},
      {"Dormand-Prince + projection, rtol = atol = 1e-10",
       {"solver.integrator=dopri5", "solver.rtol=1e-10", "solver.atol=1e-10"}},
      {"RK4 + projection, h = 1 ms", {"solver.integrator=rk4", "solver.step=1e-3"}},
      {"HHT index-3 (trapezoidal), h = 0.5 ms", {"solver.integrator=hht", "solver.step=5e-4"}},
  };
  for (const auto& [label, overrides] : runs)
    rows.push_back({"L1", "slider-crank 10 s, " + label, "positions (rad, m) vs minimal-coordinate oracle",
                    max_error(run(overrides), reference), 1e-6});

  // The example's own printout (5 digits, its run at rtol = atol = 1e-6): the same
  // tolerances here must reproduce it to its printed precision plus both runs' error.
  const auto printed = oracle::read_ida_slider_crank_printout(example_output);
  if (!printed.empty()) {
    const Samples loose = run({});
    double error = 0.0;
    for (const auto& [t, y] : printed)
      for (std::size_t k = 0; k < loose.times.size(); ++k)
        if (std::abs(loose.times[k] - t) < 1e-9)
          error = std::max(error, (loose.positions[k] - y).cwiseAbs().maxCoeff());
    rows.push_back({"L1", fmt::format("slider-crank 10 s, IDA rtol = atol = 1e-6 vs idaSlCrank_dns.out ({} rows)",
                                      printed.size()),
                    "positions vs the example's printout", error, 1e-3});
  }
  return rows;
}

}  // namespace heavesim::validation
