#include "hydro/elements/radiation_memory.hpp"

#include <cstdlib>

namespace heavesim::hydro {

RadiationMemory::RadiationMemory(std::string name, int link, std::vector<ModePairStateSpace> systems)
    : name_(std::move(name)), link_(link), systems_(std::move(systems)) {
  for (std::size_t k = 0; k < systems_.size(); ++k) {
    const ModePairStateSpace& s = systems_[k];
    const Eigen::Index n = s.A.rows();
    offsets_.push_back(state_size_);
    state_size_ += static_cast<int>(n);
    // Exact zeros off the three central diagonals: a realisation in modal form
    // (to_modal_form), whose product is the banded one of state_derivative.
    bool banded = true;
    for (Eigen::Index r = 0; r < n; ++r)
      for (Eigen::Index c = 0; c < n; ++c)
        if (std::abs(r - c) > 1 && s.A(r, c) != 0.0) banded = false;
    if (!banded) dense_systems_.push_back(static_cast<int>(k));
    for (Eigen::Index r = 0; r < n; ++r) {
      lower_.push_back(banded && r > 0 ? s.A(r, r - 1) : 0.0);
      diagonal_.push_back(banded ? s.A(r, r) : 0.0);
      upper_.push_back(banded && r + 1 < n ? s.A(r, r + 1) : 0.0);
      input_.push_back(banded ? s.B[r] : 0.0);
      output_.push_back(s.C[r]);
    }
  }
}

Vector6 RadiationMemory::load(Eigen::Ref<const VectorX> z) const {
  Vector6 f = Vector6::Zero();
  for (std::size_t k = 0; k < systems_.size(); ++k) {
    const Eigen::Index n = systems_[k].A.rows();
    f[systems_[k].force_mode] -= Eigen::Map<const Eigen::VectorXd>(output_.data() + offsets_[k], n).dot(z.segment(offsets_[k], n));
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
  // A system in modal form by its band: z_r' = A(r, r-1) z_{r-1} + A(r, r) z_r +
  // A(r, r+1) z_{r+1} + B_r v_j, 3 n multiply-adds instead of the dense product's n^2 (the
  // dense products were 23 % of the free semi's 3-hour run at order 12). A dense system's
  // states, which the band leaves zero, are then written by its own product. Nothing the
  // rates are written into is read (zdot is not z): restrict lets the compiler keep the
  // loop's loads together.
  const double* __restrict state = z.data();
  double* __restrict rate = zdot.data();
  const double* __restrict diagonal = diagonal_.data();
  const double* __restrict lower = lower_.data();
  const double* __restrict upper = upper_.data();
  const double* __restrict input_of_state = input_.data();
  for (std::size_t k = 0; k < systems_.size(); ++k) {
    // Within the system: its first state has no lower neighbour, its last no upper one.
    const double input = v[systems_[k].velocity_mode];
    const int first = offsets_[k], last = first + static_cast<int>(systems_[k].A.rows()) - 1;
    if (last < first) continue;
    if (first == last) {
      rate[first] = diagonal[first] * state[first] + input_of_state[first] * input;
      continue;
    }
    rate[first] = diagonal[first] * state[first] + input_of_state[first] * input + upper[first] * state[first + 1];
    for (int r = first + 1; r < last; ++r)
      rate[r] = diagonal[r] * state[r] + input_of_state[r] * input + lower[r] * state[r - 1] + upper[r] * state[r + 1];
    rate[last] = diagonal[last] * state[last] + input_of_state[last] * input + lower[last] * state[last - 1];
  }
  for (int k : dense_systems_) {
    const ModePairStateSpace& s = systems_[k];
    const Eigen::Index n = s.A.rows();
    zdot.segment(offsets_[k], n).noalias() = s.A * z.segment(offsets_[k], n);
    zdot.segment(offsets_[k], n) += s.B * v[s.velocity_mode];
  }
}

}  // namespace heavesim::hydro
