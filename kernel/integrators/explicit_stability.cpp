#include "kernel/integrators/explicit_stability.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace heavesim {

ButcherTableau classical_rk4_tableau() {
  return {4, {0, 0, 0, 0, 0.5, 0, 0, 0, 0, 0.5, 0, 0, 0, 0, 1, 0}, {1.0 / 6, 1.0 / 3, 1.0 / 3, 1.0 / 6}};
}

std::complex<double> stability_function(const ButcherTableau& tableau, std::complex<double> z) {
  // Stage values for y' = y, y0 = 1: g_i = 1 + z sum_{j<i} a_ij g_j; R = 1 + z b . g.
  const int s = tableau.stages;
  std::vector<std::complex<double>> g(s);
  std::complex<double> result = 1.0;
  for (int i = 0; i < s; ++i) {
    std::complex<double> sum = 0.0;
    for (int j = 0; j < i; ++j) sum += tableau.a[i * s + j] * g[j];
    g[i] = 1.0 + z * sum;
    result += z * tableau.b[i] * g[i];
  }
  return result;
}

double stability_limit(const ButcherTableau& tableau, std::complex<double> lambda) {
  const std::complex<double> mode(std::min(lambda.real(), 0.0), lambda.imag());
  const double size = std::abs(mode);
  if (!(size > 0.0)) return std::numeric_limits<double>::infinity();
  const std::complex<double> direction = mode / size;
  // Walk out along the ray until |R| exceeds 1, then bisect. Explicit methods' regions
  // end within |z| < 7 (Fehlberg 8(7)'s reaches ~5); beyond 20 the mode limits nothing.
  const auto stable = [&](double s) { return std::abs(stability_function(tableau, s * direction)) <= 1.0 + 1e-4; };
  double inside = 0.0, outside = 0.0;
  for (double s = 0.01; s <= 20.0; s += 0.01) {
    if (!stable(s)) {
      outside = s;
      break;
    }
    inside = s;
  }
  if (outside == 0.0) return 20.0 / size;
  for (int k = 0; k < 40; ++k) {
    const double middle = 0.5 * (inside + outside);
    (stable(middle) ? inside : outside) = middle;
  }
  return inside / size;
}

std::string fast_mode_remedy(const FastestMode& mode, double steps_needed) {
  std::string text = "an implicit integrator, stable at any step: solver.integrator: hht (it steps over a fast "
                     "oscillation) or ida (it resolves one that is excited)";
  if (!mode.element.empty()) text += "; or soften " + mode.element + " if it is stiffer than intended";
  if (steps_needed > 0.0) {
    char steps[64];
    std::snprintf(steps, sizeof steps, "; or solver.max_steps above %.3g", steps_needed);
    text += steps;
  }
  return text;
}

NumericalError beyond_stability_limit(double t, const std::string& method, double step, double limit,
                                      const FastestMode& mode, const std::string& symptom) {
  char what[200];
  std::snprintf(what, sizeof what, "the step of %.3g s is beyond %s's stability limit of %.3g s for ", step,
                method.c_str(), limit);
  char smaller[160];
  std::snprintf(smaller, sizeof smaller, "solver.step <= %.2g s (0.8 x the stability limit), or ", 0.8 * limit);
  return NumericalError(t,
                        what + mode.description() + ", so the state grew without bound (first symptom: " + symptom +
                            ")",
                        smaller + fast_mode_remedy(mode, 0.0));
}

}  // namespace heavesim
