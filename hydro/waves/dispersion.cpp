#include "hydro/waves/dispersion.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace heavesim::hydro {

double wave_number(double w, double h, double g) {
  if (!(w >= 0.0) || !(h > 0.0) || !(g > 0.0))
    throw std::invalid_argument("wave_number: expected w >= 0, depth > 0, g > 0; found w = " + std::to_string(w) +
                                ", depth = " + std::to_string(h) + ", g = " + std::to_string(g));
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
