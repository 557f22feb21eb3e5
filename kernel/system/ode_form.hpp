#pragma once
// A MultibodySystem as an OdeSystem, for the explicit methods (RK4, ARKODE ERK):
// y = [q; v; z], dy/dt from MultibodySystem::state_derivative; after each step
// project() renormalizes quaternions and moves (q, v) back onto Phi = 0, J v = nu.
//
// Redundant rows (a planar loop closed by a 3-D revolute joint; Bricard's mechanism,
// where Grubler counts 0 degrees of freedom and there is 1) are set aside in the KKT
// solve: on the constraint manifold they hold by themselves, but at a stage value a
// tolerance away from it J regains full rank with a singular value of the order of the
// drift, and the solve would either invert it (huge multipliers) or find J qdd = gamma
// inconsistent (a false "singular configuration"). After every step, at the projected
// state, a column-pivoted QR of J^T picks the rank-many best-conditioned rows (the rank
// found at the first projection), as a coordinate-partitioning method picks its
// independent coordinates (Wehage & Haug 1982).
#include <Eigen/QR>

#include "kernel/system/fastest_mode.hpp"
#include "kernel/system/multibody_system.hpp"
#include "kernel/system/ode_system.hpp"

namespace heavesim {

class OdeForm final : public OdeSystem {
 public:
  explicit OdeForm(MultibodySystem& system);

  int size() const override { return system_.size(); }
  void derivative(double t, const VectorX& y, VectorX& ydot) override { system_.state_derivative(t, y, ydot); }
  void project(double t, VectorX& y) override;
  std::string describe_component(int index) const override { return system_.describe_state_component(index); }
  StateDiagnosis diagnose_state(double t, const VectorX& y) override { return system_.diagnose_state(t, y); }
  FastestMode fastest_mode(double t, const VectorX& y) override { return find_fastest_mode(system_, t, y); }

 private:
  /// Marks the rows the next steps' KKT solves use (Data::constraint_row_used).
  void choose_constraint_rows();

  MultibodySystem& system_;
  VectorX q_, v_;  // the projected configuration and speeds
  int constraint_rank_ = -1;  // rank of J on the manifold, found at the first projection; -1 before
  Eigen::ColPivHouseholderQR<MatrixX> row_selection_;  // of J^T, sized once
};

}  // namespace heavesim
