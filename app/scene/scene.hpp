#pragma once
// The runnable scene built from a case: only what the case declares.
#include <memory>

#include "app/case/case_definition.hpp"
#include "kernel/system/multibody_system.hpp"

namespace heavesim {

struct Scene {
  std::shared_ptr<const Model> model;
  std::unique_ptr<MultibodySystem> system;
  VectorX initial_state;  // y0 = [q0; v0; element states]
};

/// Builds the model, the force elements and the initial state; throws InputError.
Scene build_scene(const CaseDefinition& definition);

}  // namespace heavesim
