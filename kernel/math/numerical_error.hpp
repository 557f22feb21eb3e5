#pragma once
// The kernel's one error type for a failed evaluation or step: when, what, and what to try.
#include <stdexcept>
#include <string>

namespace heavesim {

/// A numerical failure with a diagnosis: the time [s] it happened, what failed, and a
/// suggestion for the user.
class NumericalError : public std::runtime_error {
 public:
  NumericalError(double time, const std::string& what, const std::string& suggestion)
      : std::runtime_error(what), time_(time), suggestion_(suggestion) {}
  double time() const { return time_; }
  const std::string& suggestion() const { return suggestion_; }

 private:
  double time_;
  std::string suggestion_;
};

}  // namespace heavesim
