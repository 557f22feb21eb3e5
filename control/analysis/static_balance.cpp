#include "control/analysis/static_balance.hpp"

#include <cmath>

#include <fmt/format.h>

#include "kernel/algorithms/inverse_dynamics.hpp"
#include "kernel/algorithms/joint_forces.hpp"
#include "kernel/parameter_error.hpp"

namespace heavesim {

VectorX generalized_force(const Model& model, const Data& data, const AppliedForces& forces) {
  VectorX Q = forces.joint_force;
  for (int i = 1; i < model.num_links(); ++i) {
    const Joint& joint = model.joints[i];
    Force subtree = Force::Zero();
    for (int j = i; j < model.links[i].subtree_end; ++j) subtree += forces.external_force_world[j];
    for (int c = 0; c < joint.nv; ++c) Q[joint.v_index + c] += dot(data.motion_subspace_world.col(joint.v_index + c), subtree);
  }
  return Q;
}

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
  return unit.dot(needed) / unit.squaredNorm();
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
