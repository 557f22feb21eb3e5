#pragma once
// What an integrator sees: dy/dt = f(t, y), optionally with a projection onto the
// manifold on which y must stay (unit quaternions, closed loops).
#include "kernel/math/numerical_error.hpp"
#include "kernel/system/failure_diagnosis.hpp"
#include "kernel/spatial/types.hpp"

namespace heavesim {

class OdeSystem : public FailureDiagnosis {
 public:
  virtual ~OdeSystem() = default;
  virtual int size() const = 0;
  /// ydot = f(t, y). Throws NumericalError when f cannot be evaluated (non-finite, singular).
  virtual void derivative(double t, const VectorX& y, VectorX& ydot) = 0;
  /// Moves y back onto its manifold after a step (no-op by default).
  virtual void project(double /*t*/, VectorX& /*y*/) {}
};

}  // namespace heavesim
