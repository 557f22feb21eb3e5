#pragma once
// A user-defined scalar constraint function Phi(x, t) of n joint coordinates x and time
// t, with the exact derivatives the constraint equations need (Haug 1989, ch. 3:
// Phi_q, Phi_t and the acceleration right-hand side). The kernel only calls it; the
// application implements it (app/case/coordinate_expression.hpp: an expression written
// in the case, differentiated by Taylor arithmetic, so no finite differences).
//
// Implementations must not allocate in these calls: they run once per constraint
// evaluation of every Newton iteration and time step.
namespace heavesim {

class ConstraintFunction {
 public:
  virtual ~ConstraintFunction() = default;
  /// The number n of coordinates x it reads.
  virtual int size() const = 0;
  /// Phi(x, t), x[0..n-1] in the coordinates' units (m or rad), t in s.
  virtual double value(const double* x, double t) const = 0;
  /// Phi(x, t); fills gradient[k] = dPhi/dx_k (k < n) and time_partial = dPhi/dt.
  virtual double gradient(const double* x, double t, double* gradient, double& time_partial) const = 0;
  /// v' Phi_xx v + 2 Phi_xt . v + Phi_tt at (x, t) for the rates v = dx/dt: d2Phi/dt2
  /// along the motion without the term Phi_x . xdd.
  virtual double second_derivative_along(const double* x, const double* rates, double t) const = 0;
};

}  // namespace heavesim
