#pragma once
// Reads the sea (`environment.water_*`, `waves:`) and the hydrodynamic entries of
// `forces:` (docs/case-format.md, "Waves" and "Hydrodynamic forces").
#include "app/case/case_definition.hpp"
#include "app/case/node_reader.hpp"

namespace heavesim {

/// Reads `waves:` into definition.waves; checks every value that can be checked alone.
void read_waves(const NodeReader& reader, CaseDefinition& definition);

/// Reads forces[i] of a hydro type, whose name has been read (and checked unique).
/// File paths are resolved against the directory of the file the key is written in.
void read_hydro_force(const NodeReader& item, const std::string& type, const std::string& name,
                      CaseDefinition& definition);

}  // namespace heavesim
