#pragma once
// Composition of a case from several sources: `include:` files, then the case file
// itself, then command-line `--set key=value` overrides.
//
// Merge rule (overlay onto base): maps merge key by key, recursively; sequences whose
// items are all maps with a `name` merge item by item by name (unknown names are
// appended); anything else is replaced by the overlay.
#include <string>
#include <vector>

#include "app/case/case_node.hpp"

namespace heavesim {

/// Loads `path`, resolving its `include:` entries (paths relative to the including
/// file, recursively, cycles rejected); the result has no `include` key.
CaseNode load_case_tree(const std::string& path);

/// overlay merged onto base (see the merge rule above).
void merge_into(CaseNode& base, const CaseNode& overlay);

/// Applies one override "a.b[2].c=value" or "joints[elbow].axis=[0,1,0]":
/// [i] selects a sequence item by index, [name] by its `name`; the value is YAML.
void apply_override(CaseNode& root, const std::string& assignment);

}  // namespace heavesim
