#pragma once
// Bad input (case or data file): rejected before running, exit code 2.
#include <stdexcept>
#include <string>

namespace heavesim {

/// Where a value came from: a file position, or a command-line override.
struct SourceLocation {
  std::string file;  // path as given, or "--set"
  int line = 0;      // 1-based; 0 when unknown
  int column = 0;    // 1-based; 0 when unknown
  std::string to_string() const;
};

/// Names the file, line and column, the key path (e.g. joints[2].axis), what was
/// found and what was expected.
class InputError : public std::runtime_error {
 public:
  InputError(SourceLocation location, std::string key_path, std::string found, std::string expected);
  const SourceLocation& location() const { return location_; }
  const std::string& key_path() const { return key_path_; }
  const std::string& found() const { return found_; }
  const std::string& expected() const { return expected_; }

 private:
  SourceLocation location_;
  std::string key_path_, found_, expected_;
};

}  // namespace heavesim
