#pragma once
// Builds the case's compensators (control/) on the model.
#include "app/case/case_definition.hpp"
#include "app/scene/element_handles.hpp"
#include "kernel/system/multibody_system.hpp"

namespace heavesim {

/// Adds every compensator of the case to `system`, after its other force elements,
/// for the (assembled) initial state q0 at time t0: resolves strokes and body points,
/// sets gas pressures from static balance where asked, takes the active compensators'
/// initial references, and checks each controller's closed-loop stability
/// (control/analysis/stroke_loop.hpp). Records each one in `summarised`. Throws
/// InputError naming the key.
void add_compensators(const CaseDefinition& definition, const Model& model, MultibodySystem& system, double t0,
                      const VectorX& q0, SummarisedElements& summarised);

}  // namespace heavesim
