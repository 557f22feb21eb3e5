#include "cli/commands/command_support.hpp"

#include <filesystem>

#include "app/case/input_error.hpp"
#include "app/output/output_error.hpp"
#include "kernel/system/ode_system.hpp"

namespace heavesim {

std::atomic<int>& stop_signal_value() {
  static std::atomic<int> value{0};
  return value;
}

extern "C" void request_stop_signal(int signal) { stop_signal_value() = signal; }

int exit_code_reporting_errors(const std::function<int()>& command) {
  try {
    return command();
  } catch (const InputError& e) {
    fmt::print(stderr, "heavesim: bad input: {}\n", e.what());
    return 2;
  } catch (const NumericalError& e) {
    fmt::print(stderr, "heavesim: numerical failure at t = {:.6g} s: {}\n  suggestion: {}\n", e.time(), e.what(),
               e.suggestion());
    return 3;
  } catch (const std::exception& e) {
    fmt::print(stderr, "heavesim: error: {}\n", e.what());
    return 1;
  }
}

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

void record_failure(ResultFile& file, const NumericalError& error) {
  file.set_attribute("/", "failure_time", error.time());
  file.set_attribute("/", "failure", std::string(error.what()));
  file.set_attribute("/", "failure_suggestion", error.suggestion());
}

std::string prepare_result_path(const std::string& requested, const std::string& case_name,
                                const std::string& suffix) {
  const std::string path = requested.empty() ? "results/" + case_name + suffix + ".h5" : requested;
  create_parent_directory(path, "result file");
  return path;
}

}  // namespace heavesim
