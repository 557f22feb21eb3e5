// C1: the passive compensator as a 1-DOF isolator. A 290 t load on the default gas
// spring, the platform's heave prescribed by a driver (cases/validation/
// c1_passive_compensator.yaml), small amplitude; the simulated compensation efficiency
// 1 - |X / Z| against the linear transmissibility of an undamped spring-mass,
//   X / Z = k / (k - M w^2),  k = n p0 A^2 / V0,  p0 = p_atm + M g / A (static balance),
// for heave periods of 8, 10, 12 and 14 s (docs/physics/compensators.md §6; drilling-rig.md §6, C2).
#include <cmath>

#include <Eigen/QR>
#include <fmt/format.h>

#include "validation/checks/validation_suite.hpp"

namespace heavesim::validation {
namespace {

constexpr const char* case_path = "cases/validation/c1_passive_compensator.yaml";
// The case's parameters (the reference is computed here, not read from the run).
using namespace default_gas_spring;
constexpr double M = 290000.0, Z = 0.1;

/// Amplitude of the load's earth-fixed heave at frequency w, fitted by least squares
/// together with a possible free oscillation at w_n and an offset.
double forced_amplitude(const std::vector<double>& times, const std::vector<double>& heave, double w, double w_n) {
  const int rows = static_cast<int>(times.size());
  Eigen::MatrixXd basis(rows, 5);
  Eigen::VectorXd values(rows);
  for (int r = 0; r < rows; ++r) {
    const double t = times[r];
    basis.row(r) << std::sin(w * t), std::cos(w * t), std::sin(w_n * t), std::cos(w_n * t), 1.0;
    values[r] = heave[r];
  }
  const Eigen::VectorXd c = basis.colPivHouseholderQr().solve(values);
  return std::hypot(c[0], c[1]);
}

}  // namespace

std::vector<ValidationRow> check_c1_passive_compensator() {
  const double p0 = p_atm + M * g / A;
  const double k = n * p0 * A * A / V0;
  double error = 0.0;
  std::string detail;
  for (double period : {8.0, 10.0, 12.0, 14.0}) {
    const double w = 2 * M_PI / period;
    const double reference = 1.0 - std::abs(k / (k - M * w * w));
    std::vector<double> times, heave;
    run_case(case_path, {fmt::format("parameters.T={}", period)}, [&](double t, const MultibodySystem& system) {
      times.push_back(t);
      heave.push_back(system.configuration()[0] + system.configuration()[1]);  // platform heave + stroke
    });
    const double efficiency = 1.0 - forced_amplitude(times, heave, w, std::sqrt(k / M)) / Z;
    error = std::max(error, std::abs(efficiency - reference));
    detail += fmt::format("{}{:g} s: {:.4f}", detail.empty() ? "" : ", ", period, efficiency);
  }
  return {{"C1", "passive compensator, prescribed heave 0.1 m, T = 8..14 s (" + detail + ")",
           "efficiency vs k / (k - M w^2), absolute", error, 0.005}};
}

}  // namespace heavesim::validation
