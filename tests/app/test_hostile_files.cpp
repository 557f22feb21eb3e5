// Inputs that cannot be committed as bad-case files (a FIFO, a device, a directory, a
// symbolic-link loop, an oversized file, a 100,000-deep nesting, include fan-outs,
// --set overrides): each is made at run time in a temporary directory and must be
// rejected as bad input (exit 2) naming where, never hang, crash or read without bound.
// Every command runs under `timeout 10`, so a regression that blocks shows as exit 124
// instead of a hung suite.
#include <gtest/gtest.h>

#include <cmath>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "app/case/case_merge.hpp"
#include "app/case/expression.hpp"
#include "tests/test_support.hpp"

namespace heavesim {
namespace {

constexpr const char* one_body_rig = R"(bodies:
  - name: link
    mass: 1
    inertia: [0.1, 0.1, 0.1]
joints:
  - {name: pin, type: revolute, parent: ground, child: link, axis: [0, 1, 0]}
solver: {t_end: 1}
)";

class HostileFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
    directory_ = std::filesystem::temp_directory_path() /
                 ("heavesim_hostile_" + std::to_string(::getpid()) + "_" + test->name());
    std::filesystem::remove_all(directory_);
    std::filesystem::create_directories(directory_);
  }
  void TearDown() override { std::filesystem::remove_all(directory_); }

  std::string path(const std::string& name) const { return (directory_ / name).string(); }
  std::string write(const std::string& name, const std::string& text) const {
    std::ofstream(path(name), std::ios::binary) << text;
    return path(name);
  }
  /// `heavesim check` of `case_path` with extra arguments, limited to 10 s.
  static testing::CommandResult check(const std::string& case_path, const std::string& extra = "") {
    return testing::run_command_line("timeout 10 " + testing::heavesim_binary() + " check '" + case_path + "' " + extra);
  }

  std::filesystem::path directory_;
};

/// Exit 2 and every piece of `expected` in the message.
void expect_bad_input(const testing::CommandResult& result, const std::vector<std::string>& expected) {
  EXPECT_EQ(result.exit_code, 2) << "(124 means it hung) " << result.output;
  for (const std::string& text : expected)
    EXPECT_NE(result.output.find(text), std::string::npos) << "no '" << text << "' in: " << result.output;
  EXPECT_LT(result.output.size(), 2000u) << "a message of " << result.output.size() << " bytes";
}

TEST_F(HostileFiles, NamedPipeAsIncludeIsRejectedWithoutOpeningIt) {
  ASSERT_EQ(::mkfifo(path("pipe.yaml").c_str(), 0600), 0);
  const std::string case_path = write("case.yaml", "solver: {t_end: 1}\ninclude: pipe.yaml\n");
  expect_bad_input(check(case_path), {case_path + ":2:10: include: found 'pipe.yaml'", "a named pipe (FIFO)",
                                      "expected a regular file of at most 16 MiB"});
}

TEST_F(HostileFiles, NamedPipeAsCaseFileIsRejectedWithoutOpeningIt) {
  ASSERT_EQ(::mkfifo(path("pipe.yaml").c_str(), 0600), 0);
  expect_bad_input(check(path("pipe.yaml")), {path("pipe.yaml") + ": found a named pipe (FIFO)"});
}

TEST_F(HostileFiles, DeviceAsCaseFileIsRejected) {
  expect_bad_input(check("/dev/zero"), {"/dev/zero: found a character device; expected a regular file"});
}

TEST_F(HostileFiles, DirectoryAsCaseFileIsADirectoryNotAnEmptyCase) {
  const testing::CommandResult result = check(directory_.string());
  expect_bad_input(result, {directory_.string() + ": found a directory; expected a regular file"});
  EXPECT_EQ(result.output.find("bodies"), std::string::npos) << result.output;
}

TEST_F(HostileFiles, SymbolicLinkLoopAsIncludeIsRejectedAtTheEntry) {
  std::filesystem::create_symlink("b.yaml", path("a.yaml"));
  std::filesystem::create_symlink("a.yaml", path("b.yaml"));
  const std::string case_path = write("case.yaml", "include:\n  - a.yaml\n");
  expect_bad_input(check(case_path), {case_path + ":2:5: include[0]: found 'a.yaml'", "cannot be examined"});
}

TEST_F(HostileFiles, SymbolicLinkToARegularFileIsFollowed) {
  write("rig.yaml", one_body_rig);
  std::filesystem::create_symlink("rig.yaml", path("link.yaml"));
  const std::string case_path = write("case.yaml", "include: link.yaml\n");
  const testing::CommandResult result = check(case_path);
  EXPECT_EQ(result.exit_code, 0) << result.output;
}

