#include "kernel/system/fastest_mode.hpp"

#include <cmath>
#include <complex>
#include <cstdio>
#include <vector>

#include <Eigen/Eigenvalues>
#include <Eigen/SVD>

#include "kernel/algorithms/configuration.hpp"
#include "kernel/algorithms/generalized_force.hpp"
#include "kernel/algorithms/joint_forces.hpp"
#include "kernel/algorithms/kinematics.hpp"
#include "kernel/elements/body_point.hpp"
#include "kernel/system/dynamics_differentiator.hpp"

namespace heavesim {
namespace {

/// The real shape of a complex mode: turned so that its largest entry is real, scaled
/// to a largest entry of 1.
VectorX real_shape(const Eigen::VectorXcd& shape) {
  Eigen::Index largest = 0;
  shape.cwiseAbs().maxCoeff(&largest);
  const double size = std::abs(shape[largest]);
  const std::complex<double> phase = size > 0.0 ? shape[largest] / size : std::complex<double>(1.0);
  VectorX x = (shape / phase).real();
  const double norm = x.cwiseAbs().maxCoeff();
  if (norm > 0.0) x /= norm;
  return x;
}

/// The body that moves most in the mode x (velocity coordinates), by its kinetic energy
/// per unit mass: the light body of a chain, not the joint nearest the root.
std::string moving_body(const Model& model, const VectorX& q, const VectorX& x) {
  Data data(model);
  update_positions(model, data, q);
  update_velocities(model, data, q, x);
  int best = -1;
  double best_motion = 0.0;
  for (int i = 1; i < model.num_links(); ++i) {
    const Inertia& inertia = model.links[i].inertia;
    if (!(inertia.mass() > 0.0)) continue;
    const Vector3 com_velocity = BodyPoint{i, inertia.com()}.velocity_world(data);
    const double gyration = inertia.inertia_com().trace() / inertia.mass();  // m^2
    const double motion = com_velocity.squaredNorm() + data.velocity_world[i].angular().squaredNorm() * gyration;
    if (motion > best_motion) {
      best_motion = motion;
      best = i;
    }
  }
  if (best < 0) return "massless bodies only";
  char mass[32];
  std::snprintf(mass, sizeof mass, "%.3g kg", model.links[best].inertia.mass());
  return "body '" + model.links[best].name + "' (" + mass + ", joint '" + model.joints[best].name + "')";
}

/// What each source of applied force (every force element, the spring and limits of
/// every joint) does along the mode x: |x . K_e x| + |lambda| |x . C_e x|, its modal
/// stiffness and damping (forward differences in q and v); the largest names the cause.
class ModalShares {
 public:
  ModalShares(MultibodySystem& system, double t, const VectorX& y)
      : system_(system), model_(system.model()), t_(t), y_(y), base_(model_), perturbed_(model_),
        forces_(model_), subtree_(model_.num_links(), Force::Zero()) {
    q_ = y.head(model_.nq);
    v_ = y.segment(model_.nq, model_.nv);
    update_positions(model_, base_, q_);
    update_velocities(model_, base_, q_, v_);
  }

  /// "the spring-damper 'strut'" or "the spring of joint 'slide2' and the spring of
  /// joint 'slide3'"; "" when no source carries a tenth of the mode's stiffness.
  std::string dominant(const VectorX& x, double rate) {
    const double h = 1e-6;
    VectorX q_step(model_.nq), v_step = v_ + h * x;
    integrate_configuration(model_, q_, x, h, q_step);
    std::vector<std::pair<double, std::string>> shares;
    const auto& elements = system_.force_elements();
    for (std::size_t e = 0; e < elements.size(); ++e) {
      // The element's generalized force on the stages given, mapped with the base
      // configuration's subspaces (as DynamicsDifferentiator does).
      auto element_force = [&](const Data& stages) {
        forces_.clear();
        elements[e]->apply(t_, model_, stages, y_.segment(system_.state_offset(e), elements[e]->state_size()), forces_);
        VectorX out(model_.nv);
        generalized_applied_force(model_, base_, forces_.external_force_world, forces_.joint_force, subtree_, out);
        return out;
      };
      const VectorX f0 = element_force(base_);
      at(q_step, v_);
      const VectorX fq = element_force(perturbed_);
      at(q_, v_step);
      const VectorX fv = element_force(perturbed_);
      shares.emplace_back(share(x, f0, fq, fv, h, rate), "force element '" + elements[e]->name() + "'");
    }
    VectorX tau0 = VectorX::Zero(model_.nv), tauq = tau0, tauv = tau0;
    add_joint_element_forces(model_, q_, v_, tau0);
    add_joint_element_forces(model_, q_step, v_, tauq);
    add_joint_element_forces(model_, q_, v_step, tauv);
    for (int i = 1; i < model_.num_links(); ++i) {
      const Joint& joint = model_.joints[i];
      if ((!joint.spring && !joint.limits) || joint.nv == 0) continue;
      const auto segment = [&](const VectorX& tau) {
        VectorX out = VectorX::Zero(model_.nv);
        out.segment(joint.v_index, joint.nv) = tau.segment(joint.v_index, joint.nv);
        return out;
      };
      const std::string what = joint.spring && joint.limits ? "spring and limits" : joint.spring ? "spring" : "limits";
      shares.emplace_back(share(x, segment(tau0), segment(tauq), segment(tauv), h, rate),
                          "the " + what + " of joint '" + joint.name + "'");
    }
    double largest = 0.0;
    for (const auto& [value, name] : shares) largest = std::max(largest, value);
    if (!(largest > 0.1 * total_)) return "";
    // Every source within half of the largest: a light body between two springs is
    // held by both.
    std::string names;
    for (const auto& [value, name] : shares)
      if (value >= 0.5 * largest) names += (names.empty() ? "" : " and ") + name;
    return names;
  }

