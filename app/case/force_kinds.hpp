#pragma once
// The force kinds a case may declare under `forces:`, registered once: the `type` value
// (also the kind's section of the key table, app/case/case_schema.cpp) and the function
// that reads it. The `type` choice, its did-you-mean and the dispatch come from here.
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "app/case/case_definition.hpp"
#include "app/case/node_reader.hpp"

namespace heavesim {

struct ForceKind {
  std::string_view type;
  /// Reads forces[i] of this kind, whose name has been read (and checked unique).
  void (*read)(const NodeReader& item, const std::string& type, const std::string& name, CaseDefinition& definition);
};

/// Every registered kind, in the order the `type` choice lists them.
std::span<const ForceKind> force_kinds();
std::vector<std::string_view> force_kind_names();
/// The kind registered as `type` (throws std::out_of_range: a programming error).
const ForceKind& force_kind(std::string_view type);

}  // namespace heavesim
