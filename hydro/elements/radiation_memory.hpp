#pragma once
// Radiation memory of one body as a force element: the state-space realisation of the
// retardation kernel (state_space.hpp), one SISO system per coupled mode pair,
//   z_ij' = A_ij z_ij + B_ij v_j,   F_i = -sum_j C_ij z_ij,
// v the body reference point's velocity in WAMIT order (world axes; the BEM reference
// point is taken at the body frame origin). A(inf) belongs in the body's added
// inertia (added_mass.hpp), not here. A realisation in modal form (A zero off its three
// central diagonals, to_modal_form) is integrated by a banded product. No allocation in
// apply()/state_derivative().
#include "hydro/elements/body_motion.hpp"
#include "hydro/radiation/state_space.hpp"

namespace heavesim::hydro {

class RadiationMemory : public ForceElement {
 public:
  RadiationMemory(std::string name, int link, std::vector<ModePairStateSpace> systems);
  const std::string& name() const override { return name_; }
  int state_size() const override { return state_size_; }
  void initial_state(Eigen::Ref<VectorX> z) const override { z.setZero(); }
  void apply(double t, const Model& model, const Data& data, Eigen::Ref<const VectorX> z,
             AppliedForces& forces) const override;
  void state_derivative(double t, const Model& model, const Data& data, Eigen::Ref<const VectorX> z,
                        Eigen::Ref<VectorX> zdot) const override;
  /// The load reads z at the body's reference point; dz/dt reads z and the body velocity.
  ElementDependencies dependencies() const override { return {false, true, true, true, false}; }
  /// The memory load -C z [WAMIT order] for state z.
  Vector6 load(Eigen::Ref<const VectorX> z) const;

 private:
  std::string name_;
  int link_;
  std::vector<ModePairStateSpace> systems_;
  std::vector<int> offsets_;
  // State by state over the whole state: the three central diagonals of A and B of the
  // systems in modal form (zero for a dense system's states), and C.
  std::vector<double> lower_, diagonal_, upper_, input_, output_;
  std::vector<int> dense_systems_;  // systems whose A has entries off its three central diagonals
  int state_size_ = 0;
};

}  // namespace heavesim::hydro
