// `heavesim stats` on the result files of real runs: its figures against numpy and scipy
// (tests/app/stats_reference.py, computed from the file's samples straight from the
// definitions), against the closed form of an undamped oscillator, and its exit codes for
// a missing file or channel (the bad-input contract: exit 2, the file, the key, found,
// expected).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iterator>
#include <numbers>
#include <regex>
#include <string>

#include "signal/statistic_fields.hpp"
#include "tests/test_support.hpp"

namespace heavesim {
namespace {

using testing::heavesim_binary;
using testing::run_case;
using testing::run_command_line;
using testing::source_path;

/// A moored barge on a surge slide (tests/cases/moored_surge.yaml) run for 600 s.
std::string moored_run(const std::string& name, const std::string& damping) {
  const std::string output = ::testing::TempDir() + name + ".h5";
  const auto run = run_case("tests/cases/moored_surge.yaml", output,
                            "-q --set solver.t_end=600 --set 'forces[hull_damping].damping=[" + damping + ",0,0,0,0,0]'");
  EXPECT_EQ(run.exit_code, 0) << run.output;
  return output;
}

double json_value(const std::string& json, const std::string& name) {
  const std::regex pattern("\"" + name + "\": ([-0-9.eE+]+|null)");
  std::smatch match;
  if (!std::regex_search(json, match, pattern)) return std::nan("");
  return match[1] == "null" ? std::nan("") : std::stod(match[1]);
}

// Lightly damped (zeta = 0.6 %): crests that shrink cycle by cycle, so every statistic
// (crossings, significant crest, Weibull fit, Welch moments) has something to measure.
TEST(StatsCommand, FiguresMatchNumpyAndScipyComputedFromTheFile) {
  const std::string file = moored_run("stats_damped", "8.0e3");
  const std::string json_path = ::testing::TempDir() + "stats_damped.json";
  const auto stats = run_command_line(heavesim_binary() + " stats " + file + " /joints/surge/q --json --duration 3600 > " +
                                      json_path);
  ASSERT_EQ(stats.exit_code, 0) << stats.output;
  const auto reference = run_command_line("/usr/bin/python3 " + source_path("tests/app/stats_reference.py") + " " + file +
                                          " /joints/surge/q " + json_path + " 3600");
  EXPECT_EQ(reference.exit_code, 0) << reference.output;
}

// Undamped: q = cos(omega t), omega = sqrt(k / m) = sqrt(4e5 / 1e6) rad/s. Over the
// window 300 .. 600 s (the default: the middle of the record, written by the run):
// Tz = 2 pi / omega to the counting resolution Tz^2 / 300 s; the standard deviation
// 1/sqrt(2) and Pearson's kurtosis 1.5 to the partial cycle at the window's end
// (at most (Tz / 2) / 300 s of the record: 1.7 % of the mean square, 3.5 % of m4/m2^2).
TEST(StatsCommand, UndampedOscillatorHasItsClosedFormPeriodAndMoments) {
  const std::string file = moored_run("stats_undamped", "0");
  const auto stats = run_command_line(heavesim_binary() + " stats " + file + " joints/surge/q --json");
  ASSERT_EQ(stats.exit_code, 0) << stats.output;
  const double tz = 2.0 * std::numbers::pi / std::sqrt(0.4);
  EXPECT_NEAR(json_value(stats.output, "window_start"), 300.0, 1e-9);
  EXPECT_NEAR(json_value(stats.output, "zero_upcrossing_period"), tz, tz * tz / 300.0);
  EXPECT_NEAR(json_value(stats.output, "window_standard_deviation"), 1.0 / std::sqrt(2.0), 0.017 / std::sqrt(2.0));
  EXPECT_NEAR(json_value(stats.output, "kurtosis"), 1.5, 0.035 * 1.5);
  EXPECT_NEAR(json_value(stats.output, "spectral_peak_period"), tz, 0.1 * tz);  // the bin width at 1/Tz
  // The text table carries the channel's units from the file.
  const auto table = run_command_line(heavesim_binary() + " stats " + file + " /joints/surge/q /joints/surge/qd");
  ASSERT_EQ(table.exit_code, 0) << table.output;
  EXPECT_NE(table.output.find("/joints/surge/q [m]"), std::string::npos) << table.output;
  EXPECT_NE(table.output.find("/joints/surge/qd [m/s]"), std::string::npos) << table.output;
  EXPECT_NE(table.output.find("m^2 Hz^2"), std::string::npos) << table.output;
}

TEST(StatsCommand, MissingFileOrChannelIsBadInputNamingIt) {
  const std::string missing = ::testing::TempDir() + "no_such_result.h5";
  const auto no_file = run_command_line(heavesim_binary() + " stats " + missing);
  EXPECT_EQ(no_file.exit_code, 2) << no_file.output;
  EXPECT_NE(no_file.output.find("bad input: " + missing + ": found "), std::string::npos) << no_file.output;

  const std::string file = moored_run("stats_channels", "8.0e4");
  const auto no_channel = run_command_line(heavesim_binary() + " stats " + file + " /joints/heave/q");
  EXPECT_EQ(no_channel.exit_code, 2) << no_channel.output;
  EXPECT_NE(no_channel.output.find(file + ": /joints/heave/q: found no such dataset; expected a recorded channel"),
            std::string::npos)
      << no_channel.output;
  const auto bad_duration = run_command_line(heavesim_binary() + " stats " + file + " --duration -5");
  EXPECT_EQ(bad_duration.exit_code, 2) << bad_duration.output;
  EXPECT_NE(bad_duration.output.find("--duration: found -5"), std::string::npos) << bad_duration.output;
}

// The recorder writes the same statistics as the `statistics` attribute of every channel,
// over the same window: it and `heavesim stats` agree (one streaming pass, one array
// pass). Body kinematics carry the moments only.
TEST(StatsCommand, RecorderAttributesAgreeWithTheCommand) {
  const std::string file = moored_run("stats_attributes", "8.0e3");
  const auto stats = run_command_line(heavesim_binary() + " stats " + file + " /forces/mooring/force_x --json");
  ASSERT_EQ(stats.exit_code, 0) << stats.output;
  const auto attributes = run_command_line(
      "/usr/bin/python3 -c \"import h5py, numpy; a = h5py.File('" + file +
      "')['forces/mooring/force_x'].attrs; print(', '.join(chr(34) + k + chr(34) + ': ' + repr(float(a['statistics'][k][0])) for k in "
      "('mpm_rayleigh_duration', 'weibull_shape', 'spectral_m2', 'significant_crest')))\"");
  ASSERT_EQ(attributes.exit_code, 0) << attributes.output;
  for (const char* name : {"mpm_rayleigh_duration", "weibull_shape", "spectral_m2", "significant_crest"}) {
    const double command = json_value(stats.output, name), recorded = json_value(attributes.output, name);
    EXPECT_NEAR(recorded, command, 1e-9 * std::abs(command)) << name << "\n" << attributes.output;
  }
  const auto fields = run_command_line("/usr/bin/python3 -c \"import h5py; f = h5py.File('" + file +
                                       "'); print(f['bodies/barge/position'].attrs['statistics'].dtype.names, "
                                       "f['joints/surge/reaction_force'].attrs['statistics'].shape)\"");
  // The moment fields and nothing else, in name order (result_file.cpp, record_type).
  EXPECT_NE(fields.output.find("('kurtosis', 'mean_minus_4_sigma', 'mean_plus_4_sigma', 'skewness', 'window_maximum', "
                               "'window_mean', 'window_minimum', 'window_samples', 'window_standard_deviation')"),
            std::string::npos)
      << fields.output;
  EXPECT_EQ(fields.output.find("upcrossings"), std::string::npos) << fields.output;
  EXPECT_NE(fields.output.find("(3,)"), std::string::npos) << fields.output;          // one record per column
}

// docs/result-file.md names every attribute the recorder writes (its statistics table).
TEST(StatsCommand, ResultFileDocumentationNamesEveryStatistic) {
  std::ifstream in(source_path("docs/result-file.md"));
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::size_t table = text.find("<!-- statistics:");
  ASSERT_NE(table, std::string::npos);
  const std::string section = text.substr(table, text.find("\n\n", table) - table);
  for (const stats::StatisticField& field : stats::statistic_fields())
    EXPECT_NE(section.find(std::string("`") + field.name + "`"), std::string::npos) << field.name;
}

}  // namespace
}  // namespace heavesim
