// heavesim stats: the response statistics (signal/response_statistics.hpp) of the
// channels of a result file, over [--after, end] and with the most probable maxima over
// --duration; a table per channel column, or JSON. The same names as the attributes the
// recorder writes (stats::statistic_fields()).
#include <algorithm>
#include <cmath>
#include <optional>

#include <fmt/format.h>

#include "app/case/input_error.hpp"
#include "cli/commands/commands.hpp"
#include "cli/commands/recorded_time.hpp"
#include "io/hdf5/hdf5_reader.hpp"
#include "signal/statistic_fields.hpp"

namespace heavesim {
namespace {

constexpr const char* result_kind = "a heavesim result file (HDF5)";

/// A bad file or channel as the product's bad-input error (exit 2): file, key path, found, expected.
InputError as_input_error(const hydro::DataError& error, const std::string& file, const std::string& channel) {
  return InputError(SourceLocation{file, 0, 0}, channel, error.found(), error.expected());
}

/// The time series of the file: numeric datasets whose first axis has one row per sample.
bool is_channel(const hdf5::Reader& reader, const std::string& dataset, hsize_t samples) {
  if (dataset == "/time") return false;
  const std::vector<hsize_t> shape = reader.shape(dataset);
  return (shape.size() == 1 || shape.size() == 2) && shape[0] >= samples && reader.text_attribute(dataset, "units");
}

std::string json_number(double value) { return std::isfinite(value) ? fmt::format("{:.17g}", value) : "null"; }

std::string json_string(const std::string& text) {
  std::string quoted = "\"";
  for (char c : text) {
    if (c == '"' || c == '\\') quoted += '\\';
    quoted += c;
  }
  return quoted + "\"";
}

}  // namespace

int stats_command(const StatsOptions& options) {
  const std::string& path = options.result_path;
  std::optional<hdf5::Reader> opened;
  try {
    opened.emplace(path, result_kind);
  } catch (const hydro::DataError& error) {
    throw as_input_error(error, path, "");
  }
  const hdf5::Reader& reader = *opened;
  if (!(options.duration > 0.0) || !std::isfinite(options.duration))
    throw InputError(SourceLocation{"--duration", 0, 0}, "", fmt::format("{}", options.duration),
                     "a duration > 0 s (default 10800 s = 3 h)");

  const RecordedTime recorded = read_recorded_time(reader, path, 2);
  const std::vector<double>& time = recorded.time;
  const auto samples = static_cast<hsize_t>(time.size());
  const double dt = recorded.step;

  // The window: --after, else the one the run evaluated (output.evaluate_after).
  const double after = options.after.value_or(reader.number_attribute("/", "statistics_window_start").value_or(time.front()));
  const auto first = static_cast<hsize_t>(std::lower_bound(time.begin(), time.end(), after - 1e-9 * std::max(1.0, std::abs(after))) - time.begin());
  if (first + 2 > samples)
    throw InputError(SourceLocation{"--after", 0, 0}, "", fmt::format("{} s", after),
                     fmt::format("a start before the last two samples ({} s)", time[samples - 2]));

  std::vector<std::string> channels = options.channels;
  if (channels.empty())
    for (const std::string& dataset : reader.datasets())
      if (is_channel(reader, dataset, samples)) channels.push_back(dataset);

  stats::StatisticsOptions statistics_options;
  statistics_options.time_step = dt;
  statistics_options.duration = options.duration;

  std::string json = fmt::format("{{\"file\": {}, \"time_step\": {}, \"window_start\": {}, \"duration\": {}, \"channels\": [",
                                 json_string(path), json_number(dt), json_number(time[first]), json_number(options.duration));
  bool first_entry = true;
  if (!options.json)
    fmt::print("{}: {} samples, step {:.6g} s; window {:.6g} .. {:.6g} s; MPM duration {:.6g} s\n", path, samples, dt,
               time[first], time.back(), options.duration);
  for (const std::string& requested : channels) {
    const std::string channel = requested.starts_with('/') ? requested : "/" + requested;
    hdf5::Array data;
    std::string units;
    try {
      if (!reader.has(channel))
        throw InputError(SourceLocation{path, 0, 0}, channel, "no such dataset",
                         "a recorded channel (`heavesim stats " + path + "` lists them all)");
      data = reader.read(channel);
      units = reader.text_attribute(channel, "units").value_or("-");
    } catch (const hydro::DataError& error) {
      throw as_input_error(error, path, channel);
    }
    if (data.shape.empty() || data.shape.size() > 2 || data.shape[0] < samples)
      throw InputError(SourceLocation{path, 0, 0}, channel, "shape " + hdf5::shape_text(data.shape),
                       fmt::format("a time series of at least {} rows (N) or (N, columns)", samples));
    const hsize_t columns = data.shape.size() == 2 ? data.shape[1] : 1;
    for (hsize_t c = 0; c < columns; ++c) {
      std::vector<double> column(samples - first);
      for (hsize_t i = first; i < samples; ++i) column[i - first] = data.values[i * columns + c];
      const stats::ResponseStatistics r = stats::response_statistics(column, statistics_options);
      const std::string name = columns > 1 ? fmt::format("{}[{}]", channel, c) : channel;
      if (options.json) {
        json += fmt::format("{}{{\"channel\": {}, \"column\": {}, \"units\": {}, \"statistics\": {{", first_entry ? "" : ", ",
                            json_string(channel), c, json_string(units));
        bool first_field = true;
        for (const stats::StatisticField& field : stats::statistic_fields()) {
          json += fmt::format("{}{}: {}", first_field ? "" : ", ", json_string(field.name), json_number(field.value(r)));
          first_field = false;
        }
        json += "}}";
        first_entry = false;
        continue;
      }
      fmt::print("\n{} [{}]\n", name, units);
      for (const stats::StatisticField& field : stats::statistic_fields())
        fmt::print("  {:<32} {:>14.6g}  {:<12} {}\n", field.name, field.value(r), stats::unit_text(field.unit, units),
                   field.description);
    }
  }
  if (options.json) fmt::print("{}]}}\n", json);
  return 0;
}

}  // namespace heavesim
