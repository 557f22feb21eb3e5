#include "app/sweep/sweep_index.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <set>

#include <fmt/format.h>

#include "app/output/csv_cell.hpp"
#include "app/output/output_error.hpp"
#include "app/output/table_file.hpp"
#include "app/output/utc_now.hpp"
#include "app/version.hpp"
#include "signal/statistic_fields.hpp"

namespace heavesim {
namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

/// "/joints/td_string/reaction_force" -> "joints.td_string.reaction_force".
std::string channel_key(const std::string& channel) {
  std::string key = channel.starts_with('/') ? channel.substr(1) : channel;
  for (char& c : key)
    if (c == '/') c = '.';
  return key;
}

/// One statistic column group of the index: a channel's field over the runs.
struct StatisticColumn {
  std::string channel, field, unit;
  std::size_t columns = 0;
  std::vector<double> values;  // [run][column]
};

std::vector<StatisticColumn> statistic_columns(const SweepDefinition& sweep, const std::vector<RunRecord>& records) {
  std::vector<StatisticColumn> table;
  for (const std::string& channel : sweep.statistics)
    for (const stats::StatisticField& field : stats::statistic_fields()) {
      StatisticColumn column{channel, field.name, "", 0, {}};
      for (const RunRecord& record : records)
        for (const ChannelStatistic& statistic : record.statistics)
          if (statistic.channel == channel && statistic.field == field.name) {
            column.columns = std::max(column.columns, statistic.columns.size());
            column.unit = statistic.unit;
          }
      if (column.columns == 0) continue;
      column.values.assign(records.size() * column.columns, nan);
      for (std::size_t i = 0; i < records.size(); ++i)
        for (const ChannelStatistic& statistic : records[i].statistics)
          if (statistic.channel == channel && statistic.field == field.name)
            for (std::size_t c = 0; c < statistic.columns.size() && c < column.columns; ++c)
              column.values[i * column.columns + c] = statistic.columns[c];
      table.push_back(std::move(column));
    }
  return table;
}

std::string csv_number(double value) { return std::isnan(value) ? "" : fmt::format("{:.17g}", value); }

}  // namespace

