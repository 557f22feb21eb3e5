#include "kernel/analysis/static_equilibrium.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>

#include <Eigen/Eigenvalues>
#include <Eigen/QR>
#include <Eigen/SVD>

#include "kernel/algorithms/configuration.hpp"
#include "kernel/algorithms/constraint_equations.hpp"
#include "kernel/algorithms/inverse_dynamics.hpp"
#include "kernel/algorithms/mass_matrix.hpp"
#include "kernel/algorithms/projection.hpp"
#include "kernel/system/dynamics_differentiator.hpp"

namespace heavesim {
namespace {

std::string format_number(const char* format, double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, format, value + 0.0);  // + 0.0: no "-0"
  return buffer;
}

std::string format_direction(const Vector3& d) {
  return "(" + format_number("%.3g", d.x()) + ", " + format_number("%.3g", d.y()) + ", " +
         format_number("%.3g", d.z()) + ")";
}

/// The equations at one point: r (nv), Phi (m), g of the states with a rest.
struct Residuals {
  VectorX force, constraint, rates;
  double load_scale = 0.0;
};

class EquilibriumProblem {
 public:
  EquilibriumProblem(MultibodySystem& system, double t, const VectorX& y_guess)
      : system_(system), model_(system.model()), t_(t), nq_(model_.nq), nv_(model_.nv),
        m_(model_.num_constraint_rows), nz_(system.element_state_size()), y_(y_guess),
        differentiator_(system), rows_(m_) {
    y_.segment(nq_, nv_).setZero();  // at rest
    std::iota(rows_.begin(), rows_.end(), 0);
    zero_acceleration_ = VectorX::Zero(nv_);
    lambda_ = VectorX::Zero(m_);
    q_work_.resize(nq_);  // integrate_configuration writes into a sized vector
  }

  /// The element states whose rates depend on neither q nor z at rest have no rest
  /// value (an integral of a speed): they are held.
  void classify_states() {
    differentiate();
    for (int k = 0; k < nz_; ++k) {
      const bool depends = derivatives_.rate_q.row(k).cwiseAbs().maxCoeff() > 0.0 ||
                           derivatives_.rate_z.row(k).cwiseAbs().maxCoeff() > 0.0;
      (depends ? solved_states_ : held_states_).push_back(k);
    }
  }

  /// r, Phi and g at the current (y, lambda); leaves J in data.constraint_jacobian.
  void evaluate(Residuals& out) {
    Data& data = system_.mutable_data();
    system_.compute_stages_and_forces(t_, y_);
    const AppliedForces& forces = system_.applied_forces();
    out.force = inverse_dynamics(model_, data, zero_acceleration_, forces.external_force_world);
    out.force -= forces.joint_force;
    // The largest load: weights, applied forces and joint forces, multipliers [N or N m].
    double scale = forces.joint_force.size() > 0 ? forces.joint_force.cwiseAbs().maxCoeff() : 0.0;
    for (int i = 1; i < model_.num_links(); ++i) {
      scale = std::max(scale, link_weight(model_, data, i).linear().norm());
      scale = std::max(scale, forces.external_force_world[i].linear().norm());
    }
    out.constraint.resize(m_);
    if (m_ > 0) {
      constraint_jacobian(model_, data, t_, data.constraint_jacobian);
      constraint_residual(model_, data, system_.configuration(), t_, out.constraint);
      out.force.noalias() -= data.constraint_jacobian.transpose() * lambda_;
      scale = std::max(scale, lambda_.cwiseAbs().maxCoeff());
    }
    out.rates.resize(static_cast<int>(solved_states_.size()));
    if (nz_ > 0) {
      rates_.resize(nz_);
      system_.element_state_derivatives(t_, y_, data, rates_);
      out.rates = rates_(solved_states_);
    }
    out.load_scale = scale > 0.0 ? scale : 1.0;
    if (!out.force.allFinite() || !out.constraint.allFinite() || !out.rates.allFinite())
      system_.report_non_finite(t_, out.force, "the static equilibrium equations");
  }

  /// The minimum-norm multipliers that balance the applied loads at the current q
  /// (least squares J^T lambda = ID - Q).
  void balance_multipliers() {
    if (m_ == 0) return;
    lambda_.setZero();
    Residuals at_zero;
    evaluate(at_zero);
    const MatrixX jt = system_.data().constraint_jacobian.transpose();
    Eigen::CompleteOrthogonalDecomposition<MatrixX> solver(jt.rows(), jt.cols());
    solver.setThreshold(constraint_rank_threshold);  // redundant rows get no share (projection.hpp)
    lambda_ = solver.compute(jt).solve(at_zero.force);
  }

