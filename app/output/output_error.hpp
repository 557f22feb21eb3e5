#pragma once
// A result file or CSV file that cannot be written (full disk, file-size limit,
// permissions): an error of the environment, not of the case or the numerics, so
// `heavesim run` stops with exit code 1 and names the file and the system's cause.
#include <stdexcept>
#include <string>

namespace heavesim {

class OutputError : public std::runtime_error {
 public:
  /// `action` what failed ("cannot write"), `cause` the system's words ("No space left on device (errno 28)").
  OutputError(const std::string& path, const std::string& action, const std::string& cause)
      : std::runtime_error(action + " '" + path + "': " + cause), path_(path), cause_(cause) {}
  const std::string& path() const { return path_; }
  const std::string& cause() const { return cause_; }

 private:
  std::string path_, cause_;
};

}  // namespace heavesim
