// heavesim operability: the operability of a sweep over its scatter diagram
// (docs/operability.md). The work is scripts/operability.py, run with Debian's
// /usr/bin/python3: it needs matplotlib for the figure, which has no C++ counterpart
// among the project's parts, and the rest (reading the index, the criteria, the
// percentages) is a few dozen lines of numpy beside it. This command replaces itself
// with that process (exec), so its exit code is the script's: 0, 2 bad input, 1 otherwise.
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <unistd.h>

#include "app/version.hpp"
#include "cli/commands/commands.hpp"

namespace heavesim {

int operability_command(const OperabilityOptions& options) {
  const std::string python = "/usr/bin/python3";
  const std::string script = std::string(heavesim_source_dir) + "/scripts/operability.py";
  std::vector<std::string> arguments = {python, script, options.index_path, "--criteria", options.criteria_path};
  if (!options.output_directory.empty()) arguments.insert(arguments.end(), {"-o", options.output_directory});
  if (options.json) arguments.emplace_back("--json");

  std::vector<char*> argv;
  for (std::string& argument : arguments) argv.push_back(argument.data());
  argv.push_back(nullptr);
  std::fflush(nullptr);
  execv(python.c_str(), argv.data());
  // execv returns only when it failed.
  fmt::print(stderr, "heavesim: error: cannot run {} {}: {}\n", python, script, std::strerror(errno));
  return 1;
}

}  // namespace heavesim
