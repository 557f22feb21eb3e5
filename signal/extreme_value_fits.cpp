#include "signal/extreme_value_fits.hpp"

#include <algorithm>
#include <cmath>

namespace heavesim::stats {
namespace {
constexpr double nan_value = std::numeric_limits<double>::quiet_NaN();
}

double WeibullFit::cdf(double y) const { return y <= 0.0 ? 0.0 : 1.0 - std::exp(-std::pow(y / scale, shape)); }

double WeibullFit::level_exceeded_once_in(double n) const {
  if (!(n > 1.0)) return nan_value;
  return scale * std::pow(std::log(n), 1.0 / shape);
}

WeibullFit fit_weibull(const std::vector<double>& values, std::int64_t minimum_samples) {
  WeibullFit fit;
  std::vector<double> y;
  for (double v : values)
    if (v > 0.0 && std::isfinite(v)) y.push_back(v);
  fit.samples = static_cast<std::int64_t>(y.size());
  if (fit.samples < std::max<std::int64_t>(minimum_samples, 2)) return fit;
  std::sort(y.begin(), y.end());
  if (y.front() == y.back()) return fit;  // no spread: no shape
  // Scale the data by its largest value (y^k stays in [0, 1]: no overflow at large k).
  const double top = y.back();
  double mean_log = 0.0;
  for (double& v : y) {
    v /= top;
    mean_log += std::log(v);
  }
  mean_log /= static_cast<double>(y.size());
  std::vector<double> logs(y.size());
  for (std::size_t i = 0; i < y.size(); ++i) logs[i] = std::log(y[i]);
  // g(k) = S1/S0 - 1/k - mean(ln y) with S_j = sum y^k (ln y)^j, and
  // g'(k) = (S2 S0 - S1^2) / S0^2 + 1/k^2 > 0: Newton, kept inside the bracket where g
  // changes sign (a bisection step on ln k whenever Newton would leave it).
  auto equation = [&logs, mean_log](double k, double* slope) {
    double s0 = 0.0, s1 = 0.0, s2 = 0.0;
    for (double l : logs) {
      const double p = std::exp(k * l);
      s0 += p;
      s1 += p * l;
      s2 += p * l * l;
    }
    *slope = (s2 * s0 - s1 * s1) / (s0 * s0) + 1.0 / (k * k);
    return s1 / s0 - 1.0 / k - mean_log;
  };
  double slope = 0.0, low = 1e-3, high = 1e3;
  if (equation(low, &slope) > 0.0 || equation(high, &slope) < 0.0) return fit;
  double k = 1.0;
  for (int iteration = 0; iteration < 200; ++iteration) {
    const double value = equation(k, &slope);
    (value < 0.0 ? low : high) = k;
    double next = k - value / slope;
    if (!(next > low && next < high)) next = std::sqrt(low * high);  // bisection on ln k
    const bool converged = std::abs(next - k) <= 1e-12 * k;
    k = next;
    if (converged || high / low - 1.0 < 1e-12) break;
  }
  double mean_power = 0.0;
  for (double v : y) mean_power += std::pow(v, k);
  mean_power /= static_cast<double>(y.size());
  fit.shape = k;
  fit.scale = top * std::pow(mean_power, 1.0 / k);
  for (double& v : y) v *= top;
  fit.ks_statistic = kolmogorov_smirnov(y, [&fit](double v) { return fit.cdf(v); });
  return fit;
}

double GeneralizedParetoFit::cdf(double excess) const {
  if (excess <= 0.0) return 0.0;
  if (std::abs(shape) < 1e-12) return 1.0 - std::exp(-excess / scale);
  const double base = 1.0 + shape * excess / scale;
  if (base <= 0.0) return 1.0;  // beyond the upper end point (shape < 0)
  return 1.0 - std::pow(base, -1.0 / shape);
}

double GeneralizedParetoFit::level_exceeded_once_in(double n) const {
  if (!(n > 1.0)) return nan_value;
  if (std::abs(shape) < 1e-12) return threshold + scale * std::log(n);
  return threshold + scale / shape * (std::pow(n, shape) - 1.0);
}

GeneralizedParetoFit fit_generalized_pareto(const std::vector<double>& data, double threshold,
                                            std::int64_t minimum_samples) {
  GeneralizedParetoFit fit;
  fit.threshold = threshold;
  std::vector<double> y;
  for (double v : data)
    if (v > threshold && std::isfinite(v)) y.push_back(v - threshold);
  fit.exceedances = static_cast<std::int64_t>(y.size());
  if (fit.exceedances < std::max<std::int64_t>(minimum_samples, 2)) return fit;
  std::sort(y.begin(), y.end());
  const double n = static_cast<double>(y.size());
  double mean = 0.0;
  for (double v : y) mean += v;
  mean /= n;
  if (!(mean > 0.0) || y.front() == y.back()) return fit;
  // t = theta * mean (dimensionless); the profile log-likelihood per exceedance, with
  // xi(t) = mean ln(1 + t y / mean) and sigma = xi / theta, is
  //   l(t) = -ln(sigma) - (1 + xi)   (Grimshaw 1993, eq. 2.3; the exponential at t = 0).
  auto shape_at = [&y, mean](double t) {
    double sum = 0.0;
    for (double v : y) sum += std::log1p(t * v / mean);
    return sum / static_cast<double>(y.size());
  };
  auto profile = [&shape_at, mean](double t) {
    if (std::abs(t) < 1e-10) return -std::log(mean) - 1.0;
    const double xi = shape_at(t);
    if (!(xi > -1.0)) return -std::numeric_limits<double>::infinity();
    const double sigma = xi / t * mean;
    if (!(sigma > 0.0)) return -std::numeric_limits<double>::infinity();
    return -std::log(sigma) - (1.0 + xi);
  };
  // Grid over t in (-mean / y_max, 1e4]: uniform below 0 (up to the end point of a
  // bounded tail), logarithmic above (a fifth of a decade apart), then a golden-section
  // search in the best point's two neighbouring intervals. Each evaluation is a log1p per
  // exceedance: with 401 grid points and a search to 1e-12 the fits were 8 % of a 3-hour
  // run's process. 81 points and 1e-10 moved the 190 shapes of the free semi's 3-hour run
  // by 4e-7 relative at most (their standard error is ~0.1 from ~100 exceedances): the
  // likelihood is flat at its maximum, so round-off, not the tolerance, ends both searches.
  // Its scores vanish at the fit (tests/signal/test_response_statistics.cpp).
  const double lowest = -mean / y.back() * (1.0 - 1e-9);
  std::vector<double> grid;
  for (int i = 1; i <= 40; ++i) grid.push_back(lowest * (1.0 - i / 41.0));
  grid.push_back(0.0);
  for (int i = 0; i <= 40; ++i) grid.push_back(std::pow(10.0, -4.0 + 8.0 * i / 40.0));
  std::size_t best = 0;
  double best_profile = profile(grid[0]);
  for (std::size_t i = 1; i < grid.size(); ++i) {
    const double value = profile(grid[i]);
    if (value > best_profile) {
      best = i;
      best_profile = value;
    }
  }
  double a = grid[best > 0 ? best - 1 : 0], b = grid[std::min(best + 1, grid.size() - 1)];
  const double golden = 0.5 * (std::sqrt(5.0) - 1.0);
  double c = b - golden * (b - a), d = a + golden * (b - a);
  double profile_c = profile(c), profile_d = profile(d);
  for (int iteration = 0; iteration < 200 && std::abs(b - a) > 1e-10 * (1.0 + std::abs(a)); ++iteration) {
    if (profile_c > profile_d) {  // the maximum is in [a, d]: d becomes the new c's partner
      b = d;
      d = c;
      profile_d = profile_c;
      c = b - golden * (b - a);
      profile_c = profile(c);
    } else {
      a = c;
      c = d;
      profile_c = profile_d;
      d = a + golden * (b - a);
      profile_d = profile(d);
    }
  }
  const double t = 0.5 * (a + b);
  if (std::abs(t) < 1e-10) {
    fit.shape = 0.0;
    fit.scale = mean;
  } else {
    fit.shape = shape_at(t);
    fit.scale = fit.shape / t * mean;
  }
  fit.ks_statistic = kolmogorov_smirnov(y, [&fit](double v) { return fit.cdf(v); });
  return fit;
}

}  // namespace heavesim::stats
