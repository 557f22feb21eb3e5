// Run-size limits (RunLimits, app/case/case_definition.hpp): a case whose output or
// step count cannot finish or fit is refused before running, by `check` and `run`
// alike, unless --allow-large-runs; counts no run can do are refused even then.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "app/case/case_definition.hpp"
#include "app/scene/run_size.hpp"
#include "app/scene/scene.hpp"
#include "tests/test_support.hpp"

namespace heavesim {
namespace {

std::string bad_case(const std::string& name) { return testing::source_path("tests/bad_cases/" + name); }

testing::CommandResult heavesim(const std::string& arguments) {
  return testing::run_command_line(testing::heavesim_binary() + " " + arguments);
}

TEST(RunLimits, AllowLargeRunsLetsARefusedCaseThroughCheck) {
  // 1e11 output samples: refused at output.interval, accepted when the user means it.
  const std::string path = bad_case("limit_output_interval_too_fine.yaml");
  const testing::CommandResult refused = heavesim("check " + path);
  EXPECT_EQ(refused.exit_code, 2) << refused.output;
  EXPECT_NE(refused.output.find(": output.interval: found 1e-11 s, 1e+11 output samples"), std::string::npos)
      << refused.output;
  const testing::CommandResult allowed = heavesim("check " + path + " --allow-large-runs");
  EXPECT_EQ(allowed.exit_code, 0) << allowed.output;
  EXPECT_NE(allowed.output.find("outputs every 1e-11 s"), std::string::npos) << allowed.output;
}

TEST(RunLimits, AllowLargeRunsLetsAnOutputTooLargeForTheLimitThroughCheck) {
  // 1e8 samples x 32 columns x 8 bytes = 23.8 GiB: refused by the scene's estimate.
  const std::string path = bad_case("limit_output_too_large.yaml");
  const testing::CommandResult refused = heavesim("check " + path);
  EXPECT_EQ(refused.exit_code, 2) << refused.output;
  EXPECT_NE(refused.output.find("a result of 23.8 GiB (1e+08 samples x 32 columns x 8 bytes"), std::string::npos)
      << refused.output;
  EXPECT_EQ(heavesim("check " + path + " --allow-large-runs").exit_code, 0);
}

TEST(RunLimits, CountsNoRunCanDoAreRefusedEvenWhenAllowed) {
  for (const char* name : {"limit_rk4_step_never_ends.yaml", "limit_output_interval_unresolvable.yaml",
                           "limit_step_below_clock_resolution.yaml"}) {
    SCOPED_TRACE(name);
    const testing::CommandResult result = heavesim("check " + bad_case(name) + " --allow-large-runs");
    EXPECT_EQ(result.exit_code, 2) << result.output;
    EXPECT_NE(result.output.find("no run can do more"), std::string::npos) << result.output;
  }
}

TEST(RunLimits, RunRefusesWhatCheckRefusesAndWritesNothing) {
  const std::string output = (std::filesystem::temp_directory_path() / "heavesim_run_limits.h5").string();
  std::filesystem::remove(output);
  for (const char* name : {"limit_output_interval_too_fine.yaml", "limit_output_too_large.yaml",
                           "limit_hht_step_too_many.yaml", "limit_max_step_too_small.yaml"}) {
    SCOPED_TRACE(name);
    const testing::CommandResult checked = heavesim("check " + bad_case(name));
    const testing::CommandResult ran = heavesim("run " + bad_case(name) + " -o " + output);
    EXPECT_EQ(checked.exit_code, 2) << checked.output;
    EXPECT_EQ(ran.exit_code, 2) << ran.output;
    EXPECT_EQ(ran.output, checked.output);
    EXPECT_FALSE(std::filesystem::exists(output));
  }
}

TEST(RunLimits, EstimatedColumnsAreTheColumnsTheRunWrites) {
  // The estimate against the CSV the recorder writes: one header field per column.
  const std::string directory = (std::filesystem::temp_directory_path() / "heavesim_run_limits_csv").string();
  for (const char* case_file : {"cases/validation/two_link.yaml", "cases/validation/slider_crank.yaml", "cases/validation/c1_passive_compensator.yaml",
                                "cases/hydro/heave_decay.yaml"}) {
    SCOPED_TRACE(case_file);
    std::filesystem::remove_all(directory);
    const std::string output = directory + "/result.h5";
    const testing::CommandResult ran = testing::run_case(
        case_file, output, "-q --csv " + directory + " --set solver.t_end=0.2 --set output.interval=0.1");
    ASSERT_EQ(ran.exit_code, 0) << ran.output;
    const CaseDefinition definition =
        load_case(testing::source_path(case_file), {"solver.t_end=0.2", "output.interval=0.1"});
    const Scene scene = build_scene(definition);
    std::ifstream csv(directory + "/" + definition.name + ".csv");
    std::string header;
    std::getline(csv, header);
    const long fields = 1 + std::count(header.begin(), header.end(), ',');
    const RunSize size = estimate_run_size(definition, scene);
    EXPECT_EQ(size.columns, fields);
    EXPECT_EQ(size.samples, 3.0);  // t = 0, 0.1, 0.2
  }
}

}  // namespace
}  // namespace heavesim
