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

/// Files one case may include in all (each include counts, repeats too): with the bound
/// on values (case_node.hpp), what stops includes that fan out from loading a file
/// millions of times.
inline constexpr std::size_t max_included_files = 1000;

/// Loads `path`, resolving its `include:` entries (paths relative to the including
/// file, recursively; a cycle is reported at the include entry that closes it); the
/// result has no `include` key.
CaseNode load_case_tree(const std::string& path);

/// overlay merged onto base (see the merge rule above).
void merge_into(CaseNode& base, const CaseNode& overlay);

/// Applies one override "a.b[2].c=value" or "joints[elbow].axis=[0,1,0]":
/// [i] selects a sequence item by index, [name] by its `name`; the value is YAML.
/// A malformed path (an empty key, an unclosed '[', text after ']'), an index out of
/// range or a bad value is an InputError naming the --set.
void apply_override(CaseNode& root, const std::string& assignment);

}  // namespace heavesim
