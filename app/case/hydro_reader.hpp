#pragma once
// Reads the sea, `waves:` (docs/case-format.md, "Waves"); the hydrodynamic entries of
// `forces:` are read by their kinds (app/forces/).
#include "app/case/case_definition.hpp"
#include "app/case/node_reader.hpp"

namespace heavesim {

/// Reads `waves:` into definition.waves; checks every value that can be checked alone.
void read_waves(const NodeReader& reader, CaseDefinition& definition);

}  // namespace heavesim
