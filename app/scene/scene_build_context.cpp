#include "app/scene/scene_build_context.hpp"

#include "kernel/algorithms/kinematics.hpp"
#include "kernel/algorithms/mass_matrix.hpp"

namespace heavesim {

SceneBuildContext::InitialState& SceneBuildContext::initial_state() {
  if (!initial_state_) {
    InitialState& state = initial_state_.emplace(model);
    update_positions(model, state.data, initial_configuration());
    update_velocities(model, state.data, initial_configuration(), VectorX::Zero(model.nv));
    state.mass_matrix = &mass_matrix(model, state.data);
  }
  return *initial_state_;
}

}  // namespace heavesim
