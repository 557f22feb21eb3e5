#pragma once
// The registry of the force kinds a case may declare under `forces:`, derived from the
// one list in app/forces/force_kinds.hpp: the `type` value (also the kind's section of
// the key table), its keys and nested sections, and the function that reads it. The `type` choice, its
// did-you-mean, the schema's kind sections and the dispatch come from here.
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "app/case/case_schema.hpp"
#include "app/case/node_reader.hpp"

namespace heavesim {

struct CaseDefinition;

struct ForceKind {
  std::string_view type;
  /// The kind's keys (its section of the key table).
  std::span<const KeySpec> (*keys)();
  /// The sections nested in it (their own tables in docs/case-format.md).
  std::span<const SchemaSection> (*sub_sections)();
  /// Reads forces[i] of this kind, whose name has been read (and checked unique).
  void (*read)(const NodeReader& item, const std::string& type, const std::string& name, CaseDefinition& definition);
};

/// Every registered kind, in the order the `type` choice lists them.
std::span<const ForceKind> force_kinds();
std::vector<std::string_view> force_kind_names();
/// The kind registered as `type` (throws std::out_of_range: a programming error).
const ForceKind& force_kind(std::string_view type);

}  // namespace heavesim
