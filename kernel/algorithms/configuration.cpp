#include "kernel/algorithms/configuration.hpp"

namespace heavesim {

void configuration_derivative(const Model& model, const VectorX& q, const VectorX& v, Eigen::Ref<VectorX> qdot) {
  for (int i = 1; i < model.num_links(); ++i) {
    const Joint& joint = model.joints[i];
    std::visit([&](const auto& type) {
      type.configuration_derivative(q.data() + joint.q_index, v.data() + joint.v_index, qdot.data() + joint.q_index);
    }, joint.type);
  }
}

void integrate_configuration(const Model& model, const VectorX& q, const VectorX& v, double dt, VectorX& q_out) {
  for (int i = 1; i < model.num_links(); ++i) {
    const Joint& joint = model.joints[i];
    std::visit([&](const auto& type) {
      type.integrate(q.data() + joint.q_index, v.data() + joint.v_index, dt, q_out.data() + joint.q_index);
    }, joint.type);
  }
}

void configuration_difference(const Model& model, const VectorX& q0, const VectorX& q1, VectorX& dv) {
  for (int i = 1; i < model.num_links(); ++i) {
    const Joint& joint = model.joints[i];
    std::visit([&](const auto& type) {
      type.difference(q0.data() + joint.q_index, q1.data() + joint.q_index, dv.data() + joint.v_index);
    }, joint.type);
  }
}

void normalize_configuration(const Model& model, VectorX& q) {
  for (int i = 1; i < model.num_links(); ++i) {
    const Joint& joint = model.joints[i];
    std::visit([&](const auto& type) { type.normalize(q.data() + joint.q_index); }, joint.type);
  }
}

}  // namespace heavesim
