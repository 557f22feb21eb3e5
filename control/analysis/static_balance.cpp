#include "control/analysis/static_balance.hpp"

#include <cmath>

#include <Eigen/QR>
#include <fmt/format.h>

#include "kernel/algorithms/constraint_equations.hpp"
#include "kernel/algorithms/generalized_force.hpp"
#include "kernel/algorithms/inverse_dynamics.hpp"
#include "kernel/algorithms/joint_forces.hpp"
#include "kernel/parameter_error.hpp"

namespace heavesim {

namespace {

/// Q (nv) of `forces` at the position stage held in `data` (the kernel's O(n) projection;
/// set-up code, so its workspace is allocated here).
VectorX generalized_force(const Model& model, const Data& data, const AppliedForces& forces) {
  AlignedVector<Force> subtree_forces(model.num_links(), Force::Zero());
  VectorX Q(model.nv);
  generalized_applied_force(model, data, forces.external_force_world, forces.joint_force, subtree_forces, Q);
  return Q;
}

}  // namespace

VectorX unit_stroke_generalized_force(const StrokeAxis& axis, const Model& model, const Data& data) {
  AppliedForces unit_force(model);
  apply_stroke_force(axis, model, data, 1.0, unit_force);
  return generalized_force(model, data, unit_force);
}

double static_stroke_load(const Model& model, Data& data, const MultibodySystem& system, double t0,
                          const VectorX& q0, const VectorX& unit) {
  const VectorX zero = VectorX::Zero(model.nv);
  VectorX needed = rnea(model, data, q0, zero, zero);  // = -(generalized gravity) at rest
  AppliedForces others(model);
  add_joint_element_forces(model, q0, zero, others.joint_force);
  for (const auto& element : system.force_elements()) {
    VectorX z(element->state_size());
    element->initial_state(z);
    element->apply(t0, model, data, z, others);
  }
  needed -= generalized_force(model, data, others);
  if (model.num_constraint_rows == 0) return unit.dot(needed) / unit.squaredNorm();

  // With loops and drivers the constraints carry part of the load: needed = unit F + J^T lambda.
  // The least-squares (F, lambda) of minimum norm (complete orthogonal decomposition, so
  // redundant rows are allowed); set-up code, so the matrices are allocated here.
  MatrixX jacobian(model.num_constraint_rows, model.nv);
  constraint_jacobian(model, data, t0, jacobian);
  MatrixX loads(model.nv, 1 + model.num_constraint_rows);
  loads << unit, jacobian.transpose();
  const double threshold = 1e-10;
  Eigen::CompleteOrthogonalDecomposition<MatrixX> with_stroke(loads);
  with_stroke.setThreshold(threshold);
  Eigen::CompleteOrthogonalDecomposition<MatrixX> constraints_only(jacobian.transpose());
  constraints_only.setThreshold(threshold);
  // A stroke the constraints hold (unit in the range of J^T) has no load of its own.
  if (with_stroke.rank() == constraints_only.rank())
    throw ParameterError("gas_pressure",
                         "'balance' on a stroke that the loop constraints or drivers hold: the constraints take "
                         "whatever load acts along it, so no gas pressure follows from statics",
                         "an explicit gas_pressure, or a stroke the constraints leave free");
  return with_stroke.solve(needed)[0];
}

double apparent_stroke_mass(const MatrixX& mass_matrix, const VectorX& unit) {
  return unit.dot(mass_matrix * unit) / std::pow(unit.squaredNorm(), 2);
}

PneumaticParameters balanced_pneumatic(PneumaticParameters p, double load, double initial_stroke) {
  const double needed = p.atmospheric_pressure + load / p.piston_area;  // at the initial stroke, at rest
  const double volume_ratio = (p.gas_volume + p.piston_area * initial_stroke) / p.gas_volume;
  // p_init = p0 (V0/V)^n without the gas state; p0 (V0/V) at the initial temperature with it.
  p.gas_pressure = needed * std::pow(volume_ratio, p.has_gas_state() ? 1.0 : p.exponent_expansion);
  if (!(p.gas_pressure >= p.atmospheric_pressure))
    throw ParameterError("gas_pressure",
                         fmt::format("'balance', which needs {:g} Pa at mid-stroke, below atmospheric: the static "
                                     "load along the stroke is {:g} N (it pulls the stroke out)",
                                     p.gas_pressure, load),
                         "a load that compresses the gas (a weight carried along +axis), or an explicit "
                         "gas_pressure");
  return p;
}

}  // namespace heavesim
