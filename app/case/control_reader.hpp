#pragma once
// Reads the compensator entries of `forces:` (docs/case-format.md, "Compensators").
#include "app/case/case_definition.hpp"
#include "app/case/node_reader.hpp"

namespace heavesim {

/// Reads forces[i] of type pneumatic_compensator or active_compensator, whose name has
/// been read (and checked unique) already; checks every parameter that can be checked
/// without the model (InputError naming the key).
void read_compensator(const NodeReader& item, const std::string& type, const std::string& name,
                      CaseDefinition& definition);

}  // namespace heavesim
