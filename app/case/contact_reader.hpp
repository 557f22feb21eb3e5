#pragma once
// Reads the `contacts` section (docs/case-format.md, "contacts", "contact_geometry",
// "contact_pair", "joint_stop").
#include "app/case/case_definition.hpp"
#include "app/case/node_reader.hpp"

namespace heavesim {

/// Fills definition.contacts; bodies and joints are read before (names are checked
/// here, with a did-you-mean).
void read_contacts(const NodeReader& section, CaseDefinition& definition);

}  // namespace heavesim
