#pragma once
// Partial derivatives of the multibody equations of motion, shared by IDA's Newton
// matrix (ggl_dae_form.cpp) and the index-3 HHT integrator (index3_form.cpp).
//
// Analytic where the kernel can differentiate -- the mass matrix (CRBA), dID/dq and
// dID/dv (inverse_dynamics_derivatives) -- and forward differences (step 1e-7) where
// it cannot: the force elements and joint elements (their dependence on q, v, z) and
// the q-dependence of J^T lambda. Derivatives in q are along the tangent directions of
// integrate_configuration.
#include <vector>

#include "kernel/system/multibody_system.hpp"
#include "kernel/system/second_order_system.hpp"

namespace heavesim {

/// The GGL form's extra terms: d(J^T mu)/d(tangent q) and d(J v)/d(tangent q).
struct GglDerivatives {
  VectorX mu;
  MatrixX jt_mu_q, jv_q;
};

class DynamicsDifferentiator {
 public:
  explicit DynamicsDifferentiator(MultibodySystem& system);

  /// Partial derivatives at (t, y, a) with multipliers lambda on constraint rows `rows`;
  /// leaves the system's stages and forces at (t, y) and J of those rows in rows_jacobian().
  void differentiate(double t, const VectorX& y, const VectorX& a, const std::vector<int>& rows, const VectorX& lambda,
                     DynamicsDerivatives& out, GglDerivatives* ggl);
  /// J (the rows given to the last differentiate()) at its (t, y).
  const MatrixX& rows_jacobian() const { return rows_jacobian_; }

 private:
  /// One difference column in q or v, the perturbed stages being in scratch_data_ at (q, v):
  /// every element's load (subtracted from force_column: the residual holds -Q) and rates
  /// (into rate_column, empty without element states), against applied_base_ and rates_base_.
  void column_of_every_element(double t, const VectorX& q, const VectorX& v, const VectorX& y, double h,
                               Eigen::Ref<VectorX> force_column, Eigen::Ref<VectorX> rate_column);
  /// Q = tau + sum_i J_i^T f_i of `forces`, mapped with the subspaces in `base`.
  void generalized_force(const Data& base, const AppliedForces& forces, VectorX& out);

  MultibodySystem& system_;
  Data scratch_data_;  // the perturbed stages of each finite-difference column
  AppliedForces scratch_forces_;
  MatrixX rows_jacobian_, jacobian_change_;  // J of the rows in use; dJ/d(tangent k)
  AlignedVector<Force> subtree_forces_;
  VectorX applied_base_, applied_perturbed_, element_base_, rates_base_, rates_perturbed_, direction_;
  VectorX q_perturbed_, v_perturbed_, y_perturbed_;
};

}  // namespace heavesim