void write_sweep_index(const std::string& directory, const SweepDefinition& sweep, const SweepPlan& plan,
                       const std::vector<RunRecord>& records) {
  const std::size_t n = plan.runs.size();
  std::set<std::string> summary_names;
  for (const RunRecord& record : records)
    for (const auto& [name, value] : record.summary) summary_names.insert(name);
  std::map<std::string, std::vector<double>> summary;
  for (const std::string& name : summary_names) summary[name].assign(n, nan);
  for (std::size_t i = 0; i < n; ++i)
    for (const auto& [name, value] : records[i].summary) summary[name][i] = value;
  const std::vector<StatisticColumn> statistics = statistic_columns(sweep, records);
  const bool complete = std::none_of(records.begin(), records.end(),
                                     [](const RunRecord& r) { return r.status == run_status::pending; });

  const std::string path = (std::filesystem::path(directory) / "index.h5").string();
  const std::string partial = path + ".partial";
  {
    TableFile file(partial, "the sweep index");
    file.attribute("/", "sweep_file", sweep.sweep_file);
    std::string bases;
    for (const std::string& base : sweep.base_cases) bases += (bases.empty() ? "" : "\n") + base;
    file.attribute("/", "base_case", bases);
    file.attribute("/", "heavesim_version", std::string(heavesim_version));
    file.attribute("/", "created_utc", utc_now());
    file.attribute("/", "run_count", static_cast<long>(n));
    file.attribute("/", "complete", complete ? 1L : 0L);
    file.attribute("/", "sampling", std::string(sampling_name(sweep.sampling)));
    file.attribute("/", "statistics_duration_s", sweep.duration);
    if (sweep.scatter) file.attribute("/", "scatter_file", sweep.scatter->file);

    for (std::size_t j = 0; j < plan.columns.size(); ++j) {
      std::vector<double> values;
      for (const PlannedRun& run : plan.runs) values.push_back(run.values[j]);
      const bool scatter_column = sweep.scatter && j + 2 >= plan.columns.size();
      const std::string units = !scatter_column ? "as the case key" : plan.columns[j] == "Hs" ? "m" : "s";
      file.numbers("/variables/" + plan.columns[j], values, 1, units,
                   scatter_column ? (plan.columns[j] == "Hs" ? "significant wave height" : "spectral peak period")
                                  : "the value of the case key in `path`");
      file.attribute("/variables/" + plan.columns[j], "path", plan.column_paths[j]);
    }
    if (sweep.scatter) {
      std::vector<double> probability;
      for (const PlannedRun& run : plan.runs) probability.push_back(run.probability);
      file.numbers("/scatter/probability", probability, 1, "-",
                   "occurrence of the run's sea state / sum over the scatter diagram");
    }
    std::vector<std::string> status, result_file, hash, message, base_case;
    for (const PlannedRun& run : plan.runs) base_case.push_back(run.base_case);
    std::vector<long> exit_code, worker;
    std::vector<double> wall;
    for (const RunRecord& record : records) {
      status.push_back(record.status);
      result_file.push_back(record.result_file);
      hash.push_back(record.hash);
      message.push_back(record.message);
      exit_code.push_back(record.exit_code);
      worker.push_back(record.rank_or_worker);
      wall.push_back(record.wall_time_s);
    }
    file.texts("/runs/status", status, "complete | input_error | numerical_failure | stopped | error | crashed | pending");
    file.integers("/runs/exit_code", exit_code, "the run's exit code (128 + signal when crashed; -1 when pending)");
    file.numbers("/runs/wall_time_s", wall, 1, "s", "wall time of the run (NaN when pending or reused)");
    file.texts("/runs/result_file", result_file, "the run's result file, relative to the sweep directory");
    file.texts("/runs/hash", hash, "SHA-256 of the resolved case text and the heavesim version");
    file.texts("/runs/message", message, "the last error line of the run's log (logs/<run>.log); empty when complete");
    file.integers("/runs/rank_or_worker", worker, "the worker (-j) or MPI rank that ran it");
    file.texts("/runs/base_case", base_case, "the case file the run starts from (`base`)");
    for (const auto& [name, values] : summary)
      file.numbers("/summary/" + name, values, 1, "as in the result file", "the run's /summary attribute " + name);
    for (const StatisticColumn& column : statistics)
      file.numbers("/statistics/" + channel_key(column.channel) + "/" + column.field, column.values, column.columns,
                   column.unit, "response statistic of " + column.channel + " (per column)");
    file.close();
  }
  std::error_code error;
  std::filesystem::rename(partial, path, error);
  if (error) throw OutputError(path, "cannot rename the sweep index to", error.message());

  // index.csv: the same columns, one header row (units in brackets where known).
  const std::string csv_path = (std::filesystem::path(directory) / "index.csv").string();
  std::ofstream csv(csv_path);
  std::vector<std::string> header = {"run", "status", "exit_code", "wall_time_s [s]", "result_file", "hash", "message",
                                     "rank_or_worker", "base_case"};
  for (std::size_t j = 0; j < plan.columns.size(); ++j)
    header.push_back(plan.columns[j] == "Hs" && sweep.scatter ? "Hs [m]" : plan.columns[j] == "Tp" && sweep.scatter ? "Tp [s]" : plan.columns[j]);
  if (sweep.scatter) header.push_back("probability");
  for (const auto& [name, values] : summary) header.push_back("summary." + name);
  for (const StatisticColumn& column : statistics)
    for (std::size_t c = 0; c < column.columns; ++c)
      header.push_back(fmt::format("{}.{}{}{}", channel_key(column.channel), column.field,
                                   column.columns > 1 ? fmt::format("[{}]", c) : "",
                                   column.unit.empty() || column.unit == "-" ? "" : " [" + column.unit + "]"));
  for (std::size_t k = 0; k < header.size(); ++k) csv << (k ? "," : "") << csv_text(header[k]);
  csv << "\n";
  for (std::size_t i = 0; i < n; ++i) {
    const RunRecord& r = records[i];
    csv << plan.runs[i].name << "," << r.status << "," << r.exit_code << "," << csv_number(r.wall_time_s) << ","
        << csv_text(r.result_file) << "," << r.hash << "," << csv_text(r.message) << "," << r.rank_or_worker
        << "," << csv_text(plan.runs[i].base_case);
    for (double value : plan.runs[i].values) csv << "," << csv_number(value);
    if (sweep.scatter) csv << "," << csv_number(plan.runs[i].probability);
    for (const auto& [name, values] : summary) csv << "," << csv_number(values[i]);
    for (const StatisticColumn& column : statistics)
      for (std::size_t c = 0; c < column.columns; ++c) csv << "," << csv_number(column.values[i * column.columns + c]);
    csv << "\n";
  }
  csv.close();
  if (!csv) throw OutputError(csv_path, "cannot write", std::strerror(errno));
}

}  // namespace heavesim
