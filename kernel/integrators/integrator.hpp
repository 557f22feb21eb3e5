#pragma once
// Time integrators behind one small interface: initialize at (t0, y0), then advance
// to each output time. Each integrator is bound at construction to the form of the
// system it needs (RK4 and ERK: OdeSystem; IDA: DaeSystem; HHT: SecondOrderSystem), so
// a wrong pairing does not compile; make_integrator builds the right form of a
// MultibodySystem for the chosen method. The caller owns the system.
#include <memory>
#include <string>

#include "kernel/system/ode_system.hpp"

namespace heavesim {

enum class IntegrationMethod {
  rk4,        // classical Runge-Kutta, fixed step, projection after every step
  dopri5,     // ARKODE ERK Dormand-Prince 5(4), adaptive, projection after every step
  verner6,    // ARKODE ERK Verner 6(5), adaptive (tight-tolerance references)
  fehlberg8,  // ARKODE ERK Fehlberg 8(7), adaptive (very tight tolerances)
  ida,        // SUNDIALS IDA, variable-order BDF (stiff problems), dense direct solver
  hht,        // Hilber-Hughes-Taylor, index-3 augmented Lagrangian with projections, fixed step
  contact     // velocity-level contact stepping (impulses; contacts, stops, constraints as one MLCP), fixed step
};

/// Whether the method steps with the fixed solver.step (rk4, hht, contact).
inline bool is_fixed_step(IntegrationMethod method) {
  return method == IntegrationMethod::rk4 || method == IntegrationMethod::hht || method == IntegrationMethod::contact;
}
/// Whether the method integrates the ODE form (rk4, dopri5, verner6, fehlberg8), which
/// sets a mechanism's redundant constraint rows aside step by step (kernel/system/ode_form.cpp).
inline bool integrates_the_ode_form(IntegrationMethod method) {
  return method == IntegrationMethod::rk4 || method == IntegrationMethod::dopri5 ||
         method == IntegrationMethod::verner6 || method == IntegrationMethod::fehlberg8;
}
/// Linear solver for IDA's Newton iterations.
enum class LinearSolver {
  dense,  // dense LU with partial pivoting (Eigen, in a SUNDIALS linear solver: dense_lu_linear_solver.hpp)
  sparse  // KLU (SuiteSparse) on the Jacobian's sparsity pattern
};

struct IntegratorSettings {
  IntegrationMethod method = IntegrationMethod::ida;
  double step = 1e-3;             // s, fixed step (rk4)
  double relative_tolerance = 1e-8;
  double absolute_tolerance = 1e-10;
  double max_step = 0.0;          // s, 0 = unlimited (adaptive methods)
  long max_steps_per_output = 100000;
  LinearSolver linear_solver = LinearSolver::dense;  // ida
  double hht_alpha = 0.0;         // hht: numerical damping, in [-1/3, 0] (0: trapezoidal rule)
  double constraint_tolerance = 1e-10;  // hht, ida: largest |Phi| accepted at the end of a step [m or rad]
};

struct IntegratorStatistics {
  long steps = 0;
  long rhs_evaluations = 0;          // f(t, y) or residual evaluations
  long jacobian_evaluations = 0;
  long error_test_failures = 0;
  long nonlinear_iterations = 0;
  long convergence_failures = 0;
  long events = 0;                   // located events handled (impacts, stops engaging or releasing)
  double last_step = 0.0;            // s
};

class Integrator {
 public:
  virtual ~Integrator() = default;
  /// Starts (or restarts) the integration of the bound system at (t0, y0).
  virtual void initialize(double t0, const VectorX& y0) = 0;
  /// Advances the solution to exactly t_out; throws NumericalError on failure.
  virtual void advance_to(double t_out) = 0;
  virtual const VectorX& state() const = 0;
  virtual double time() const = 0;
  virtual IntegratorStatistics statistics() const = 0;
  /// A failure met outside advance_to -- an output's evaluation of the state it
  /// returned -- explained with what the integrator knows (an explicit step beyond its
  /// stability limit leaves a finite but meaningless state); unchanged by default.
  virtual NumericalError explain(const NumericalError& error) const { return error; }
};

class MultibodySystem;

/// The integrator of settings.method on the form of `system` that the method needs
/// (OdeForm, GglDaeForm or Index3Form), which the returned integrator owns. `system`
/// must outlive it.
std::unique_ptr<Integrator> make_integrator(const IntegratorSettings& settings, MultibodySystem& system);
/// The integrator of settings.method on a plain ODE (IDA on F = y' - f(t, y)); HHT needs
/// a second-order form and is refused with a ParameterError at `integrator`. `system` must outlive it.
std::unique_ptr<Integrator> make_integrator(const IntegratorSettings& settings, OdeSystem& system);
std::string integration_method_name(IntegrationMethod method);

}  // namespace heavesim