  /// Sets the total modal stiffness the shares are compared with (|x . K x| + |lambda| |x . C x|).
  void set_total(double total) { total_ = total; }

 private:
  void at(const VectorX& q, const VectorX& v) {
    update_positions(model_, perturbed_, q);
    update_velocities(model_, perturbed_, q, v);
  }
  static double share(const VectorX& x, const VectorX& f0, const VectorX& fq, const VectorX& fv, double h,
                      double rate) {
    return std::abs(x.dot(fq - f0)) / h + rate * std::abs(x.dot(fv - f0)) / h;
  }

  MultibodySystem& system_;
  const Model& model_;
  double t_;
  const VectorX& y_;
  VectorX q_, v_;
  Data base_, perturbed_;
  AppliedForces forces_;
  AlignedVector<Force> subtree_;
  double total_ = 0.0;
};

}  // namespace

FastestMode find_fastest_mode(MultibodySystem& system, double t, const VectorX& y) {
  const Model& model = system.model();
  const int nq = model.nq, nv = model.nv, nz = system.element_state_size();
  system.compute_accelerations(t, y);  // qdd and the multipliers at (t, y)
  const VectorX acceleration = system.data().qdd;
  std::vector<int> rows(model.num_constraint_rows);
  for (int k = 0; k < model.num_constraint_rows; ++k) rows[k] = k;
  const VectorX multipliers = system.data().constraint_multipliers;
  DynamicsDifferentiator differentiator(system);
  DynamicsDerivatives d;
  differentiator.differentiate(t, y, acceleration, rows, multipliers, d, nullptr);

  // The motions the constraints allow: the null space of J.
  MatrixX basis = MatrixX::Identity(nv, nv);
  if (!rows.empty()) {
    const Eigen::JacobiSVD<MatrixX> svd(differentiator.rows_jacobian(), Eigen::ComputeFullV);
    const VectorX& sigma = svd.singularValues();
    const int rank = sigma.size() == 0 ? 0 : static_cast<int>((sigma.array() > 1e-8 * sigma[0]).count());
    basis = svd.matrixV().rightCols(nv - rank);
  }
  const int n = static_cast<int>(basis.cols());
  if (n + nz == 0) return {};
  const MatrixX mass = basis.transpose() * d.mass * basis;
  const Eigen::LDLT<MatrixX> mass_solver(mass);
  MatrixX A = MatrixX::Zero(2 * n + nz, 2 * n + nz);
  A.block(0, n, n, n).setIdentity();
  A.block(n, 0, n, n) = -mass_solver.solve(basis.transpose() * d.force_q * basis);
  A.block(n, n, n, n) = -mass_solver.solve(basis.transpose() * d.force_v * basis);
  if (nz > 0) {
    A.block(n, 2 * n, n, nz) = -mass_solver.solve(basis.transpose() * d.force_z);
    A.block(2 * n, 0, nz, n) = d.rate_q * basis;
    A.block(2 * n, n, nz, n) = d.rate_v * basis;
    A.block(2 * n, 2 * n, nz, nz) = d.rate_z;
  }
  if (!A.allFinite()) return {};
  const Eigen::EigenSolver<MatrixX> eigen(A);
  if (eigen.info() != Eigen::Success) return {};
  Eigen::Index fastest = 0;
  eigen.eigenvalues().cwiseAbs().maxCoeff(&fastest);
  FastestMode mode;
  mode.eigenvalue = eigen.eigenvalues()[fastest];
  if (!(std::abs(mode.eigenvalue) > 0.0)) return {};
  const Eigen::VectorXcd shape = eigen.eigenvectors().col(fastest);
  // A mode of the element states (a thermal time constant, a valve) moves them more
  // than the speeds: it is named by its element.
  if (nz > 0 && shape.tail(nz).norm() > shape.segment(n, n).norm()) {
    Eigen::Index k = 0;
    shape.tail(nz).cwiseAbs().maxCoeff(&k);
    mode.where = "the " + system.describe_state_component(nq + nv + static_cast<int>(k));
    return mode;
  }
  const VectorX x = basis * real_shape(shape.head(n));
  mode.where = moving_body(model, y.head(nq), x);
  const double rate = std::abs(mode.eigenvalue);
  ModalShares shares(system, t, y);
  shares.set_total(std::abs(x.dot(d.force_q * x)) + rate * std::abs(x.dot(d.force_v * x)));
  mode.element = shares.dominant(x, rate);
  return mode;
}

}  // namespace heavesim
