#include "kernel/integrators/hht_integrator.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include "kernel/math/index_list.hpp"

namespace heavesim {
namespace {

/// The penalty's share of Newton's matrix: c max diag(J^T J) = kappa max diag(M).
/// Each multiplier update shrinks Phi by about kappa, and along a direction the
/// constraints are losing (distance eps from a singular configuration) the loop is
/// held with stiffness ~ kappa eps^2, so kappa must be large: with 1e4 the IFToMM A02
/// runs with N = 2 stalled at their first singular pass, with 1e6 they passed but lost
/// energy there (4.6e-6 rad at h = 0.2 ms), with 1e8 they pass at the accuracy the step
/// gives (2.8e-7 rad; docs/validation.md, L2). Newton's matrix then carries ~8 digits
/// fewer, which its iteration recovers: the residual is always evaluated exactly.
constexpr double kappa = 1e8;
/// Regularization of the projections' J M^-1 J^T (relative to its largest diagonal):
/// directions the constraints are losing (eigenvalue below ~1e-8 of the largest, within
/// ~1e-4 of a singular configuration) fade out smoothly instead of being inverted. An
/// exact pseudo-inverse kicked the speeds by residual/eigenvalue there, and a hard
/// cutoff kicked them as a direction switched back on (A02 with N = 2).
constexpr double projection_regularization = 1e-8;
// Newton's iteration stops after 8 iterations unless it is still contracting (each
// correction below 0.9 of the last).
constexpr int min_newton_iterations = 8;
constexpr int max_newton_iterations = 60;
constexpr int max_halvings = 10;

}  // namespace

HhtIntegrator::HhtIntegrator(SecondOrderSystem& system, const IntegratorSettings& settings)
    : settings_(settings), system_(system) {
  alpha_ = std::clamp(settings.hht_alpha, -1.0 / 3.0, 0.0);
  gamma_ = 0.5 - alpha_;
  beta_ = 0.25 * (1.0 - alpha_) * (1.0 - alpha_);
}

void HhtIntegrator::initialize(double t0, const VectorX& y0) {
  nq_ = system_.configuration_size();
  nv_ = system_.velocity_size();
  nz_ = system_.element_state_size();
  m_ = system_.constraint_size();
  t_ = t0;
  y_ = y0;
  statistics_ = {};
  matrix_step_ = 0.0;
  system_.initial_accelerations(t0, y_, acceleration_, rate_, multipliers_);
  final_constraint_residual_.setZero(m_);
  system_.constraint_terms(t0, y_, terms_);
  // At t0 the accelerations satisfy the equations of motion exactly: f_0 = -M a_0.
  previous_force_.noalias() = -terms_.mass * acceleration_;
  delta_.resize(nv_);
  z_.resize(nz_);
  a_.resize(nv_);
  zdot_.resize(nz_);
  y_iterate_.resize(y_.size());
  q_step_.resize(nq_);
  residual_.resize(nv_ + nz_);
  correction_.resize(nv_ + nz_);
  phi_.resize(m_);
  newton_matrix_.resize(nv_ + nz_, nv_ + nz_);
  active_jacobian_.resize(m_, nv_);
  mass_llt_ = SizedCholesky(nv_);  // sized storage, no factor yet
  // The projections use the rows independent at the start (a column-pivoted QR of J^T,
  // as the GGL form keeps its rows): structurally redundant rows -- the out-of-plane
  // rows of a planar loop closed by 3-D revolute joints, 120 of the 200 rows of IFToMM
  // A02 with N = 40 -- add nothing to them but a cubic cost in J M^-1 J^T (measured: the
  // 200-row factorization made most of that run's time).
  projection_rows_ = system_.independent_constraint_rows();
  const int kept = static_cast<int>(projection_rows_.size());
  projection_jacobian_.resize(kept, nv_);
  schur_solver_ = RegularizedSymmetricSolver(kept);
  projection_residual_.resize(kept);
  projection_multipliers_.resize(kept);
  projection_step_.resize(nv_);
  whitened_jacobian_t_.resize(nv_, kept);
  schur_.resize(kept, kept);
}

void HhtIntegrator::iterate_state(double h) {
  // a_{n+1} and v_{n+1} from Delta (Newmark), zdot_{n+1} from z_{n+1} (generalized trapezoid).
  a_ = delta_;
  a_.noalias() -= h * y_.segment(nq_, nv_);
  a_.noalias() -= h * h * (0.5 - beta_) * acceleration_;
  a_ /= beta_ * h * h;
  system_.integrate_configuration(q_start_, delta_, q_step_);
  y_iterate_.head(nq_) = q_step_;
  y_iterate_.segment(nq_, nv_) = y_.segment(nq_, nv_);
  y_iterate_.segment(nq_, nv_).noalias() += h * (1.0 - gamma_) * acceleration_;
  y_iterate_.segment(nq_, nv_).noalias() += h * gamma_ * a_;
  if (nz_ > 0) {
    zdot_ = z_ - y_.tail(nz_);
    zdot_.noalias() -= h * (1.0 - gamma_) * rate_;
    zdot_ /= h * gamma_;
    y_iterate_.tail(nz_) = z_;
  }
}

void HhtIntegrator::build_newton_matrix(double h) {
  // d/dDelta of beta h^2 R_v with R_v = (1 + alpha)[ID(q, v, a/(1+alpha)) - Q - J^T lambda] + alpha M_n a_n
  // (ID is linear in a), and of h gamma R_z with R_z = zdot - g.
  const double scale = 1.0 + alpha_;
  a_ /= scale;
  system_.dynamics_derivatives(t_ + h, y_iterate_, a_, derivatives_);
  a_ *= scale;
  ++statistics_.jacobian_evaluations;
  const DynamicsDerivatives& d = derivatives_;
  double weight = 0.0;  // c = beta h^2 (1 + alpha) p
  if (m_ > 0) {
    system_.constraint_terms(t_ + h, y_iterate_, terms_);
    const double constraint_scale = terms_.jacobian.colwise().squaredNorm().maxCoeff();
    const double mass_scale = terms_.mass.diagonal().maxCoeff();
    weight = constraint_scale > 0.0 ? kappa * mass_scale / constraint_scale : 0.0;
    penalty_ = weight / (beta_ * h * h * scale);
  }
  auto vv = newton_matrix_.topLeftCorner(nv_, nv_);
  vv = d.mass;
  vv.noalias() += (gamma_ * h * scale) * d.force_v;
  vv.noalias() += (beta_ * h * h * scale) * d.force_q;
  if (m_ > 0) {
    // J^T J over the rows that are not identically zero. The structurally redundant rows
    // of a planar loop closed by 3-D joints (120 of the 200 of IFToMM A02 with N = 40)
    // are exact zeros: they add nothing to the sum but a third of a cubic product each
    // (measured: the 200-row product was the largest single cost of that run).
    Eigen::Index active = 0;
    for (Eigen::Index row = 0; row < m_; ++row)
      if ((terms_.jacobian.row(row).array() != 0.0).any()) active_jacobian_.row(active++) = terms_.jacobian.row(row);
    const auto rows = active_jacobian_.topRows(active);
    vv.noalias() += weight * (rows.transpose() * rows);
  }
  if (nz_ > 0) {
    newton_matrix_.topRightCorner(nv_, nz_) = (beta_ * h * h * scale) * d.force_z;
    newton_matrix_.bottomLeftCorner(nz_, nv_) = -(h * gamma_) * d.rate_q;
    newton_matrix_.bottomLeftCorner(nz_, nv_).noalias() -= (gamma_ * gamma_ / beta_) * d.rate_v;
    newton_matrix_.bottomRightCorner(nz_, nz_) = -(h * gamma_) * d.rate_z;
    newton_matrix_.bottomRightCorner(nz_, nz_).diagonal().array() += 1.0;
  }
  newton_lu_.compute(newton_matrix_);
  matrix_step_ = h;
}

bool HhtIntegrator::try_step(double h) {
  const double t1 = t_ + h, scale = 1.0 + alpha_;
  // Predictor: constant acceleration and element-state rates.
  q_start_ = y_.head(nq_);
  delta_ = h * y_.segment(nq_, nv_);
  delta_.noalias() += 0.5 * h * h * acceleration_;
  if (nz_ > 0) {
    z_ = y_.tail(nz_);
    z_.noalias() += h * rate_;
  }
  iterate_state(h);
  // Modified Newton: a matrix serves as long as it contracts well (it is rebuilt for a
  // new step size, and whenever a correction shrinks less than 3x -- near a singular
  // configuration the tangent turns quickly).
  force_multipliers_ = multipliers_;
  bool fresh = false;
  if (matrix_step_ != h) {
    build_newton_matrix(h);
    fresh = true;
  }
  lambda_ = multipliers_;
  if (m_ > 0) lambda_.noalias() += penalty_ * final_constraint_residual_;
  double last_correction = std::numeric_limits<double>::infinity();
  for (int iteration = 0; iteration < max_newton_iterations; ++iteration) {
    a_ /= scale;
    try {
      system_.dynamics_residual(t1, y_iterate_, a_, zdot_, penalty_, lambda_, residual_.head(nv_),
                                 residual_.tail(nz_), phi_);
    } catch (const NumericalError& error) {
      // A diverging iterate (not necessarily the model): a smaller step may pass.
      last_failure_ = error;
      matrix_step_ = 0.0;
      ++statistics_.convergence_failures;
      return false;
    }
    a_ *= scale;
    ++statistics_.rhs_evaluations;
    ++statistics_.nonlinear_iterations;
    const double constraint_error = m_ > 0 ? phi_.cwiseAbs().maxCoeff() : 0.0;
    force_multipliers_ = lambda_;
    force_multipliers_.noalias() -= penalty_ * phi_;
    residual_.head(nv_) *= beta_ * h * h * scale;
    residual_.head(nv_).noalias() -= (beta_ * h * h * alpha_) * previous_force_;
    if (nz_ > 0) residual_.tail(nz_) *= h * gamma_;
    correction_ = newton_lu_.solve(residual_);
    if (!correction_.allFinite()) break;
    delta_ -= correction_.head(nv_);
    if (nz_ > 0) z_ -= correction_.tail(nz_);
    iterate_state(h);
    // Converged when the loops are closed and the speeds' error left after this
    // correction -- gamma / (beta h) |d Delta| rho / (1 - rho), rho the contraction
    // rate -- is within the tolerances. Speeds, not positions: Newmark turns an error
    // d in Delta into d gamma/(beta h) in v and d/(beta h^2) in a, so a positional test
    // lets the speeds random-walk over many small steps. Below round-off of q the
    // iteration cannot go, and stops.
    const double correction = correction_.cwiseAbs().maxCoeff(), contraction = correction / last_correction;
    const double rho = std::min(contraction, 0.9);
    const double remaining = iteration == 0 ? std::numeric_limits<double>::infinity() : rho / (1.0 - rho);
    const double speed_error = remaining * gamma_ / (beta_ * h) * correction_.head(nv_).cwiseAbs().maxCoeff();
    // The step size sets this method's accuracy; Newton's error per step must stay far
    // below it because it adds up over many steps: 1/1000 of the user's tolerances on the
    // speeds, and never looser than 1e-10 relative (measured: the L1 slider-crank at
    // h = 0.5 ms drifts to 2e-6 rad with 1e-9, stays at the step's 9e-8 with 1e-10).
    const double speed_scale = y_iterate_.segment(nq_, nv_).cwiseAbs().maxCoeff();
    const double speed_tolerance =
        std::min(1e-3 * (settings_.absolute_tolerance + settings_.relative_tolerance * speed_scale),
                 1e-10 * (1.0 + speed_scale));
    const double round_off = 16.0 * std::numeric_limits<double>::epsilon() * (1.0 + y_.head(nq_).cwiseAbs().maxCoeff());
    // A correction that no longer shrinks, within ~1e4 round-offs of q, is the noise
    // floor of the residual: the penalty's p Phi turns the round-off of Phi (which grows
    // with the mechanism's extent, ~40 m for the 81 rods of IFToMM A02 with N = 40)
    // into multiplier noise. Measured on A02: the corrections stall at 1e-11..2e-11
    // for N = 40 near its first flat pass (1000 round-offs stopped the run there at
    // t = 0.72 s; 1e4 carries it through 20 s, B0 within 4e-7 m of the exact motion).
    const bool at_noise_floor = iteration >= 2 && contraction > 0.5 && correction <= 1e4 * round_off;
    bool converged = constraint_error <= settings_.constraint_tolerance &&
                     (speed_error <= speed_tolerance || correction <= round_off || at_noise_floor);
    for (int k = 0; k < nz_ && converged; ++k)
      converged = remaining * std::abs(correction_[nv_ + k]) <=
                  settings_.absolute_tolerance + settings_.relative_tolerance * std::abs(z_[k]);
    const double newton_tolerance = speed_tolerance * beta_ * h / gamma_;  // the same, on Delta
    if (converged) return true;
    if (iteration >= min_newton_iterations && contraction > 0.9) break;
    last_correction = correction;
    // A matrix is rebuilt only while the corrections are well above the tolerance: a
    // slow ratio between two corrections near round-off says nothing about the matrix.
    const bool far = correction > 100.0 * newton_tolerance;
    if (far && iteration >= 1 && contraction > 1.0 / 3.0 && (!fresh || iteration >= 2)) {
      build_newton_matrix(h);
      fresh = true;
    }
  }
  // Remember where it failed, for the diagnosis; the next try starts with a new matrix.
  worst_residual_ = residual_.cwiseAbs().maxCoeff(&worst_row_);
  last_failure_.reset();
  matrix_step_ = 0.0;
  ++statistics_.convergence_failures;
  return false;
}

void HhtIntegrator::accept_step(double h) {
  t_ += h;
  y_ = y_iterate_;
  acceleration_ = a_;
  rate_ = zdot_;
  // The multipliers of the constraint forces actually applied, lambda* - p Phi, and the
  // Phi they came with: the next step starts from lambda* = that + p' Phi, so that the
  // force stays continuous when the penalty p' (which scales with 1/h^2) changes.
  multipliers_ = force_multipliers_;
  final_constraint_residual_ = phi_;
  system_.constraint_terms(t_, y_, terms_);
  if (m_ > 0) {
    mass_llt_.compute(terms_.mass);
    projection_jacobian_ = terms_.jacobian(index_list(projection_rows_), Eigen::all);
    // With M = L L^T and W = L^-1 J^T: J M^-1 J^T = W^T W, one triangular solve and a
    // symmetric product (half a general one), and M^-1 J^T mu = L^-T (W mu) is applied to
    // the vector in project(). Before: two triangular solves for M^-1 J^T and the general
    // product J (M^-1 J^T), most of a step of IFToMM A02 with N = 40 (80 rows, 81 speeds).
    whitened_jacobian_t_ = projection_jacobian_.transpose();
    mass_llt_.matrixL().solveInPlace(whitened_jacobian_t_);
    schur_.setZero();  // the solver's Cholesky reads the lower triangle only
    schur_.selfadjointView<Eigen::Lower>().rankUpdate(whitened_jacobian_t_.transpose());
    schur_solver_.compute(schur_, projection_regularization);
    speeds_ = y_.segment(nq_, nv_);
    project(speeds_, terms_.velocity_target);
    y_.segment(nq_, nv_) = speeds_;
    system_.constraint_bias_at(t_, y_, gamma_target_);
    project(acceleration_, gamma_target_);
  }
  if (alpha_ != 0.0) {
    // f_{n+1} = C - Q - J^T lambda at the accepted state, for the next step's alpha term
    // (HHT weights the forces of both ends of a step; its accelerations do not satisfy
    // M a + f = 0 at either end, so f cannot be recovered from them).
    zero_acceleration_.setZero(nv_);
    lambda_ = force_multipliers_;
    system_.dynamics_residual(t_, y_, zero_acceleration_, zdot_, 0.0, lambda_, previous_force_, residual_.tail(nz_),
                               phi_);
  }
  ++statistics_.steps;
  statistics_.last_step = h;
}

void HhtIntegrator::project(VectorX& x, const VectorX& target) {
  projection_residual_.noalias() = projection_jacobian_ * x;
  projection_residual_ -= target(index_list(projection_rows_));
  schur_solver_.solve(projection_residual_, projection_multipliers_);
  projection_step_.noalias() = whitened_jacobian_t_ * projection_multipliers_;
  mass_llt_.matrixU().solveInPlace(projection_step_);  // M^-1 J^T mu = L^-T (W mu)
  x -= projection_step_;
}

void HhtIntegrator::fail(double h) {
  char what[320];
  const std::string where = system_.describe_component(worst_row_);
  if (last_failure_)
    std::snprintf(what, sizeof what, "HHT step-size collapse: Newton's iteration diverged even with a step of %.3g s", h);
  else if (worst_row_ < nv_)
    std::snprintf(what, sizeof what,
                  "HHT step-size collapse: Newton's iteration did not converge even with a step of %.3g s "
                  "(largest residual %.3g, in the equation of motion of the %s)",
                  h, worst_residual_, where.c_str());
  else
    std::snprintf(what, sizeof what,
                  "HHT step-size collapse: Newton's iteration did not converge even with a step of %.3g s "
                  "(largest residual %.3g, in the rate of the %s)",
                  h, worst_residual_, where.c_str());
  // The cause, most specific first: the loops at the last accepted state (a driver
  // beyond their reach says so whatever the integrator), then the evaluation's own
  // error with its own remedy (an element out of its range), then the generic advice.
  const StateDiagnosis note = system_.state_note(t_, y_);
  if (!note.empty())
    throw NumericalError(t_, std::string(what) + "; " + note.what,
                         !note.suggestion.empty()
                             ? note.suggestion
                             : "the loops lose rank here: a smaller solver.step resolves the pass better; check that "
                               "the mechanism can pass this configuration (a toggle or dead centre locks it)");
  if (last_failure_)
    throw NumericalError(t_, std::string(what) + ": " + last_failure_->what(), last_failure_->suggestion());
  throw NumericalError(t_, what,
                       "look for a discontinuous or unstable force element, or a configuration the constraints "
                       "cannot reach; a smaller solver.step, or hht_alpha < 0 to damp stiff modes");
}

void HhtIntegrator::advance_to(double t_out) {
  // Equal steps no longer than `step` up to t_out: a sliver of a step left over by
  // rounding would be fatal here (Newmark divides by beta h^2).
  if (!(t_out > t_)) return;
  const double span = t_out - t_;
  const long steps = std::max(1L, static_cast<long>(std::ceil(span / settings_.step - 1e-6)));
  const double nominal = span / static_cast<double>(steps), t_start = t_;
  for (long k = 0; k < steps; ++k) {
    const double t_target = k + 1 == steps ? t_out : t_start + (k + 1) * nominal;
    while (t_target - t_ > 1e-6 * nominal) {
      double h = std::min(nominal, t_target - t_);
      int halvings = 0;
      while (!try_step(h)) {
        if (++halvings > max_halvings) fail(h);
        h *= 0.5;
      }
      accept_step(h);
    }
    t_ = t_target;
  }
}

}  // namespace heavesim
