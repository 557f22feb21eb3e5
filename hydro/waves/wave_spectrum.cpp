#include "hydro/waves/wave_spectrum.hpp"

#include <cmath>
#include <string>

#include <fmt/format.h>

#include "hydro/waves/dispersion.hpp"
#include "kernel/parameter_error.hpp"

namespace heavesim::hydro {
void check_sea_state(double hs, double tp) {
  if (!(hs > 0.0)) throw ParameterError("significant_height", fmt::format("Hs = {:g} m", hs), "Hs > 0 m");
  check_wave_period("peak_period", "Tp", tp);
}

double PiersonMoskowitz::operator()(double w) const {
  if (w <= 0.0) return 0.0;
  const double wp = 2.0 * M_PI / peak_period;
  const double r4 = std::pow(wp / w, 4);
  return 5.0 / 16.0 * significant_height * significant_height * r4 / w * std::exp(-1.25 * r4);
}

Jonswap::Jonswap(double hs, double tp, double gamma) : significant_height_(hs), peak_period_(tp), gamma_(gamma) {
  check_sea_state(hs, tp);
  // gamma = 1 is Pierson-Moskowitz; measured North Sea peaks stay below about 7 (Hasselmann
  // et al. 1973), and 10 bounds the quadrature's resolution of the peak below.
  if (!(gamma >= 1.0 && gamma <= 10.0))
    throw ParameterError("peak_enhancement", fmt::format("{:g}", gamma), "a peak enhancement 1 <= gamma <= 10");
  // m0 by the substitution u = (wp/w)^4 would need gamma's factor in u; plain
  // composite Simpson on w in [0.05 wp, 40 wp] (the tail beyond holds < 1e-7 of m0,
  // since S ~ w^-5) with 20000 panels is exact to ~1e-10 for this smooth integrand.
  const double wp = 2.0 * M_PI / tp;
  const double a = 0.05 * wp, b = 40.0 * wp;
  const int n = 20000;
  const double h = (b - a) / n;
  double sum = unnormalized(a) + unnormalized(b);
  for (int i = 1; i < n; ++i) sum += (i % 2 ? 4.0 : 2.0) * unnormalized(a + i * h);
  double m0 = sum * h / 3.0;
  // Tail w > b of S_PM (gamma factor 1 there): int_b^inf (5/16) Hs^2 wp^4 w^-5 dw.
  m0 += 5.0 / 64.0 * hs * hs * std::pow(wp / b, 4);
  normalization_ = hs * hs / 16.0 / m0;
}

double Jonswap::unnormalized(double w) const {
  const double wp = 2.0 * M_PI / peak_period_;
  const double sigma = w <= wp ? 0.07 : 0.09;
  const double x = (w - wp) / (sigma * wp);
  return PiersonMoskowitz{significant_height_, peak_period_}(w) * std::pow(gamma_, std::exp(-0.5 * x * x));
}

double Jonswap::operator()(double w) const { return normalization_ * unnormalized(w); }

double default_peak_enhancement(double hs, double tp) {
  check_sea_state(hs, tp);
  const double r = tp / std::sqrt(hs);
  if (r <= 3.6) return 5.0;
  if (r >= 5.0) return 1.0;
  return std::exp(5.75 - 1.15 * r);
}

}  // namespace heavesim::hydro
