#pragma once
// Bad hydrodynamic data (a BEM coefficient file, a hull mesh): names the file, the
// line (1-based; 0 when the problem is not on one line), what was found and what was
// expected, like the application's InputError (app/ is not visible from hydro/).
#include <stdexcept>
#include <string>

namespace heavesim::hydro {

class DataError : public std::runtime_error {
 public:
  DataError(std::string file, int line, std::string found, std::string expected)
      : std::runtime_error(describe(file, line, found, expected)),
        file_(std::move(file)),
        line_(line),
        found_(std::move(found)),
        expected_(std::move(expected)) {}
  const std::string& file() const { return file_; }
  int line() const { return line_; }
  const std::string& found() const { return found_; }
  const std::string& expected() const { return expected_; }

 private:
  /// "file:line: found ...; expected ..." (out of line: GCC 12 reports false overflows
  /// in inlined std::string concatenation chains, GCC bug 105329).
  static std::string describe(const std::string& file, int line, const std::string& found,
                              const std::string& expected);
  std::string file_;
  int line_;
  std::string found_, expected_;
};

}  // namespace heavesim::hydro
