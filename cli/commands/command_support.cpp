#include "cli/commands/command_support.hpp"

#include <filesystem>

#include "app/output/output_error.hpp"

namespace heavesim {

std::atomic<int>& stop_signal_value() {
  static std::atomic<int> value{0};
  return value;
}

extern "C" void request_stop_signal(int signal) { stop_signal_value() = signal; }

int stopped_before_the_run(const std::string& case_name) {
  fmt::print(stderr, "heavesim: stopped by signal {} before the run of case '{}' started; no result file written\n",
             StopSignals::received(), case_name);
  return 1;
}

void create_parent_directory(const std::string& path, const char* what) {
  const std::filesystem::path directory = std::filesystem::path(path).parent_path();
  if (directory.empty()) return;
  std::error_code error;
  std::filesystem::create_directories(directory, error);
  if (error) throw OutputError(directory.string(), std::string("cannot create the directory for the ") + what, error.message());
}

}  // namespace heavesim
