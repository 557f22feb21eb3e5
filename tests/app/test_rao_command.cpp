// heavesim rao's refusals (docs/rao.md, docs/reliability.md's error contract): bad input
// is exit 2 with the argument or case key, what was found and what was expected, before
// any run starts. The end-to-end RAOs of the MSS semi against the frequency-domain RAO are
// in test_platform_6dof.cpp, beside the references they share.
#include <gtest/gtest.h>

#include <filesystem>

#include "tests/test_support.hpp"

namespace heavesim {
namespace {

using testing::heavesim_binary;
using testing::run_command_line;
using testing::source_path;

std::string rao(const std::string& arguments) {
  return heavesim_binary() + " rao " + arguments + " --no-plot -o " + ::testing::TempDir() + "rao_refused";
}

TEST(RaoCommand, UnknownChannelIsRefusedNamingTheArgument) {
  std::filesystem::remove_all(::testing::TempDir() + "rao_refused");
  const auto result = run_command_line(rao(source_path("cases/hydro/semisub_6dof_regular_wave.yaml") +
                                           " --periods 10 --channel heaving"));
  EXPECT_EQ(result.exit_code, 2) << result.output;
  EXPECT_NE(result.output.find("--channel"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("'heaving'"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("surge, sway, heave, roll, pitch, yaw"), std::string::npos) << result.output;
  EXPECT_FALSE(std::filesystem::exists(::testing::TempDir() + "rao_refused/runs")) << "nothing may run";
  // A result path of an element the case does not have: refused before the runs, naming what it has.
  const auto misspelt = run_command_line(rao(source_path("cases/hydro/semisub_6dof_regular_wave.yaml") +
                                             " --periods 10 --channel /forces/excitatoin/force_z"));
  EXPECT_EQ(misspelt.exit_code, 2) << misspelt.output;
  EXPECT_NE(misspelt.output.find("no forces 'excitatoin' in it"), std::string::npos) << misspelt.output;
  EXPECT_NE(misspelt.output.find("excitation"), std::string::npos) << misspelt.output;
}

TEST(RaoCommand, EmptyOrBadPeriodListsAreRefused) {
  for (const char* periods : {"','", "'8:-1:12'", "'12:1:8'", "'0,10'", "'ten'"}) {
    const auto result = run_command_line(rao(source_path("cases/hydro/semisub_6dof_regular_wave.yaml") + " --periods " + periods));
    EXPECT_EQ(result.exit_code, 2) << periods << ": " << result.output;
    EXPECT_NE(result.output.find("--periods"), std::string::npos) << result.output;
    EXPECT_NE(result.output.find("expected periods in s as A:STEP:B"), std::string::npos) << result.output;
  }
  const auto empty = run_command_line(rao(source_path("cases/hydro/semisub_6dof_regular_wave.yaml") + " --periods ','"));
  EXPECT_NE(empty.output.find("found an empty list"), std::string::npos) << empty.output;
  const auto none = run_command_line(rao(source_path("cases/hydro/semisub_6dof_regular_wave.yaml")));
  EXPECT_EQ(none.exit_code, 2) << none.output;
  EXPECT_NE(none.output.find("--periods"), std::string::npos) << none.output;
}

TEST(RaoCommand, NonPositiveAmplitudeIsRefused) {
  for (const char* amplitude : {"0", "-1"}) {
    const auto result = run_command_line(
        rao(source_path("cases/hydro/semisub_6dof_regular_wave.yaml") + " --periods 10 --amplitude " + amplitude));
    EXPECT_EQ(result.exit_code, 2) << result.output;
    EXPECT_NE(result.output.find("--amplitude"), std::string::npos) << result.output;
    EXPECT_NE(result.output.find(std::string("found ") + amplitude), std::string::npos) << result.output;
    EXPECT_NE(result.output.find("a wave amplitude a > 0 m"), std::string::npos) << result.output;
  }
}

TEST(RaoCommand, CaseWithoutWavesIsRefusedAtItsWavesKey) {
  // heave_decay.yaml declares no sea: the error names the file, the key `waves` and what it needs.
  const auto result = run_command_line(rao(source_path("cases/hydro/heave_decay.yaml") + " --periods 10"));
  EXPECT_EQ(result.exit_code, 2) << result.output;
  EXPECT_NE(result.output.find("heave_decay.yaml: waves: found no waves"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("waves: found no waves"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("expected a `waves:` block"), std::string::npos) << result.output;
}

TEST(RaoCommand, FitWindowShorterThanThePeriodIsRefused) {
  const auto result = run_command_line(rao(source_path("cases/hydro/semisub_6dof_regular_wave.yaml") +
                                           " --periods 8,25 --set solver.t_end=420"));
  EXPECT_EQ(result.exit_code, 2) << result.output;
  EXPECT_NE(result.output.find("output.evaluate_after"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("found a fitting window of 20 s"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("at least the longest period, 25 s"), std::string::npos) << result.output;
}

TEST(RaoCommand, ResultFileWithoutTheWaveElevationNamesTheChannelToRecord) {
  const std::string output = ::testing::TempDir() + "rao_no_elevation.h5";
  const auto run = testing::run_case("cases/hydro/semisub_6dof_irregular_sea.yaml", output,
                                     "-q --set solver.t_end=20 --set output.evaluate_after=0 --set output.channels=[bodies]");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const auto result = run_command_line(rao(output));
  EXPECT_EQ(result.exit_code, 2) << result.output;
  EXPECT_NE(result.output.find(output), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("/forces/excitation/wave_elevation: found no such dataset"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("`forces` in output.channels"), std::string::npos) << result.output;
  // A channel the run did not record: the same rule, naming the channel.
  const std::string with_forces = ::testing::TempDir() + "rao_short.h5";
  ASSERT_EQ(testing::run_case("cases/hydro/semisub_6dof_irregular_sea.yaml", with_forces,
                              "-q --set solver.t_end=200 --set output.evaluate_after=0 --set output.channels=[bodies,forces]")
                .exit_code,
            0);
  const auto missing = run_command_line(rao(with_forces + " --channel /joints/platform/reaction_force[2]"));
  EXPECT_EQ(missing.exit_code, 2) << missing.output;
  EXPECT_NE(missing.output.find("/joints/platform/reaction_force: found no such dataset (channel "
                                "'/joints/platform/reaction_force[2]')"),
            std::string::npos)
      << missing.output;
}

TEST(RaoCommand, ARelativeCaseFileNotFoundFromHereNamesItAndAsksForCase) {
  // A run records its case path as given; read from another directory, the RAO command
  // names that path and the remedy instead of failing on the case reader's missing file.
  const std::string output = ::testing::TempDir() + "rao_relative_case.h5";
  const auto run = run_command_line("cd " + source_path("") + " && " + heavesim_binary() +
                                    " run cases/hydro/semisub_6dof_irregular_sea.yaml -q -o " + output +
                                    " --set solver.t_end=20 --set output.evaluate_after=0");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const auto result = run_command_line("cd / && " + rao(output));
  EXPECT_EQ(result.exit_code, 2) << result.output;
  EXPECT_NE(result.output.find(output), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("case_file: found the run's case file 'cases/hydro/semisub_6dof_irregular_sea.yaml', "
                               "which does not exist from /"),
            std::string::npos)
      << result.output;
  EXPECT_NE(result.output.find("or --case CASE.yaml"), std::string::npos) << result.output;
}

}  // namespace
}  // namespace heavesim
