#pragma once
// What a position-level (index-3) implicit integrator sees of a constrained
// mechanical system: the equations of motion in their second-order form,
//   r_v = ID(q, v, a) - Q(t, q, v, z) - J(q)^T lambda = 0     (nv; N or N m per coordinate)
//   Phi(q, t) = 0                                           (m; m or rad)
//   r_z = zdot - g(t, q, v, z) = 0                          (nz; element states)
// with ID the inverse dynamics (M a + C), Q the applied generalized forces (gravity,
// external loads, joint and force elements), J = dPhi/dq in velocity coordinates and
// the multipliers' sign as in constraint_equations.hpp. Derivatives with respect to
// q are taken along the tangent directions of the configuration manifold (those of
// integrate_configuration), so quaternion joints need no special care by the caller.
#include <vector>

#include "kernel/system/ode_system.hpp"

namespace heavesim {

/// Partial derivatives of (r_v, r_z) at one point; the caller owns the storage
/// (sized on first use, then reused).
struct DynamicsDerivatives {
  MatrixX mass;     // d r_v / d a = M(q)                                  nv x nv
  MatrixX force_q;  // d r_v / d(tangent q): dID/dq - dQ/dq (see dynamics_derivatives)  nv x nv
  MatrixX force_v;  // d r_v / d v = dID/dv - dQ/dv                         nv x nv
  MatrixX force_z;  // d r_v / d z = -dQ/dz                                 nv x nz
  MatrixX rate_q;   // d g / d(tangent q)                                  nz x nv
  MatrixX rate_v;   // d g / d v                                           nz x nv
  MatrixX rate_z;   // d g / d z                                           nz x nz
};

/// Everything a projection onto the constraint manifold needs at (t, q, v).
struct ConstraintTerms {
  MatrixX mass;      // M(q), nv x nv
  MatrixX jacobian;  // J(q), m x nv
  VectorX residual;  // Phi(q, t), m
  VectorX velocity_target;  // nu(t) = -dPhi/dt: J v = nu, m
  VectorX bias;      // gamma(t, q, v): J a = gamma, m
};

/// Components (describe_component): velocity coordinates 0 .. nv-1, then element
/// states nv .. nv+nz-1; diagnose_state takes y = [q; v; z].
class SecondOrderSystem : public FailureDiagnosis {
 public:
  virtual ~SecondOrderSystem() = default;
  virtual int configuration_size() const = 0;  // nq
  virtual int velocity_size() const = 0;       // nv
  virtual int constraint_size() const = 0;     // m, every constraint row
  virtual int element_state_size() const = 0;  // nz

  /// q_out = q "+" step (joint by joint on the manifold).
  virtual void integrate_configuration(const VectorX& q, const VectorX& step, VectorX& q_out) const = 0;

  /// Accelerations a, element-state rates zdot and multipliers lambda consistent with
  /// the state y at t (the index-1 solution), to start an integration.
  virtual void initial_accelerations(double t, const VectorX& y, VectorX& a, VectorX& zdot, VectorX& lambda) = 0;
  /// The constraint rows independent at the state of initial_accelerations (ascending):
  /// the others are redundant there (the out-of-plane rows of a planar loop closed by
  /// 3-D revolute joints).
  virtual const std::vector<int>& independent_constraint_rows() const = 0;

  /// r_v, r_z and Phi at (t, y = [q; v; z]) for accelerations a and element-state
  /// rates zdot, in the augmented-Lagrangian form of Bayo & Ledesma (1996): the
  /// multipliers are first updated, lambda <- lambda - penalty Phi(q, t), and the
  /// constraint force is then J^T (lambda - penalty Phi).
  /// penalty >= 0 is a stiffness in the rows' units (N/m, N m/rad). Throws
  /// NumericalError for non-finite values.
  virtual void dynamics_residual(double t, const VectorX& y, const VectorX& a, const VectorX& zdot, double penalty,
                                 VectorX& lambda, Eigen::Ref<VectorX> r_v,
                                 Eigen::Ref<VectorX> r_z, Eigen::Ref<VectorX> phi) = 0;

  /// The partial derivatives of r_v and r_z at (t, y, a), without the constraint
  /// forces' own dependence on q (their geometric stiffness d(J^T lambda)/dq): at a
  /// singular configuration the multipliers along the directions being lost are not
  /// determined, and a tangent built from them sends Newton's iteration astray
  /// (measured on IFToMM A02, docs/validation.md L2).
  virtual void dynamics_derivatives(double t, const VectorX& y, const VectorX& a, DynamicsDerivatives& out) = 0;

  /// M, J, Phi, nu and gamma at (t, y).
  virtual void constraint_terms(double t, const VectorX& y, ConstraintTerms& out) = 0;
  /// gamma(t, q, v) alone.
  virtual void constraint_bias_at(double t, const VectorX& y, VectorX& gamma) = 0;
};

}  // namespace heavesim
