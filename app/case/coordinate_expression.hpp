#pragma once
// A user-defined constraint Phi(x, t) = 0 written as an expression of named joint
// coordinates x_1..x_n and time t ("s - 0.2*sin(theta) - 0.01*t"), with the
// derivatives a constraint needs, all exact (Taylor arithmetic on muParser's bytecode,
// taylor_evaluation.hpp):
//   the gradient dPhi/dx and dPhi/dt  (Jacobian row, velocity target -dPhi/dt),
//   v' Phi_xx v + 2 Phi_xt . v + Phi_tt  (the acceleration bias gamma is minus this).
// The last is the second derivative of s -> Phi(x + s v, t + s) at s = 0, so one
// second-order pass along the direction (v, 1) gives it: no Hessian is formed.
// The gradient takes n + 1 first-order passes along the unit directions.
// Evaluation allocates nothing. It is the kernel's ConstraintFunction of an expression
// constraint (kernel/model/constraint_function.hpp).
#include <map>
#include <string>
#include <vector>

#include "app/case/taylor_evaluation.hpp"
#include "kernel/model/constraint_function.hpp"

namespace heavesim {

class CoordinateExpression final : public ConstraintFunction {
 public:
  /// Throws std::invalid_argument with muParser's message (column of a syntax error).
  CoordinateExpression(const std::string& text, const std::vector<std::string>& coordinates,
                       const std::map<std::string, double>& parameters);

  int size() const override { return size_; }
  /// Whether the expression reads coordinate k (k = size(): the time t).
  bool reads(int k) const { return expression_.reads(k); }
  const std::string& text() const { return expression_.text(); }

  /// Phi(x, t).
  double value(const double* x, double t) const override;
  /// Phi(x, t); fills gradient[k] = dPhi/dx_k (k < size()) and returns dPhi/dt in time_partial.
  double gradient(const double* x, double t, double* gradient, double& time_partial) const override;
  /// v' Phi_xx v + 2 Phi_xt . v + Phi_tt at (x, t) for the rates v = dx/dt.
  double second_derivative_along(const double* x, const double* rates, double t) const override;

 private:
  DifferentiableExpression expression_;  // variables: the coordinates, then t
  int size_ = 0;
  mutable std::vector<Taylor2> point_;   // size_ + 1: the path through (x, t)
  mutable std::vector<double> values_;   // size_ + 1
};

}  // namespace heavesim
