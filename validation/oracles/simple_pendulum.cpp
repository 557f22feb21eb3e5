#include "validation/oracles/simple_pendulum.hpp"

#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace heavesim::oracle {

namespace {
constexpr int max_agm_steps = 32;  // the AGM converges quadratically: ~6 steps reach 1e-16 for m <= 0.99
}

JacobiSnCn jacobi_sn_cn(double u, double parameter_m) {
  if (!(parameter_m >= 0.0 && parameter_m < 1.0)) throw std::invalid_argument("jacobi_sn_cn: m must be in [0, 1)");
  // Descending Landen / AGM scale, A&S 16.4.3: a_{n+1} = (a_n + b_n)/2, b_{n+1} = sqrt(a_n b_n),
  // c_{n+1} = (a_n - b_n)/2 from a_0 = 1, b_0 = sqrt(1 - m), c_0 = sqrt(m); then
  // phi_N = 2^N a_N u and sin(2 phi_{n-1} - phi_n) = (c_n / a_n) sin(phi_n); sn = sin(phi_0).
  std::array<double, max_agm_steps + 1> a{}, c{};
  a[0] = 1.0;
  c[0] = std::sqrt(parameter_m);
  double b = std::sqrt(1.0 - parameter_m);
  int steps = 0;
  while (std::abs(c[steps]) > 1e-17 * a[steps] && steps < max_agm_steps) {
    a[steps + 1] = 0.5 * (a[steps] + b);
    c[steps + 1] = 0.5 * (a[steps] - b);
    b = std::sqrt(a[steps] * b);
    ++steps;
  }
  // Reduce u modulo the real period 4K so the angle phi_N stays small (no loss of digits at large t).
  const double quarter_period = std::numbers::pi / (2.0 * a[steps]);
  const double reduced = u - 4.0 * quarter_period * std::floor(u / (4.0 * quarter_period));
  double phi = std::ldexp(a[steps] * reduced, steps);
  for (int n = steps; n >= 1; --n) phi = 0.5 * (phi + std::asin(c[n] / a[n] * std::sin(phi)));
  return {std::sin(phi), std::cos(phi)};
}

double complete_elliptic_integral_k(double parameter_m) {
  if (!(parameter_m >= 0.0 && parameter_m < 1.0))
    throw std::invalid_argument("complete_elliptic_integral_k: m must be in [0, 1)");
  double a = 1.0, b = std::sqrt(1.0 - parameter_m);
  for (int step = 0; step < max_agm_steps && std::abs(a - b) > 1e-17 * a; ++step) {
    const double next_a = 0.5 * (a + b);
    b = std::sqrt(a * b);
    a = next_a;
  }
  return std::numbers::pi / (2.0 * a);  // A&S 17.6.1
}

double pendulum_angle(double theta0, double length, double gravity, double time) {
  const double modulus_k = std::sin(0.5 * theta0);
  const double parameter_m = modulus_k * modulus_k;
  const double natural_frequency = std::sqrt(gravity / length);
  const double quarter_period = complete_elliptic_integral_k(parameter_m);
  // At t = 0, sn(K) = 1: theta = theta0, and d(theta)/dt = 0 (cn(K) = 0).
  const JacobiSnCn value = jacobi_sn_cn(quarter_period - natural_frequency * time, parameter_m);
  return 2.0 * std::asin(modulus_k * value.sn);
}

std::vector<Eigen::Vector2d> pendulum_mass_positions(double theta0, double length, double gravity,
                                                     const std::vector<double>& times) {
  std::vector<Eigen::Vector2d> positions;
  positions.reserve(times.size());
  for (double t : times) {
    const double theta = pendulum_angle(theta0, length, gravity, t);
    positions.emplace_back(length * std::sin(theta), -length * std::cos(theta));
  }
  return positions;
}

}  // namespace heavesim::oracle
