#include "app/sweep/run_record.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <optional>
#include <stdexcept>

#include "app/sweep/sweep_plan.hpp"
#include "io/hdf5/hdf5_reader.hpp"
#include "signal/statistic_fields.hpp"

namespace heavesim {
namespace {

class Writer {
 public:
  void number(double value) { raw(&value, sizeof value); }
  void integer(std::int64_t value) { raw(&value, sizeof value); }
  void text(const std::string& value) {
    integer(static_cast<std::int64_t>(value.size()));
    bytes_ += value;
  }
  std::string bytes_;

 private:
  void raw(const void* data, std::size_t size) { bytes_.append(static_cast<const char*>(data), size); }
};

class Reader {
 public:
  explicit Reader(const std::string& bytes) : bytes_(bytes) {}
  double number() {
    double value;
    raw(&value, sizeof value);
    return value;
  }
  std::int64_t integer() {
    std::int64_t value;
    raw(&value, sizeof value);
    return value;
  }
  std::string text() {
    const auto size = static_cast<std::size_t>(integer());
    if (size > bytes_.size() - position_) throw std::runtime_error("truncated run record");
    std::string value = bytes_.substr(position_, size);
    position_ += size;
    return value;
  }

 private:
  void raw(void* data, std::size_t size) {
    if (size > bytes_.size() - position_) throw std::runtime_error("truncated run record");
    std::memcpy(data, bytes_.data() + position_, size);
    position_ += size;
  }
  const std::string& bytes_;
  std::size_t position_ = 0;
};

}  // namespace

std::string encode(const RunRecord& record) {
  Writer out;
  out.text(record.status);
  out.integer(record.exit_code);
  out.number(record.wall_time_s);
  out.text(record.result_file);
  out.text(record.hash);
  out.text(record.message);
  out.integer(record.rank_or_worker);
  out.integer(record.reused);
  out.integer(static_cast<std::int64_t>(record.summary.size()));
  for (const auto& [name, value] : record.summary) {
    out.text(name);
    out.number(value);
  }
  out.integer(static_cast<std::int64_t>(record.statistics.size()));
  for (const ChannelStatistic& statistic : record.statistics) {
    out.text(statistic.channel);
    out.text(statistic.field);
    out.text(statistic.unit);
    out.integer(static_cast<std::int64_t>(statistic.columns.size()));
    for (double value : statistic.columns) out.number(value);
  }
  return out.bytes_;
}

RunRecord decode(const std::string& bytes) {
  Reader in(bytes);
  RunRecord record;
  record.status = in.text();
  record.exit_code = static_cast<int>(in.integer());
  record.wall_time_s = in.number();
  record.result_file = in.text();
  record.hash = in.text();
  record.message = in.text();
  record.rank_or_worker = static_cast<int>(in.integer());
  record.reused = in.integer() != 0;
  for (std::int64_t i = 0, n = in.integer(); i < n; ++i) {
    std::string name = in.text();
    record.summary.emplace_back(std::move(name), in.number());
  }
  for (std::int64_t i = 0, n = in.integer(); i < n; ++i) {
    ChannelStatistic statistic;
    statistic.channel = in.text();
    statistic.field = in.text();
    statistic.unit = in.text();
    for (std::int64_t c = 0, columns = in.integer(); c < columns; ++c) statistic.columns.push_back(in.number());
    record.statistics.push_back(std::move(statistic));
  }
  return record;
}

bool result_is_current(const std::string& result_path, const std::string& hash) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(result_path, error)) return false;
  try {
    const hdf5::Reader file(result_path, "a heavesim result file");
    if (file.number_attribute("/", "complete").value_or(0.0) != 1.0) return false;
    const std::optional<std::string> version = file.text_attribute("/", "heavesim_version");
    const std::vector<std::string> yaml = file.read_strings("/case/yaml");
    return version && yaml.size() == 1 && run_hash(yaml.front(), *version) == hash;
  } catch (const std::exception&) {
    return false;  // unreadable: run it again
  }
}

void read_result_quantities(const std::string& result_path, const std::vector<std::string>& channels, double duration,
                            RunRecord& record) {
  const hdf5::Reader file(result_path, "a heavesim result file");
  for (const std::string& name : file.attribute_names("/summary"))
    if (std::optional<double> value = file.scalar_number_attribute("/summary", name)) record.summary.emplace_back(name, *value);
  if (channels.empty()) return;

  // The evaluation window, as the recorder's: t >= statistics_window_start, over the
  // samples on disk (the reader's rule, docs/result-file.md).
  std::vector<double> time = file.read("/time").values;
  const auto samples =
      std::min<std::size_t>(time.size(), static_cast<std::size_t>(file.number_attribute("/", "samples_written").value_or(time.size())));
  if (samples < 2) return;
  time.resize(samples);
  const double start = file.number_attribute("/", "statistics_window_start").value_or(time.front());
  const auto first = static_cast<std::size_t>(
      std::lower_bound(time.begin(), time.end(), start - 1e-9 * std::max(1.0, std::abs(start))) - time.begin());
  if (first + 2 > samples) return;
  stats::StatisticsOptions options;
  options.time_step = (time.back() - time.front()) / static_cast<double>(samples - 1);
  options.duration = duration;

  for (const std::string& channel : channels) {
    if (!file.has(channel)) continue;
    const hdf5::Array data = file.read(channel);
    if (data.shape.empty() || data.shape.size() > 2 || data.shape[0] < samples) continue;
    const std::size_t columns = data.shape.size() == 2 ? data.shape[1] : 1;
    const std::string units = file.text_attribute(channel, "units").value_or("-");
    std::vector<stats::ResponseStatistics> results;
    for (std::size_t c = 0; c < columns; ++c) {
      std::vector<double> column(samples - first);
      for (std::size_t i = first; i < samples; ++i) column[i - first] = data.values[i * columns + c];
      results.push_back(stats::response_statistics(column, options));
    }
    for (const stats::StatisticField& field : stats::statistic_fields()) {
      ChannelStatistic statistic{channel, field.name, stats::unit_text(field.unit, units), {}};
      for (const stats::ResponseStatistics& r : results) statistic.columns.push_back(field.value(r));
      record.statistics.push_back(std::move(statistic));
    }
  }
}

}  // namespace heavesim
