#include "hydro/elements/radiation_memory.hpp"

namespace heavesim::hydro {

RadiationMemory::RadiationMemory(std::string name, int link, std::vector<ModePairStateSpace> systems)
    : name_(std::move(name)), link_(link), systems_(std::move(systems)) {
  for (const ModePairStateSpace& s : systems_) {
    offsets_.push_back(state_size_);
    state_size_ += static_cast<int>(s.A.rows());
  }
}

Vector6 RadiationMemory::load(Eigen::Ref<const VectorX> z) const {
  Vector6 f = Vector6::Zero();
  for (size_t k = 0; k < systems_.size(); ++k) {
    const ModePairStateSpace& s = systems_[k];
    f[s.force_mode] -= s.C.dot(z.segment(offsets_[k], s.A.rows()));
  }
  return f;
}

void RadiationMemory::apply(double, const Model& model, const Data& data, Eigen::Ref<const VectorX> z,
                            AppliedForces& forces) const {
  const Transform X = data.X_world_link[link_] * model.links[link_].X_link_body;
  add_load(forces, link_, X.translation(), load(z));
}

void RadiationMemory::state_derivative(double, const Model& model, const Data& data, Eigen::Ref<const VectorX> z,
                                       Eigen::Ref<VectorX> zdot) const {
  const Vector6 v = body_motion(model, data, link_).velocity;
  for (size_t k = 0; k < systems_.size(); ++k) {
    const ModePairStateSpace& s = systems_[k];
    const Eigen::Index n = s.A.rows();
    zdot.segment(offsets_[k], n).noalias() = s.A * z.segment(offsets_[k], n);
    zdot.segment(offsets_[k], n) += s.B * v[s.velocity_mode];
  }
}

}  // namespace heavesim::hydro