TEST_F(HostileFiles, FileOverTheSizeLimitIsRejectedBeforeReading) {
  const std::string big = write("big.yaml", "");
  std::filesystem::resize_file(big, max_case_file_bytes + 1);  // sparse: no 16 MiB written
  expect_bad_input(check(big), {big + ": found a file of 16777217 bytes; expected a regular file of at most 16 MiB"});
  const std::string case_path = write("case.yaml", "include: big.yaml\n");
  expect_bad_input(check(case_path), {case_path + ":1:10: include: found 'big.yaml'", "a file of 16777217 bytes"});
}

TEST_F(HostileFiles, HundredThousandLevelsOfNestingStopAtTheLimit) {
  const std::string case_path = write("deep.yaml", "bodies: " + std::string(100000, '[') + "\n");
  expect_bad_input(check(case_path), {case_path + ":1:", "expected at most 100 levels of nesting"});
  const std::string block = write("block.yaml", [] {
    std::string text;
    for (int level = 0; level < 150; ++level) text += std::string(level, ' ') + "k:\n";
    return text;
  }());
  expect_bad_input(check(block), {block + ":101:", "at most 100 levels of nesting"});
}

TEST_F(HostileFiles, LongFlowCollectionIsRejectedBeforeTheParserBuffersIt) {
  // yaml-cpp holds a flow collection's tokens until it closes: 16 MiB of "0," took 2.4 GB.
  std::string text = std::string(one_body_rig) + "output:\n  channels: [";
  while (text.size() < 3 * max_flow_collection_bytes) text += "bodies, ";
  const std::string case_path = write("long.yaml", text);
  expect_bad_input(check(case_path), {case_path + ":9:13: found a '[' whose flow collection runs on for more than "
                                                   "1048576 bytes"});
}

TEST_F(HostileFiles, IncludeCycleIsReportedAtTheEntryThatClosesItWithTheChain) {
  const std::string first = write("first.yaml", "include: second.yaml\n");
  write("second.yaml", "solver: {t_end: 1}\ninclude: [third.yaml]\n");
  const std::string third = write("third.yaml", "# the last link\ninclude: first.yaml\n");
  expect_bad_input(check(first), {third + ":2:10: include: found 'first.yaml'",
                                  "a cycle of includes: " + first + " -> " + path("second.yaml") + " -> " + third +
                                      " -> " + path("first.yaml")});
}

TEST_F(HostileFiles, IncludesThatFanOutStopAtTheFileLimit) {
  // Each level includes the next one twice: 2^14 loads of the last file, no cycle.
  for (int level = 0; level < 14; ++level)
    write("level" + std::to_string(level) + ".yaml",
          "include: [level" + std::to_string(level + 1) + ".yaml, level" + std::to_string(level + 1) + ".yaml]\n");
  write("level14.yaml", "solver: {t_end: 1}\n");
  expect_bad_input(check(path("level0.yaml")), {"include[", "found more than 1000 included files in the case"});
}

TEST_F(HostileFiles, AliasExpansionsCountAcrossIncludes) {
  // 11 + 10 * 11 + ... : each file expands to about 611,000 values; two exceed 10^6.
  write("expands.yaml",
        "output:\n  wide:\n    a: &a [0, 0, 0, 0, 0, 0, 0, 0, 0, 0]\n    b: &b [*a, *a, *a, *a, *a, *a, *a, *a, *a, *a]\n"
        "    c: &c [*b, *b, *b, *b, *b, *b, *b, *b, *b, *b]\n    d: &d [*c, *c, *c, *c, *c, *c, *c, *c, *c, *c]\n"
        "    e: &e [*d, *d, *d, *d, *d, *d, *d, *d, *d, *d]\n    f: [*e, *e, *e, *e, *e]\n");
  const std::string case_path = write("case.yaml", "include: [expands.yaml, expands.yaml]\n");
  expect_bad_input(check(case_path), {path("expands.yaml") + ":", "found the case growing past 1000000 values"});
}

TEST_F(HostileFiles, SecondDocumentInAnIncludedFileIsRejectedAtItsLine) {
  write("rig.yaml", std::string(one_body_rig) + "---\nsolver: {t_end: 5}\n");
  const std::string case_path = write("case.yaml", "include: rig.yaml\n");
  expect_bad_input(check(case_path), {path("rig.yaml") + ":8:1: found a second YAML document"});
}

TEST_F(HostileFiles, NulByteIsASyntaxErrorNotTheEndOfTheFile) {
  const std::string case_path = write("nul.yaml", std::string(one_body_rig) + std::string("extra: 1\0more: 2\n", 17));
  expect_bad_input(check(case_path), {case_path + ":8:", "YAML syntax error"});
}

// --set: the override syntax swept for crashes; each is bad input at the --set.
struct BadOverride {
  std::string assignment;
  std::string expected;
};

