#include "signal/cross_spectrum.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

#include <fmt/format.h>

#include "signal/hann_segment.hpp"

namespace heavesim::stats {

std::complex<double> CrossSpectralEstimate::transfer_function(std::size_t k) const {
  if (!(input_density[k] > 0.0)) return {std::numeric_limits<double>::quiet_NaN(), 0.0};
  return cross_density[k] / input_density[k];
}

double CrossSpectralEstimate::coherence(std::size_t k) const {
  if (!(input_density[k] > 0.0 && output_density[k] > 0.0)) return std::numeric_limits<double>::quiet_NaN();
  return std::norm(cross_density[k]) / (input_density[k] * output_density[k]);
}

CrossSpectralEstimate cross_spectral_density(const std::vector<double>& input, const std::vector<double>& output,
                                             int segment_length, double sampling_frequency) {
  if (input.size() != output.size())
    throw std::invalid_argument(
        fmt::format("cross spectrum: input has {} samples, output {}: expected equal lengths", input.size(), output.size()));
  if (!(sampling_frequency > 0.0) || !std::isfinite(sampling_frequency))
    throw std::invalid_argument(fmt::format("sampling frequency {} Hz: expected > 0", sampling_frequency));
  if (segment_length > static_cast<int>(input.size()))
    throw std::invalid_argument(fmt::format("cross spectrum: segment of {} samples in a record of {}: expected at most "
                                            "the record's length",
                                            segment_length, input.size()));
  HannSegmentTransform input_transform(segment_length), output_transform(segment_length);
  const std::size_t bins = segment_length / 2 + 1, step = segment_length / 2;
  CrossSpectralEstimate estimate;
  estimate.input_density.assign(bins, 0.0);
  estimate.output_density.assign(bins, 0.0);
  estimate.cross_density.assign(bins, 0.0);
  for (std::size_t start = 0; start + segment_length <= input.size(); start += step) {
    const std::vector<std::complex<double>>& X = input_transform.transform(input.data() + start);
    const std::vector<std::complex<double>>& Y = output_transform.transform(output.data() + start);
    for (std::size_t k = 0; k < bins; ++k) {
      estimate.input_density[k] += std::norm(X[k]);
      estimate.output_density[k] += std::norm(Y[k]);
      estimate.cross_density[k] += std::conj(X[k]) * Y[k];
    }
    ++estimate.segments;
  }
  // One-sided densities: every bin but DC and Nyquist carries its mirror's half too.
  const double scale = 1.0 / (sampling_frequency * input_transform.window_power() * estimate.segments);
  estimate.frequencies.resize(bins);
  for (std::size_t k = 0; k < bins; ++k) {
    const double one_sided = (k == 0 || k + 1 == bins) ? scale : 2.0 * scale;
    estimate.input_density[k] *= one_sided;
    estimate.output_density[k] *= one_sided;
    estimate.cross_density[k] *= one_sided;
    estimate.frequencies[k] = sampling_frequency * static_cast<double>(k) / segment_length;
  }
  return estimate;
}

}  // namespace heavesim::stats
