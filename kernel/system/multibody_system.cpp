#include "kernel/system/multibody_system.hpp"

#include <cmath>

#include "kernel/algorithms/configuration.hpp"
#include "kernel/algorithms/joint_forces.hpp"
#include "kernel/algorithms/joint_reactions.hpp"

namespace heavesim {

MultibodySystem::MultibodySystem(std::shared_ptr<const Model> model, ForwardDynamicsMethod method)
    : model_(std::move(model)),
      method_(method),
      data_(*model_),
      forces_(*model_),
      size_(model_->nq + model_->nv),
      q_(VectorX::Zero(model_->nq)),
      v_(VectorX::Zero(model_->nv)) {}

void MultibodySystem::add_force_element(std::unique_ptr<ForceElement> element) {
  state_offsets_.push_back(size_);
  size_ += element->state_size();
  elements_.push_back(std::move(element));
}

VectorX MultibodySystem::initial_state(const VectorX& q0, const VectorX& v0) const {
  VectorX y(size_);
  y << q0, v0, VectorX::Zero(size_ - model_->nq - model_->nv);
  for (std::size_t e = 0; e < elements_.size(); ++e)
    elements_[e]->initial_state(y.segment(state_offsets_[e], elements_[e]->state_size()));
  return y;
}

void MultibodySystem::compute_accelerations(double t, const VectorX& y) {
  const Model& model = *model_;
  q_ = y.head(model.nq);
  v_ = y.segment(model.nq, model.nv);
  update_positions(model, data_, q_);
  update_velocities(model, data_, q_, v_);
  forces_.clear();
  add_joint_element_forces(model, q_, v_, forces_.joint_force);
  for (std::size_t e = 0; e < elements_.size(); ++e)
    elements_[e]->apply(t, model, data_, y.segment(state_offsets_[e], elements_[e]->state_size()), forces_);
  forward_dynamics(model, data_, forces_.joint_force, forces_.external_force_world, method_);
  if (!data_.qdd.allFinite()) report_non_finite(t);
}

void MultibodySystem::derivative(double t, const VectorX& y, VectorX& ydot) {
  const Model& model = *model_;
  compute_accelerations(t, y);
  configuration_derivative(model, q_, v_, ydot.head(model.nq));
  ydot.segment(model.nq, model.nv) = data_.qdd;
  for (std::size_t e = 0; e < elements_.size(); ++e) {
    const int n = elements_[e]->state_size();
    if (n == 0) continue;
    elements_[e]->state_derivative(t, model, data_, y.segment(state_offsets_[e], n),
                                   ydot.segment(state_offsets_[e], n));
  }
}

void MultibodySystem::project(double, VectorX& y) {
  q_ = y.head(model_->nq);
  normalize_configuration(*model_, q_);
  y.head(model_->nq) = q_;
}

void MultibodySystem::evaluate(double t, const VectorX& y, bool compute_reactions) {
  compute_accelerations(t, y);
  if (compute_reactions) compute_joint_wrenches(*model_, data_, forces_.external_force_world);
}

void MultibodySystem::report_non_finite(double t) const {
  const Model& model = *model_;
  for (int i = 1; i < model.num_links(); ++i) {
    const Joint& joint = model.joints[i];
    if (joint.nv > 0 && !data_.qdd.segment(joint.v_index, joint.nv).allFinite())
      throw NumericalError(t,
                           "acceleration of joint '" + joint.name + "' (body '" + model.links[i].name +
                               "') is not finite",
                           "check that body's mass and inertia and the forces acting on it; a stiff or "
                           "unstable force element can also produce this");
  }
  throw NumericalError(t, "accelerations are not finite", "check masses, inertias and applied forces");
}

}  // namespace heavesim
