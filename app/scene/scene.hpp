#pragma once
// The runnable scene built from a case: only what the case declares.
#include <memory>
#include <optional>

#include "app/case/case_definition.hpp"
#include "app/scene/element_handles.hpp"
#include "kernel/algorithms/projection.hpp"
#include "kernel/system/multibody_system.hpp"

namespace heavesim {

/// How the user's approximate initial state was brought onto the constraints.
struct Assembly {
  int newton_iterations = 0;
  double largest_position_change = 0.0;  // max |q0 - q_user| over coordinates [m or rad]
  double largest_speed_change = 0.0;     // max |v0 - v_user| [m/s or rad/s]
  double position_residual = 0.0;        // max |Phi| after assembly
  ConstraintRank rank;                   // at the assembled configuration
};

struct Scene {
  std::shared_ptr<const Model> model;
  std::unique_ptr<MultibodySystem> system;
  VectorX initial_state;  // y0 = [q0; v0; element states], assembled when there are loops
  Assembly assembly;
  SummarisedElements summarised;  // the elements the run summary reads
  /// `initial: static`: the static equilibrium the run starts from (initial_state is its
  /// state; kernel/analysis/static_equilibrium.hpp).
  std::optional<EquilibriumResult> equilibrium;
};

/// Builds the model, the force elements and the initial state; assembles closed
/// loops from the user's approximate state; with `initial: static`, solves the static
/// equilibrium from there. Throws InputError (NumericalError: no equilibrium).
Scene build_scene(const CaseDefinition& definition);

/// "loop joint 'a': rotation about x, ..." for the redundant rows, or "" if none.
std::string describe_redundant_rows(const Model& model, const ConstraintRank& rank);

}  // namespace heavesim