  void differentiate() {
    differentiator_.differentiate(t_, y_, zero_acceleration_, rows_, lambda_, derivatives_, nullptr);
  }

  /// The tangent matrix of (r, Phi, g) in (dq, dlambda, dz_solved), at the current point.
  void tangent_matrix(MatrixX& a) {
    differentiate();
    const int s = static_cast<int>(solved_states_.size()), n = nv_ + m_ + s;
    a.setZero(n, n);
    a.topLeftCorner(nv_, nv_) = derivatives_.force_q;
    if (m_ > 0) {
      const MatrixX& j = differentiator_.rows_jacobian();
      a.block(0, nv_, nv_, m_) = -j.transpose();
      a.block(nv_, 0, m_, nv_) = j;
    }
    if (s > 0) {
      a.block(0, nv_ + m_, nv_, s) = derivatives_.force_z(Eigen::all, solved_states_);
      a.block(nv_ + m_, 0, s, nv_) = derivatives_.rate_q(solved_states_, Eigen::all);
      a.block(nv_ + m_, nv_ + m_, s, s) = derivatives_.rate_z(solved_states_, solved_states_);
    }
  }

  /// Moves the point by alpha * step = alpha [dq; dlambda; dz_solved] from (y0, lambda0).
  void move(const VectorX& y0, const VectorX& lambda0, const VectorX& step, double alpha) {
    y_ = y0;
    integrate_configuration(model_, y0.head(nq_), step.head(nv_), alpha, q_work_);
    y_.head(nq_) = q_work_;
    lambda_ = lambda0 + alpha * step.segment(nv_, m_);
    for (std::size_t k = 0; k < solved_states_.size(); ++k)
      y_[nq_ + nv_ + solved_states_[k]] += alpha * step[nv_ + m_ + static_cast<int>(k)];
  }

  MultibodySystem& system_;
  const Model& model_;
  double t_;
  int nq_, nv_, m_, nz_;
  VectorX y_, lambda_, zero_acceleration_, rates_, q_work_;
  DynamicsDifferentiator differentiator_;
  DynamicsDerivatives derivatives_;
  std::vector<int> rows_, solved_states_, held_states_;
};

/// Row and column scalings that bring every non-zero row and column of |a| to a largest
/// entry of about 1 (Ruiz 2001), so that the rank decision of the least-squares solve
/// does not depend on the units (N, N m, m, rad, the element states').
void equilibrate(const MatrixX& a, VectorX& row_scale, VectorX& column_scale) {
  row_scale.setOnes(a.rows());
  column_scale.setOnes(a.cols());
  MatrixX scaled = a;
  for (int pass = 0; pass < 10; ++pass) {
    for (int i = 0; i < a.rows(); ++i) {
      const double largest = scaled.row(i).cwiseAbs().maxCoeff();
      if (largest > 0.0) row_scale[i] /= std::sqrt(largest);
    }
    for (int j = 0; j < a.cols(); ++j) {
      const double largest = scaled.col(j).cwiseAbs().maxCoeff();
      if (largest > 0.0) column_scale[j] /= std::sqrt(largest);
    }
    scaled = row_scale.asDiagonal() * a * column_scale.asDiagonal();
  }
}

/// The size of the residuals in the units of the convergence test: r relative to the
/// load scale, Phi in m or rad, g as it is.
double scaled_norm(const Residuals& r, double load_scale) {
  return std::sqrt((r.force / load_scale).squaredNorm() + r.constraint.squaredNorm() + r.rates.squaredNorm());
}

double largest(const VectorX& x) { return x.size() > 0 ? x.cwiseAbs().maxCoeff() : 0.0; }

bool converged(const Residuals& r, double tolerance) {
  return largest(r.force) <= tolerance * r.load_scale && largest(r.constraint) <= tolerance &&
         largest(r.rates) <= tolerance;
}

}  // namespace

std::string describe_velocity_coordinate(const Model& model, const Data& data, int k) {
  for (int i = 1; i < model.num_links(); ++i) {
    const Joint& joint = model.joints[i];
    if (k < joint.v_index || k >= joint.v_index + joint.nv) continue;
    const Vector3 angular = data.motion_subspace_world.col(k).head<3>();
    const Vector3 linear = data.motion_subspace_world.col(k).tail<3>();
    // A pure translation has no angular part; a rotation is named by its world axis.
    const std::string what = angular.norm() == 0.0 ? "translation along world " + format_direction(linear.normalized())
                                                   : "rotation about world axis " + format_direction(angular.normalized());
    return what + " (coordinate " + std::to_string(k - joint.v_index) + ") of joint '" + joint.name + "' (body '" +
           model.links[i].name + "')";
  }
  return "velocity coordinate " + std::to_string(k);
}

