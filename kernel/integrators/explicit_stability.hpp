#pragma once
// Linear stability of explicit Runge-Kutta methods, for the diagnosis of a failed run:
// a step h is stable for a mode with eigenvalue lambda when |R(h lambda)| <= 1, with
// R(z) = 1 + z b^T (I - z A)^-1 1 the method's stability function (Hairer & Wanner,
// Solving ODEs II, IV.2). Classical RK4 reaches |h lambda| = 2.83 on the imaginary axis
// (undamped oscillations) and 2.79 on the negative real axis (stiff dampers).
// Error path only.
#include <complex>
#include <string>
#include <vector>

#include "kernel/math/numerical_error.hpp"
#include "kernel/system/failure_diagnosis.hpp"

namespace heavesim {

struct ButcherTableau {
  int stages = 0;
  std::vector<double> a;  // stages x stages, row-major, strictly lower triangular
  std::vector<double> b;  // stages
};

ButcherTableau classical_rk4_tableau();

/// R(z) of an explicit tableau.
std::complex<double> stability_function(const ButcherTableau& tableau, std::complex<double> z);

/// The largest step h [s] with |R(h' lambda)| <= 1 for every h' <= h: the method's
/// stability limit for the mode lambda [1/s]. A growing part of lambda (Re > 0) is the
/// motion's own, not the method's, and is set aside.
double stability_limit(const ButcherTableau& tableau, std::complex<double> lambda);

/// The failure of an explicit method whose step `step` [s] is beyond its stability
/// limit `limit` [s] for `mode`: names the mode and what makes it fast, keeps the first
/// symptom the instability produced, and suggests a stable step or an implicit method.
NumericalError beyond_stability_limit(double t, const std::string& method, double step, double limit,
                                      const FastestMode& mode, const std::string& symptom);

/// The remedy for a mode that holds an explicit method's step: an implicit method, a
/// softer element, or (for `steps_needed` > 0) more steps per output interval.
std::string fast_mode_remedy(const FastestMode& mode, double steps_needed);

}  // namespace heavesim
