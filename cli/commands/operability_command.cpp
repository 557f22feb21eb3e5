// heavesim operability: the operability of a sweep over its scatter diagram
// (docs/operability.md). The work is scripts/operability.py, run with Debian's
// /usr/bin/python3: it needs matplotlib for the figure, which has no C++ counterpart
// among the project's parts, and the rest (reading the index, the criteria, the
// percentages) is a few dozen lines of numpy beside it. This command replaces itself
// with that process (exec), so its exit code is the script's: 0, 2 bad input, 1 otherwise.
#include <string>
#include <vector>

#include "cli/commands/commands.hpp"
#include "cli/commands/project_script.hpp"

namespace heavesim {

int operability_command(const OperabilityOptions& options) {
  std::vector<std::string> arguments = {options.index_path, "--criteria", options.criteria_path};
  if (!options.output_directory.empty()) arguments.insert(arguments.end(), {"-o", options.output_directory});
  if (options.json) arguments.emplace_back("--json");
  return exec_project_script("operability.py", arguments);
}

}  // namespace heavesim
