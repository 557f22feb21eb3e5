#include "kernel/algorithms/joint_forces.hpp"

namespace heavesim {
namespace {

/// Displacement of the joint from its spring's rest configuration (size nv).
JointVector spring_displacement(const Joint& joint, const VectorX& q) {
  JointVector displacement(joint.nv);
  std::visit([&](const auto& type) { type.difference(joint.spring->rest.data(), q.data() + joint.q_index,
                                                     displacement.data()); },
             joint.type);
  return displacement;
}

/// Penetration beyond the limits: negative below lower, positive above upper, else 0.
double limit_penetration(const JointLimits& limits, double position) {
  if (position < limits.lower) return position - limits.lower;
  if (position > limits.upper) return position - limits.upper;
  return 0.0;
}

}  // namespace

void add_joint_element_forces(const Model& model, const VectorX& q, const VectorX& v, VectorX& tau) {
  for (int i = 1; i < model.num_links(); ++i) {
    const Joint& joint = model.joints[i];
    if (joint.spring) {
      const JointVector displacement = spring_displacement(joint, q);
      tau.segment(joint.v_index, joint.nv) -=
          joint.spring->stiffness.cwiseProduct(displacement) +
          joint.spring->damping.cwiseProduct(v.segment(joint.v_index, joint.nv));
    }
    if (joint.limits) {
      const double penetration = limit_penetration(*joint.limits, q[joint.q_index]);
      if (penetration != 0.0)
        tau[joint.v_index] -= joint.limits->stiffness * penetration + joint.limits->damping * v[joint.v_index];
    }
  }
}

double joint_elastic_energy(const Model& model, const VectorX& q) {
  double energy = 0.0;
  for (int i = 1; i < model.num_links(); ++i) {
    const Joint& joint = model.joints[i];
    if (joint.spring) {
      const JointVector displacement = spring_displacement(joint, q);
      energy += 0.5 * displacement.dot(joint.spring->stiffness.cwiseProduct(displacement));
    }
    if (joint.limits) {
      const double penetration = limit_penetration(*joint.limits, q[joint.q_index]);
      energy += 0.5 * joint.limits->stiffness * penetration * penetration;
    }
  }
  return energy;
}

}  // namespace heavesim
