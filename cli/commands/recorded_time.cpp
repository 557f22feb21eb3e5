#include "cli/commands/recorded_time.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "app/case/input_error.hpp"

namespace heavesim {

RecordedTime read_recorded_time(const hdf5::Reader& file, const std::string& path, std::size_t minimum_samples) {
  RecordedTime recorded;
  std::size_t samples = 0;
  try {
    recorded.time = file.read("/time").values;
    samples = static_cast<std::size_t>(file.number_attribute("/", "samples_written").value_or(recorded.time.size()));
  } catch (const hydro::DataError& error) {
    throw InputError(SourceLocation{path, 0, 0}, "/time", error.found(), error.expected());
  }
  samples = std::min(samples, recorded.time.size());  // the reader's rule (docs/result-file.md)
  if (samples < minimum_samples)
    throw InputError(SourceLocation{path, 0, 0}, "/time", fmt::format("{} samples", samples),
                     fmt::format("at least {} samples", minimum_samples));
  recorded.time.resize(samples);
  const std::vector<double>& time = recorded.time;
  recorded.step = (time.back() - time.front()) / static_cast<double>(samples - 1);
  for (std::size_t i = 1; i < samples; ++i)
    if (std::abs(time[i] - time[i - 1] - recorded.step) > 1e-6 * recorded.step)
      throw InputError(SourceLocation{path, 0, 0}, "/time", fmt::format("a step of {} s at sample {}", time[i] - time[i - 1], i),
                       fmt::format("a uniform step ({} s)", recorded.step));
  return recorded;
}

}  // namespace heavesim
