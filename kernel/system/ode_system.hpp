#pragma once
// What an integrator sees: dy/dt = f(t, y), optionally with a projection onto the
// manifold on which y must stay (unit quaternions, closed loops).
#include <stdexcept>
#include <string>

#include "kernel/spatial/types.hpp"

namespace heavesim {

/// A numerical failure with a diagnosis: when, what, and what to try.
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

class OdeSystem {
 public:
  virtual ~OdeSystem() = default;
  virtual int size() const = 0;
  /// ydot = f(t, y). Throws NumericalError when f cannot be evaluated (non-finite, singular).
  virtual void derivative(double t, const VectorX& y, VectorX& ydot) = 0;
  /// Moves y back onto its manifold after a step (no-op by default).
  virtual void project(double /*t*/, VectorX& /*y*/) {}
};

}  // namespace heavesim
