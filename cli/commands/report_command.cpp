// heavesim report: one self-contained HTML page of a result file (docs/report.md). The
// work is scripts/report.py, run with Debian's /usr/bin/python3, as `heavesim
// operability` does: the page is matplotlib figures and tables around the statistics
// `heavesim stats` computes (the script asks this executable for them, its version and
// its validation checks). This command replaces itself with that process (exec), so its
// exit code is the script's: 0, 2 bad input, 1 otherwise.
#include <unistd.h>

#include <string>
#include <vector>

#include <fmt/format.h>

#include "cli/commands/commands.hpp"
#include "cli/commands/project_script.hpp"

namespace heavesim {

int report_command(const ReportOptions& options) {
  std::vector<std::string> arguments = {options.result_path, "--duration", fmt::format("{:.17g}", options.duration)};
  // The script runs this very executable (/proc/self/exe: the build that makes the report).
  std::vector<char> self(4096, '\0');
  const ssize_t length = readlink("/proc/self/exe", self.data(), self.size() - 1);
  if (length > 0) arguments.insert(arguments.end(), {"--heavesim", std::string(self.data(), static_cast<size_t>(length))});
  if (!options.output_path.empty()) arguments.insert(arguments.end(), {"-o", options.output_path});
  if (options.from) arguments.insert(arguments.end(), {"--from", fmt::format("{:.17g}", *options.from)});
  if (!options.validation_log.empty()) arguments.insert(arguments.end(), {"--validation", options.validation_log});
  return exec_project_script("report.py", arguments);
}

}  // namespace heavesim
