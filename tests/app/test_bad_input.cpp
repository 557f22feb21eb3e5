// Every malformed case in tests/bad_cases is rejected by `heavesim check` with exit
// code 2 and a message that names the file, the line (marked "# <-- error" in the
// file), the key path and what was expected ("# expect-path:", "# expect-text:").
// A sweep file says "# expect-command: sweep" (run by `heavesim sweep`, refused before
// any run); "# expect-file: F" when the marked line is in F (a scatter diagram).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "tests/test_support.hpp"

namespace heavesim {
namespace {

struct BadCase {
  std::string path;
  int line = 0;
  std::string key_path;
  std::string text;
  std::string command = "check";
  std::string error_file;  // the file whose line is marked (default: the case itself)
};

BadCase read_expectations(const std::filesystem::path& file) {
  BadCase bad;
  bad.path = bad.error_file = file.string();
  std::ifstream in(file);
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    if (line.rfind("# expect-path:", 0) == 0) bad.key_path = line.size() > 15 ? line.substr(15) : "";
    if (line.rfind("# expect-text:", 0) == 0) bad.text = line.substr(15);
    if (line.rfind("# expect-command:", 0) == 0) bad.command = line.substr(18);
    if (line.rfind("# expect-file:", 0) == 0) bad.error_file = (file.parent_path() / line.substr(15)).string();
    if (line.find("# <-- error") != std::string::npos && bad.line == 0) bad.line = number;
  }
  if (bad.error_file != bad.path) {
    std::ifstream marked(bad.error_file);
    for (int number = 1; std::getline(marked, line); ++number)
      if (line.find("# <-- error") != std::string::npos && bad.line == 0) bad.line = number;
  }
  return bad;
}

std::vector<BadCase> corpus() {
  std::vector<BadCase> cases;
  for (const auto& entry : std::filesystem::directory_iterator(testing::source_path("tests/bad_cases")))
    if (entry.path().extension() == ".yaml") cases.push_back(read_expectations(entry.path()));
  std::sort(cases.begin(), cases.end(), [](const BadCase& a, const BadCase& b) { return a.path < b.path; });
  return cases;
}

TEST(BadInput, CorpusHasAtLeastTwentyFiveCases) { EXPECT_GE(corpus().size(), 25u); }

TEST(BadInput, EveryCaseIsRejectedWithFileLineKeyPathAndExpectation) {
  for (const BadCase& bad : corpus()) {
    SCOPED_TRACE(bad.path);
    ASSERT_GT(bad.line, 0) << "the file marks no line with '# <-- error'";
    const std::string arguments =
        bad.command == "sweep" ? " sweep " + bad.path + " -o " + ::testing::TempDir() + "bad_sweep" : " check " + bad.path;
    const testing::CommandResult result = testing::run_command_line("timeout 10 " + testing::heavesim_binary() + arguments);
    EXPECT_EQ(result.exit_code, 2) << "(124 means it hung) " << result.output;
    if (bad.command == "sweep") {
      EXPECT_FALSE(std::filesystem::exists(::testing::TempDir() + "bad_sweep/index.h5")) << "a run started";
    }
    const std::string position = bad.error_file + ":" + std::to_string(bad.line) + ":";
    EXPECT_NE(result.output.find(position), std::string::npos) << "no '" << position << "' in: " << result.output;
    if (!bad.key_path.empty()) {
      EXPECT_NE(result.output.find(": " + bad.key_path + ": "), std::string::npos) << result.output;
    }
    EXPECT_NE(result.output.find("found "), std::string::npos) << result.output;
    EXPECT_NE(result.output.find("expected "), std::string::npos) << result.output;
    EXPECT_NE(result.output.find(bad.text), std::string::npos) << "no '" << bad.text << "' in: " << result.output;
  }
}

TEST(BadInput, MissingCaseFileIsBadInput) {
  const testing::CommandResult result = testing::run_command_line(testing::heavesim_binary() + " run /nonexistent.yaml");
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_NE(result.output.find("/nonexistent.yaml"), std::string::npos);
}

TEST(BadInput, BadCommandLineOverrideIsBadInput) {
  const testing::CommandResult result = testing::run_command_line(
      testing::heavesim_binary() + " check " + testing::source_path("cases/validation/two_link.yaml") +
      " --set solver.t_end=never");
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_NE(result.output.find("--set solver.t_end"), std::string::npos) << result.output;
}

TEST(BadInput, DomainRuleReachedThroughAnOverrideIsBadInputAtThatKey) {
  // The kernel of 21 samples cannot hold a state space of order 12: hydro's rule
  // (state_space.cpp), reported at the overridden key, not as exit code 1.
  const testing::CommandResult result = testing::run_command_line(
      testing::heavesim_binary() + " check " + testing::source_path("cases/hydro/heave_decay.yaml") +
      " --set 'forces[radiation].kernel_step=3'");
  EXPECT_EQ(result.exit_code, 2) << result.output;
  EXPECT_NE(result.output.find("--set forces[radiation].kernel_step"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find(": forces[1].kernel_step: found a kernel of 21 samples"), std::string::npos)
      << result.output;
}

}  // namespace
}  // namespace heavesim
