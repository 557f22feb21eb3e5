#pragma once
// The case's `contacts` resolved onto the model (names to link and joint indices, shape
// frames from body to link frames) and added to the system as its contact element;
// kernel rules on the values reported at the case keys, and an initial overlap refused.
#include "app/case/case_definition.hpp"
#include "kernel/system/multibody_system.hpp"

namespace heavesim {

/// Nothing when the case has no contacts. Throws InputError (exit code 2) at the key a
/// rule fails on, at the pair whose shapes overlap by more than the margin at the
/// initial configuration q0, or at the bound of a stop its joint starts beyond (the
/// position stage of system's Data must hold q0).
void build_contacts(const CaseDefinition& definition, MultibodySystem& system);

}  // namespace heavesim
