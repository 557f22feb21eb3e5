// A01: IFToMM benchmark A01, the simple pendulum (cases/validation/iftomm_a01_pendulum.yaml:
// a 1 kg point mass on a massless 1 m rod, released at rest from the horizontal) through
// the whole application, against the exact large-amplitude motion in Jacobi elliptic
// functions (oracles/simple_pendulum). The benchmark's measure is the largest error of
// P1's x and y over the run (oracles/iftomm_accuracy.hpp, docs/physics/benchmarks.md);
// energy is conserved exactly. Run over 10 s and over the benchmark's own 2000 s.
#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "kernel/elements/body_point.hpp"
#include "validation/checks/validation_suite.hpp"
#include "validation/oracles/iftomm_accuracy.hpp"
#include "validation/oracles/simple_pendulum.hpp"

namespace heavesim::validation {
namespace {

struct PendulumErrors {
  double position = 0.0;      // m, IFToMM: max over samples of |x - x_exact|, |y - y_exact|
  double energy_drift = 0.0;  // relative to m g L
};

PendulumErrors compare_pendulum(const std::vector<std::string>& overrides) {
  std::vector<double> times;
  std::vector<Eigen::Vector2d> positions;
  std::vector<double> energies;
  run_case("cases/validation/iftomm_a01_pendulum.yaml", overrides, [&](double t, const MultibodySystem& system) {
    // P1 is the bob's body point (1, 0, 0) (its centre of mass).
    const Vector3 p1 = BodyPoint::on_body(system.model(), "bob", Vector3(1, 0, 0)).position_world(system.data());
    times.push_back(t);
    positions.emplace_back(p1.x(), p1.y());
    energies.push_back(mechanical_energy(system));
  });
  // Released at theta0 = pi/2 from the downward vertical, towards +x.
  const std::vector<Eigen::Vector2d> exact = oracle::pendulum_mass_positions(std::numbers::pi / 2, 1.0, g, times);
  PendulumErrors errors;
  errors.position = oracle::iftomm_max_error(positions, exact);
  const double energy_scale = 1.0 * g * 1.0;  // m g L, J
  for (double energy : energies)
    errors.energy_drift = std::max(errors.energy_drift, std::abs(energy - energies.front()) / energy_scale);
  return errors;
}

}  // namespace

std::vector<ValidationRow> check_a01_simple_pendulum() {
  std::vector<ValidationRow> rows;
  const PendulumErrors ten_seconds = compare_pendulum({});
  const std::string subject = "A01 pendulum 10 s, Verner 6(5), rtol = atol = 1e-13";
  rows.push_back({"A01", subject, "P1 x, y vs exact (Jacobi sn), max [m]", ten_seconds.position, 1e-8});
  rows.push_back({"A01", subject, "energy drift / (m g L)", ten_seconds.energy_drift, 1e-9});
  // The benchmark's own run: 2000 s, 4000 output steps (0.5 s).
  const PendulumErrors benchmark = compare_pendulum({"solver.t_end=2000", "output.interval=0.5"});
  const std::string benchmark_subject = "A01 pendulum 2000 s (IFToMM), 4000 samples";
  rows.push_back({"A01", benchmark_subject, "P1 x, y vs exact, max [m] (IFToMM high: 1e-3)", benchmark.position, 1e-6});
  rows.push_back({"A01", benchmark_subject, "energy drift / (m g L)", benchmark.energy_drift, 1e-8});
  return rows;
}

}  // namespace heavesim::validation
