#include "signal/statistic_fields.hpp"

namespace heavesim::stats {

const std::vector<StatisticField>& statistic_fields() {
  using R = ResponseStatistics;
  using U = FieldUnit;
  using G = FieldGroup;
  static const std::vector<StatisticField> fields = {
      {"window_samples", G::moments, U::count, "samples in the evaluation window",
       [](const R& r) { return static_cast<double>(r.samples); }},
      {"window_mean", G::moments, U::signal, "mean", [](const R& r) { return r.mean; }},
      {"window_standard_deviation", G::moments, U::signal, "standard deviation (n - 1)",
       [](const R& r) { return r.standard_deviation; }},
      {"window_minimum", G::moments, U::signal, "smallest sample", [](const R& r) { return r.minimum; }},
      {"window_maximum", G::moments, U::signal, "largest sample", [](const R& r) { return r.maximum; }},
      {"skewness", G::moments, U::none, "m3 / m2^1.5", [](const R& r) { return r.skewness; }},
      {"kurtosis", G::moments, U::none, "m4 / m2^2 (Gaussian: 3)", [](const R& r) { return r.kurtosis; }},
      {"upcrossings", G::cycles, U::count, "up-crossings of the mean", [](const R& r) { return static_cast<double>(r.upcrossings); }},
      {"zero_upcrossing_period", G::cycles, U::seconds, "Tz = window duration / up-crossings",
       [](const R& r) { return r.zero_upcrossing_period; }},
      {"cycles", G::cycles, U::count, "complete cycles (crests)", [](const R& r) { return static_cast<double>(r.crests.size()); }},
      {"significant_crest", G::cycles, U::signal, "mean of the highest third of the crests",
       [](const R& r) { return r.significant_crest; }},
      {"significant_trough", G::cycles, U::signal, "mean of the lowest third of the troughs",
       [](const R& r) { return r.significant_trough; }},
      {"mean_plus_4_sigma", G::moments, U::signal, "mean + 4 standard deviations", [](const R& r) { return r.mean_plus_4_sigma; }},
      {"mean_minus_4_sigma", G::moments, U::signal, "mean - 4 standard deviations", [](const R& r) { return r.mean_minus_4_sigma; }},
      {"mpm_duration", G::cycles, U::seconds, "D of the *_duration maxima", [](const R& r) { return r.duration; }},
      {"cycles_in_duration", G::cycles, U::none, "N = D / Tz", [](const R& r) { return r.cycles_in_duration; }},
      {"mpm_rayleigh", G::cycles, U::signal, "Rayleigh MPM over the window: mean + std sqrt(2 ln cycles)",
       [](const R& r) { return r.rayleigh.record; }},
      {"mpm_rayleigh_duration", G::cycles, U::signal, "Rayleigh MPM over D: mean + std sqrt(2 ln(D / Tz))",
       [](const R& r) { return r.rayleigh.duration; }},
      {"mpm_minimum_rayleigh_duration", G::cycles, U::signal, "Rayleigh most probable minimum over D",
       [](const R& r) { return r.rayleigh_minimum.duration; }},
      {"weibull_shape", G::cycles, U::none, "Weibull shape k of crest - mean (maximum likelihood)",
       [](const R& r) { return r.weibull.shape; }},
      {"weibull_scale", G::cycles, U::signal, "Weibull scale of crest - mean", [](const R& r) { return r.weibull.scale; }},
      {"weibull_ks_statistic", G::cycles, U::none, "Kolmogorov-Smirnov statistic of the Weibull fit",
       [](const R& r) { return r.weibull.ks_statistic; }},
      {"mpm_weibull", G::cycles, U::signal, "Weibull MPM over the window", [](const R& r) { return r.weibull_maximum.record; }},
      {"mpm_weibull_duration", G::cycles, U::signal, "Weibull MPM over D", [](const R& r) { return r.weibull_maximum.duration; }},
      {"pareto_threshold", G::cycles, U::signal, "threshold u of crest - mean (exceeded by a third of the crests)",
       [](const R& r) { return r.pareto.threshold; }},
      {"pareto_exceedances", G::cycles, U::count, "crests over the threshold",
       [](const R& r) { return static_cast<double>(r.pareto.exceedances); }},
      {"pareto_shape", G::cycles, U::none, "generalised Pareto shape xi (maximum likelihood)", [](const R& r) { return r.pareto.shape; }},
      {"pareto_scale", G::cycles, U::signal, "generalised Pareto scale", [](const R& r) { return r.pareto.scale; }},
      {"pareto_ks_statistic", G::cycles, U::none, "Kolmogorov-Smirnov statistic of the Pareto fit",
       [](const R& r) { return r.pareto.ks_statistic; }},
      {"mpm_pareto", G::cycles, U::signal, "generalised Pareto MPM over the window", [](const R& r) { return r.pareto_maximum.record; }},
      {"mpm_pareto_duration", G::cycles, U::signal, "generalised Pareto MPM over D", [](const R& r) { return r.pareto_maximum.duration; }},
      {"spectral_peak_period", G::spectrum, U::seconds, "Tp = 1 / frequency of the largest Welch density",
       [](const R& r) { return r.spectrum.peak_period; }},
      {"spectral_m0", G::spectrum, U::signal_squared, "m0 = sum S df (Hz)", [](const R& r) { return r.spectrum.m0; }},
      {"spectral_m2", G::spectrum, U::signal_squared_hz2, "m2 = sum f^2 S df (Hz)", [](const R& r) { return r.spectrum.m2; }},
      {"spectral_m4", G::spectrum, U::signal_squared_hz4, "m4 = sum f^4 S df (Hz)", [](const R& r) { return r.spectrum.m4; }},
      {"spectral_zero_upcrossing_period", G::spectrum, U::seconds, "Tz = sqrt(m0 / m2) (Hz moments)",
       [](const R& r) { return r.spectrum.zero_upcrossing_period(); }},
      {"spectral_bandwidth", G::spectrum, U::none, "epsilon = sqrt(1 - m2^2 / (m0 m4))", [](const R& r) { return r.spectrum.bandwidth(); }},
  };
  return fields;
}

std::string unit_text(FieldUnit unit, const std::string& channel_units) {
  const std::string u = channel_units.find_first_of(" ,/") == std::string::npos ? channel_units : "(" + channel_units + ")";
  switch (unit) {
    case FieldUnit::signal: return channel_units;
    case FieldUnit::none: return "-";
    case FieldUnit::seconds: return "s";
    case FieldUnit::count: return "count";
    case FieldUnit::signal_squared: return u + "^2";
    case FieldUnit::signal_squared_hz2: return u + "^2 Hz^2";
    case FieldUnit::signal_squared_hz4: return u + "^2 Hz^4";
  }
  return "-";
}

}  // namespace heavesim::stats
