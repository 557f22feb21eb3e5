// The compiled half of the heavesim Python package (docs/python.md): runs and checks a
// case in-process through the very functions `heavesim run` and `heavesim check` call,
// and hands back the exit code the executable would return with what it would print.
// heavesim/__init__.py turns that into a Result or one of the package's exceptions; no
// exit code, signal disposition or stream is left changed behind the interpreter.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <unistd.h>

#include <cstdio>
#include <exception>
#include <fstream>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include <fmt/format.h>

#include "app/case/case_definition.hpp"
#include "app/case/input_error.hpp"
#include "app/version.hpp"
#include "cli/commands/commands.hpp"
#include "kernel/math/numerical_error.hpp"

namespace py = pybind11;

namespace heavesim {
namespace {

/// What the process writes on a file descriptor (1 or 2) while this object lives: the
/// commands print with stdio and fmt on the process's streams, which Python's
/// sys.stdout does not see. The text goes to an unnamed temporary file (a pipe could
/// fill and block the command) and comes back with text().
class CapturedStream {
 public:
  explicit CapturedStream(int descriptor) : descriptor_(descriptor), file_(std::tmpfile()) {
    std::fflush(descriptor == 1 ? stdout : stderr);
    saved_ = dup(descriptor_);
    if (file_ && saved_ >= 0) dup2(fileno(file_), descriptor_);
  }
  ~CapturedStream() { restore(); }
  CapturedStream(const CapturedStream&) = delete;
  CapturedStream& operator=(const CapturedStream&) = delete;

  /// Restores the stream and returns what was written to it.
  std::string text() {
    restore();
    if (!file_) return "";
    std::string text;
    std::rewind(file_);
    char buffer[4096];
    for (std::size_t read; (read = std::fread(buffer, 1, sizeof buffer, file_)) > 0;) text.append(buffer, read);
    std::fclose(file_);
    file_ = nullptr;
    return text;
  }

 private:
  void restore() {
    if (saved_ < 0) return;
    std::fflush(descriptor_ == 1 ? stdout : stderr);
    dup2(saved_, descriptor_);
    close(saved_);
    saved_ = -1;
  }
  int descriptor_;
  std::FILE* file_;
  int saved_ = -1;
};

/// (exit code, the path written, what the command printed on stderr or the error's
/// message): the exit codes of cli/main.cpp, 2 bad input, 3 numerical failure, 1 the rest.
using Outcome = std::tuple<int, std::string, std::string>;

template <class Command>
Outcome run_captured(Command&& command, std::string& output_path) {
  CapturedStream errors(2);
  int code = 1;
  std::string message;
  {
    py::gil_scoped_release unlocked;  // the run may take minutes; other Python threads go on
    try {
      code = command(output_path);
    } catch (const InputError& error) {
      code = 2;
      message = error.what();
    } catch (const NumericalError& error) {
      code = 3;
      message = fmt::format("numerical failure at t = {:.6g} s: {}\n  suggestion: {}", error.time(), error.what(),
                            error.suggestion());
    } catch (const std::exception& error) {
      code = 1;
      message = error.what();
    }
  }
  const std::string printed = errors.text();
  return {code, output_path, message.empty() ? printed : message};
}

Outcome run_case(const std::string& case_path, const std::vector<std::string>& overrides, const std::string& output,
                 const std::string& csv_directory, bool allow_large_runs) {
  std::string output_path = output;
  return run_captured(
      [&](std::string& path) {
        // The executable's default output (results/<case name>.h5) made explicit, so
        // that the caller knows what to open.
        if (path.empty()) path = "results/" + load_case(case_path, overrides, allow_large_runs).name + ".h5";
        RunOptions options;
        options.case_path = case_path;
        options.output_path = path;
        options.csv_directory = csv_directory;
        options.overrides = overrides;
        options.quiet = true;
        options.allow_large_runs = allow_large_runs;
        return run_command(options);
      },
      output_path);
}

/// (exit code, what `heavesim check` prints on stdout, its error message).
std::tuple<int, std::string, std::string> check_case(const std::string& case_path,
                                                     const std::vector<std::string>& overrides,
                                                     bool allow_large_runs) {
  CapturedStream printed(1);
  std::string unused;
  const auto [code, path, message] = run_captured(
      [&](std::string&) { return check_command(case_path, overrides, allow_large_runs); }, unused);
  return {code, printed.text(), message};
}

}  // namespace
}  // namespace heavesim

PYBIND11_MODULE(_heavesim, module) {
  module.doc() = "heavesim's compiled commands (use the heavesim package, docs/python.md)";
  module.attr("version") = heavesim::heavesim_version;
  module.def("run", &heavesim::run_case, py::arg("case_path"), py::arg("overrides"), py::arg("output"),
             py::arg("csv_directory"), py::arg("allow_large_runs"),
             "Runs a case as `heavesim run --quiet`: (exit code, result path, message).");
  module.def("check", &heavesim::check_case, py::arg("case_path"), py::arg("overrides"), py::arg("allow_large_runs"),
             "Checks a case as `heavesim check`: (exit code, printed text, message).");
}
