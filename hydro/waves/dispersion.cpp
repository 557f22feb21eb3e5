#include "hydro/waves/dispersion.hpp"

#include <cmath>
#include <string>

#include <fmt/format.h>

#include "kernel/parameter_error.hpp"

namespace heavesim::hydro {

void check_wave_period(const char* field, const char* what, double period) {
  if (!(period >= shortest_wave_period && period <= longest_wave_period))
    throw ParameterError(field, fmt::format("{} = {:g} s", what, period),
                         fmt::format("a wave period in [{:g}, {:g}] s (a sea state of linear gravity waves)",
                                     shortest_wave_period, longest_wave_period));
}

double wave_number(double w, double h, double g) {
  if (!(g > 0.0))
    throw ParameterError("gravity", fmt::format("g = {:g} m/s^2", g),
                         "g > 0 (waves need gravity: w^2 = g k tanh(k h))");
  if (!(h > 0.0)) throw ParameterError("depth", fmt::format("a depth of {:g} m", h), "a water depth > 0 m");
  if (!(w >= 0.0))
    throw ParameterError("angular_frequency", fmt::format("w = {:g} rad/s", w), "an angular frequency >= 0 rad/s");
  const double k_deep = w * w / g;
  if (w == 0.0) return 0.0;
  // Beyond k h = 20, tanh(k h) = 1 to machine precision: the deep-water root.
  if (std::isinf(h) || k_deep * h > 20.0) return k_deep;
  // Start from the Eckart (1952) approximation, which is within 5 % everywhere, so
  // Newton on the convex f(k) = g k tanh(k h) - w^2 converges monotonically.
  double k = k_deep / std::sqrt(std::tanh(k_deep * h));
  for (int iteration = 0; iteration < 50; ++iteration) {
    const double t = std::tanh(k * h);
    const double f = g * k * t - w * w;
    const double df = g * t + g * k * h * (1.0 - t * t);
    const double step = f / df;
    k -= step;
    if (std::abs(step) <= 1e-15 * k) break;
  }
  return k;
}

double phase_speed(double w, double h, double g) { return w / wave_number(w, h, g); }

double group_speed(double w, double h, double g) {
  const double k = wave_number(w, h, g);
  const double c = w / k;
  if (std::isinf(h)) return 0.5 * c;
  const double kh = k * h;
  // c_g = c/2 (1 + 2 k h / sinh(2 k h)).
  return kh > 350.0 ? 0.5 * c : 0.5 * c * (1.0 + 2.0 * kh / std::sinh(2.0 * kh));
}

}  // namespace heavesim::hydro
