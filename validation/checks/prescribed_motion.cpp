#include "validation/checks/prescribed_motion.hpp"

#include "kernel/algorithms/kinematics.hpp"

namespace heavesim::validation {

PrescribedMotionSystem::PrescribedMotionSystem(std::shared_ptr<const Model> model, MotionLaw motion)
    : model_(std::move(model)),
      motion_(std::move(motion)),
      data_(*model_),
      forces_(*model_),
      q_(model_->neutral_configuration()),
      v_(VectorX::Zero(model_->nv)) {}

void PrescribedMotionSystem::add_force_element(std::unique_ptr<ForceElement> element) {
  offsets_.push_back(size_);
  size_ += element->state_size();
  elements_.push_back(std::move(element));
}

VectorX PrescribedMotionSystem::initial_state() const {
  VectorX y = VectorX::Zero(size());
  for (std::size_t e = 0; e < elements_.size(); ++e)
    elements_[e]->initial_state(y.segment(offsets_[e], elements_[e]->state_size()));
  return y;
}

void PrescribedMotionSystem::place(double t) {
  motion_(t, q_, v_);
  update_positions(*model_, data_, q_);
  update_velocities(*model_, data_, q_, v_);
}

void PrescribedMotionSystem::derivative(double t, const VectorX& y, VectorX& ydot) {
  place(t);
  forces_.clear();
  for (std::size_t e = 0; e < elements_.size(); ++e) {
    const int n = elements_[e]->state_size();
    elements_[e]->apply(t, *model_, data_, y.segment(offsets_[e], n), forces_);
    if (n > 0) elements_[e]->state_derivative(t, *model_, data_, y.segment(offsets_[e], n), ydot.segment(offsets_[e], n));
  }
  // Power of the applied loads: generalized forces on v plus spatial forces on the
  // links' spatial velocities (both world, about the origin).
  double power = forces_.joint_force.dot(v_);
  for (int i = 1; i < model_->num_links(); ++i) power += dot(data_.velocity_world[i], forces_.external_force_world[i]);
  ydot[size_] = power;
}

}  // namespace heavesim::validation
