#pragma once
// Extreme-value distributions fitted by maximum likelihood to peak excursions (peaks minus
// the mean, > 0), and the most probable maximum (MPM) of N peaks they give.
//
// The MPM used throughout is the level that one of N peaks exceeds on average, the
// 1 - 1/N quantile of the peak distribution F: x_N = F^-1(1 - 1/N). For large N it is the
// mode of the distribution of the largest of N independent peaks, F(x)^N (Ochi 1998,
// "Ocean Waves"; DNV-RP-C205 sec. 3.5); for Rayleigh peaks it is sigma sqrt(2 ln N).
#include <algorithm>
#include <cstdint>
#include <limits>
#include <vector>

namespace heavesim::stats {

/// Two-parameter Weibull F(y) = 1 - exp(-(y / scale)^shape), y >= 0.
struct WeibullFit {
  double shape = std::numeric_limits<double>::quiet_NaN();  // k, -
  double scale = std::numeric_limits<double>::quiet_NaN();  // lambda, units of y
  double ks_statistic = std::numeric_limits<double>::quiet_NaN();  // sup |F_empirical - F|, -
  std::int64_t samples = 0;
  double cdf(double y) const;
  /// F^-1(1 - 1/N): the level one of N values exceeds on average (units of y).
  double level_exceeded_once_in(double n) const;
};
/// Maximum-likelihood fit to the positive values of `y` (at least `minimum_samples` of
/// them, else a fit of NaN). The likelihood equation for the shape,
///   sum y^k ln y / sum y^k - 1/k - mean(ln y) = 0,
/// is increasing in k and solved by Newton's method safeguarded by bisection; the scale follows as
/// (mean y^k)^(1/k) (Cohen 1965, Technometrics 7(4)).
WeibullFit fit_weibull(const std::vector<double>& y, std::int64_t minimum_samples = 10);

/// Generalised Pareto G(y) = 1 - (1 + shape y / scale)^(-1/shape) for the excesses y > 0
/// over a threshold (exponential when shape = 0); Coles (2001) ch. 4.
struct GeneralizedParetoFit {
  double threshold = std::numeric_limits<double>::quiet_NaN();  // u, units of the data
  double shape = std::numeric_limits<double>::quiet_NaN();      // xi, -
  double scale = std::numeric_limits<double>::quiet_NaN();      // sigma_u, units of the data
  double ks_statistic = std::numeric_limits<double>::quiet_NaN();
  std::int64_t exceedances = 0;
  double cdf(double excess) const;
  /// u + G^-1(1 - 1/n): the level one of n exceedances passes on average.
  double level_exceeded_once_in(double n) const;
};
/// Maximum-likelihood fit to the excesses `data - threshold` of the values above
/// `threshold` (at least `minimum_samples`, else NaN). Grimshaw (1993, Technometrics
/// 35(2)): with theta = shape / scale the likelihood's maximum over shape for a given
/// theta is shape = mean ln(1 + theta y), which leaves a one-dimensional search over theta
/// (a grid, then golden-section refinement), limited to shape > -1 where the maximum
/// likelihood estimator exists.
GeneralizedParetoFit fit_generalized_pareto(const std::vector<double>& data, double threshold,
                                            std::int64_t minimum_samples = 10);

/// Kolmogorov-Smirnov statistic sup |F_n(y) - F(y)| of `sorted` (ascending) against `cdf`.
template <class Cdf>
double kolmogorov_smirnov(const std::vector<double>& sorted, const Cdf& cdf) {
  double largest = 0.0;
  const double n = static_cast<double>(sorted.size());
  for (std::size_t i = 0; i < sorted.size(); ++i) {
    const double f = cdf(sorted[i]);
    largest = std::max({largest, (static_cast<double>(i) + 1.0) / n - f, f - static_cast<double>(i) / n});
  }
  return largest;
}

}  // namespace heavesim::stats
