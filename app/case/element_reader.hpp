#pragma once
// Reads the kernel's own force elements in `forces:` (docs/case-format.md, "forces[i]"):
// spring_damper, point_force, ground_contact.
#include "app/case/case_definition.hpp"
#include "app/case/node_reader.hpp"

namespace heavesim {

/// Reads forces[i] of a kernel element type, whose name has been read (and checked
/// unique) already.
void read_kernel_force(const NodeReader& item, const std::string& type, const std::string& name,
                       CaseDefinition& definition);

}  // namespace heavesim