EquilibriumResult solve_static_equilibrium(MultibodySystem& system, double t, const VectorX& y_guess,
                                           const EquilibriumSettings& settings) {
  const Model& model = system.model();
  EquilibriumProblem problem(system, t, y_guess);
  const int nv = model.nv, m = model.num_constraint_rows;
  // Start on the constraints (the smallest correction in kinetic energy), with the
  // multipliers that balance the loads there.
  if (m > 0) {
    VectorX q = problem.y_.head(model.nq), v = VectorX::Zero(nv);
    const ProjectionResult projected =
        project_to_constraints(model, system.mutable_data(), t, q, v, settings.tolerance, 50);
    if (projected.converged) problem.y_.head(model.nq) = q;
  }
  problem.balance_multipliers();
  problem.classify_states();

  Residuals residual, trial;
  problem.evaluate(residual);
  const double load_scale = residual.load_scale;  // fixed: the merit function must not change under the search
  MatrixX a;
  VectorX row_scale, column_scale, step, rhs;
  int iteration = 0;
  for (; !converged(residual, settings.tolerance); ++iteration) {
    if (iteration >= settings.max_iterations) {
      // The largest residual names what is not in balance.
      int worst_force = 0, worst_row = 0;
      const double force = largest(residual.force) / residual.load_scale;
      if (residual.force.size() > 0) residual.force.cwiseAbs().maxCoeff(&worst_force);
      const double phi = largest(residual.constraint);
      if (phi > 0.0) residual.constraint.cwiseAbs().maxCoeff(&worst_row);
      const std::string what =
          phi > force ? describe_constraint_row(model, worst_row) + ": |Phi| = " + format_number("%.3g", phi)
                      : describe_velocity_coordinate(model, system.data(), worst_force) + ": unbalanced " +
                            format_number("%.4g", residual.force[worst_force]) + " N or N m (" +
                            format_number("%.3g", force) + " of the largest load)";
      throw NumericalError(t,
                           "static equilibrium did not converge in " + std::to_string(settings.max_iterations) +
                               " Newton iterations; largest residual at " + what,
                           "start from joint `initial` values nearer the rest state, raise equilibrium.max_iterations, "
                           "or check that the elements acting there can balance the load");
    }
    problem.tangent_matrix(a);
    const int n = static_cast<int>(a.rows());
    rhs.resize(n);
    rhs << -residual.force / load_scale, -residual.constraint, -residual.rates;
    a.topRows(nv) /= load_scale;
    equilibrate(a, row_scale, column_scale);
    const MatrixX scaled = row_scale.asDiagonal() * a * column_scale.asDiagonal();
    // The threshold decides the rank when the decomposition is computed: set it first.
    Eigen::CompleteOrthogonalDecomposition<MatrixX> solver(n, n);
    solver.setThreshold(1e-10);
    solver.compute(scaled);
    step = column_scale.asDiagonal() * solver.solve(row_scale.asDiagonal() * rhs);
    // What the linearised step leaves of the residual: a part no step can remove (outside
    // the range) is a load nothing resists, or constraints that contradict each other.
    const VectorX left = a * step - rhs;
    const double before = rhs.norm();
    if (left.norm() > 0.5 * before) {
      int worst = 0;
      left.cwiseAbs().maxCoeff(&worst);
      if (worst < nv) {
        const Data& data = system.data();
        const Vector3 force_world = data.motion_subspace_world.col(worst).tail<3>() * -residual.force[worst];
        const bool translation = data.motion_subspace_world.col(worst).head<3>().norm() == 0.0;
        throw NumericalError(
            t,
            "no static equilibrium: nothing resists the load along " +
                describe_velocity_coordinate(model, data, worst) + " (unbalanced generalized force " +
                format_number("%.4g", -residual.force[worst]) +
                (translation ? " N, world force " + format_direction(force_world) + " N" : std::string(" N m")) +
                ")",
            "add what holds that direction (hydrostatics, a mooring, a spring, a joint or a driver), or run the case "
            "from its given initial state (initial: given)");
      }
      const int row = worst - nv;
      throw NumericalError(t,
                           row < m ? "no static equilibrium: the constraints cannot all hold; " +
                                         describe_constraint_row(model, row) + " contradicts the others"
                                   : "no static equilibrium: state " +
                                         std::to_string(problem.solved_states_[row - m]) +
                                         " of the force elements has no rest value",
                           "check the drivers' values at the start time and the loop joints' geometry");
    }
    // Backtracking (Armijo) on the scaled residual norm.
    const VectorX y0 = problem.y_, lambda0 = problem.lambda_;
    const double merit0 = scaled_norm(residual, load_scale);
    double alpha = 1.0;
    bool accepted = false;
    for (int halving = 0; halving < 12; ++halving, alpha *= 0.5) {
      problem.move(y0, lambda0, step, alpha);
      problem.evaluate(trial);
      if (scaled_norm(trial, load_scale) <= (1.0 - 1e-4 * alpha) * merit0) {
        accepted = true;
        break;
      }
    }
    if (!accepted) {  // the smallest step still moves on: the next tangent may do better
      problem.move(y0, lambda0, step, alpha);
      problem.evaluate(trial);
    }
    std::swap(residual, trial);
  }

  EquilibriumResult result;
  // The multipliers with no part along redundant rows (their split is not determined).
  problem.balance_multipliers();
  problem.evaluate(residual);
  result.state = problem.y_;
  result.multipliers = problem.lambda_;
  result.iterations = iteration;
  result.load_scale = residual.load_scale;
  result.force_residual = largest(residual.force) / residual.load_scale;
  result.constraint_residual = largest(residual.constraint);
  result.rate_residual = largest(residual.rates);
  result.held_states = problem.held_states_;

  // Stability: K x = w^2 M x on the directions the constraints allow, states condensed.
  problem.tangent_matrix(a);
  MatrixX stiffness = a.topLeftCorner(nv, nv);
  const int s = static_cast<int>(problem.solved_states_.size());
  if (s > 0) {
    const MatrixX coupling = a.block(0, nv + m, nv, s);
    const MatrixX rate_q = a.block(nv + m, 0, s, nv), rate_z = a.block(nv + m, nv + m, s, s);
    stiffness -= coupling * Eigen::CompleteOrthogonalDecomposition<MatrixX>(rate_z).solve(rate_q);
  }
  MatrixX allowed = MatrixX::Identity(nv, nv);
  if (m > 0) {
    const MatrixX& j = system.data().constraint_jacobian;
    Eigen::JacobiSVD<MatrixX> svd(j, Eigen::ComputeFullV);
    svd.setThreshold(constraint_rank_threshold);
    allowed = svd.matrixV().rightCols(nv - static_cast<int>(svd.rank()));
  }
  result.lowest_mode = VectorX::Zero(nv);
  if (allowed.cols() > 0) {
    Data& data = system.mutable_data();
    const MatrixX mass = allowed.transpose() * mass_matrix(model, data) * allowed;
    const MatrixX reduced = allowed.transpose() * stiffness * allowed;
    const Eigen::LLT<MatrixX> cholesky(mass);
    const MatrixX l_inverse = cholesky.matrixL().solve(MatrixX::Identity(mass.rows(), mass.cols()));
    const MatrixX normalised = l_inverse * reduced * l_inverse.transpose();
    const Eigen::EigenSolver<MatrixX> eigen(normalised);
    const Eigen::VectorXcd values = eigen.eigenvalues();
    int lowest = 0;
    values.real().minCoeff(&lowest);
    const double largest_value = values.cwiseAbs().maxCoeff();
    // Finite-difference stiffness carries errors of about 1e-7 of its scale (step 1e-7):
    // a w^2 below 1e-6 of the largest is zero.
    const double zero = 1e-6 * largest_value;
    for (int k = 0; k < values.size(); ++k)
      if (std::abs(values[k].real()) <= zero) ++result.neutral_directions;
    result.lowest_squared_frequency = values[lowest].real();
    result.stability = result.lowest_squared_frequency < -zero  ? EquilibriumStability::unstable
                       : result.neutral_directions > 0 || largest_value == 0.0 ? EquilibriumStability::neutral
                                                                                : EquilibriumStability::stable;
    const VectorX shape = eigen.eigenvectors().col(lowest).real();
    result.lowest_mode = allowed * l_inverse.transpose() * shape;
    const double peak = largest(result.lowest_mode);
    if (peak > 0.0) {
      int at = 0;
      result.lowest_mode.cwiseAbs().maxCoeff(&at);
      result.lowest_mode /= result.lowest_mode[at];
    }
  }
  // Leave the system's stages at the rest state (the caller records them).
  problem.evaluate(residual);
  return result;
}

}  // namespace heavesim
