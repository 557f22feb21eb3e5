#pragma once
// Helpers shared by the tests: locations of the built binary and the source tree,
// and running a command line to capture its output and exit code.
#include <array>
#include <cstdio>
#include <string>
#include <sys/wait.h>

namespace heavesim::testing {

inline std::string source_path(const std::string& relative) { return std::string(HEAVESIM_SOURCE_DIR) + "/" + relative; }
inline std::string heavesim_binary() { return HEAVESIM_BINARY; }

struct CommandResult {
  int exit_code = -1;
  std::string output;  // stdout and stderr together
};

inline CommandResult run_command_line(const std::string& command) {
  CommandResult result;
  FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  if (!pipe) return result;
  std::array<char, 4096> buffer;
  while (std::fgets(buffer.data(), buffer.size(), pipe)) result.output += buffer.data();
  const int status = pclose(pipe);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

/// `heavesim run` of a case (path relative to the source tree) writing `output`, with
/// extra arguments (e.g. "--set key=value").
inline CommandResult run_case(const std::string& case_file, const std::string& output, const std::string& extra = "") {
  return run_command_line(heavesim_binary() + " run " + source_path(case_file) + " -o " + output + " " + extra);
}

/// `heavesim check` of a case (path relative to the source tree).
inline CommandResult check_case(const std::string& case_file) {
  return run_command_line(heavesim_binary() + " check " + source_path(case_file));
}

}  // namespace heavesim::testing