TEST_F(HostileFiles, MalformedOverridesAreBadInputAtTheSet) {
  const std::string case_path = write("case.yaml", one_body_rig);
  const std::vector<BadOverride> overrides = {
      {"bodies[99999999999999999999999].mass=1",
       "bodies[99999999999999999999999]: found index 99999999999999999999999 in a list of 1 items; expected an "
       "index from 0 to 0"},
      {"bodies[1].mass=1", "found index 1 in a list of 1 items"},
      {"bodies..mass=1", "found an empty key at character 8"},
      {".solver.t_end=1", "found an empty key at character 1"},
      {"solver.=1", "found an empty key after the last '.'"},
      {"bodies[=1", "found a '[' that is not closed"},
      {"bodies[0[1]].mass=1", "found a '[' that is not closed"},
      {"]x=1", "found a ']' without '['"},
      {"bodies]=1", "found a ']' without '['"},
      {"bodies[0]x=1", "found 'x' after a key or ']'"},
      {"bodies[]=1", "found an empty selector []"},
      {"=5", "expected key.path=value"},
      {"solver.t_end", "expected key.path=value"},
      {"solver.t_end=[1, 2", "--set solver.t_end:1:1: found a YAML syntax error"},
      {"solver.t_end=\"10", "--set solver.t_end:1:4: found"},
      {"solver.t_end=&a [*a]", "a cycle"},
      {"solver.t_end=1\n---\n2", "a second YAML document"},
      {"solver.t_end=\xff", "--set solver.t_end"},
      {"solver.t_end=" + std::string(100000, '9'), "--set solver.t_end"},
      {"parameters._e=1", "parameter name '_e', a name that expressions already define"},
      {"bodies[link].mass=-1", "bodies[0].mass: found -1"},
  };
  for (const BadOverride& bad : overrides) {
    SCOPED_TRACE(bad.assignment.substr(0, 80));
    // The assignment goes through a file so that no byte of it meets the shell.
    write("assignment.txt", bad.assignment);
    expect_bad_input(check(case_path, "--set \"$(cat '" + path("assignment.txt") + "')\""), {"--set", bad.expected});
  }
}

TEST(ParameterNames, DefineRejectsWhatMuParserWouldThrowOnAndStaysUsable) {
  ExpressionContext context;
  for (const std::string& name : std::vector<std::string>{"_e", "_pi", "sin", "pi", "deg", "t", "", "2a", "a-b", std::string(101, 'a')})
    EXPECT_THROW(context.define(name, 1.0), std::invalid_argument) << name;
  context.define("arm", 2.0);
  context.define(std::string(100, 'a'), 3.0);  // muParser's identifier limit is 100 characters
  EXPECT_DOUBLE_EQ(context.evaluate("arm * _e"), 2.0 * M_E);  // _e is still muParser's constant
  EXPECT_EQ(context.parameters().size(), 2u);
}

TEST(ParameterNames, ReservedNamesComeFromTheParserAndTheCase) {
  // A few of muParser 2.3's built-ins, ours, and t; all must be refused.
  for (const std::string name : {"sin", "atan2", "log10", "ln", "rint", "sum", "avg", "min", "max", "_pi", "_e", "deg",
                                 "rad", "pi", "t"}) {
    EXPECT_NE(parameter_name_problem(name), "") << name;
    // Listed as an entry of "none of a, b, c" (a bare find would match letters of the prose).
    const std::string expectation = parameter_name_expectation();
    const std::string list = expectation.substr(expectation.find("none of ") + 8);
    EXPECT_NE((", " + list + ",").find(", " + name + ","), std::string::npos) << name;
  }
  for (const std::string name : {"L", "arm_length", "_offset", "e", "sine", "T", "x2"})
    EXPECT_EQ(parameter_name_problem(name), "") << name;
}

TEST_F(HostileFiles, DataFilesThatAreNotRegularFilesAreBadDataNotAHang) {
  // The readers of BEM coefficients and hull meshes check what a path names before
  // opening it (hydro/data_file.hpp), as the case reader does: a FIFO's open() blocked
  // and /dev/zero as a text file never ended.
  const std::string fifo = path("pipe");
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  std::filesystem::create_directories(path("folder"));
  const std::string linear = testing::source_path("cases/hydro/heave_decay.yaml");
  const std::string nonlinear = testing::source_path("cases/hydro/heave_decay_nonlinear.yaml");
  struct Probe {
    std::string target, what;
  };
  for (const Probe& probe : {Probe{fifo, "a named pipe (FIFO)"}, Probe{"/dev/zero", "a character device"},
                             Probe{path("folder"), "a directory"}}) {
    SCOPED_TRACE(probe.target);
    expect_bad_input(check(linear, "--set 'forces[hydrostatics].hst=" + probe.target + "'"),
                     {probe.target, probe.what, "expected a readable data file"});
    expect_bad_input(check(nonlinear, "--set 'forces[hydrostatics].mesh=" + probe.target + "'"),
                     {probe.target, probe.what, "expected a readable data file"});
  }
}

}  // namespace
}  // namespace heavesim
