#pragma once
// The case schema as data: for each section of a case, its keys with type, unit,
// default and one line of meaning. The readers accept exactly these keys (and compute
// their did-you-mean from them); docs/case-format.md documents them in tables marked
// `<!-- keys: <section> -->`, and tests/app/test_case_schema.cpp fails when a key, unit
// or default there disagrees with this table, in either direction.
#include <span>
#include <string_view>
#include <vector>

namespace heavesim {

struct KeySpec {
  std::string_view key;
  std::string_view type;           // number, text, choice, vector, list, map, boolean, expression
  std::string_view unit;           // as documented; "–" for none
  std::string_view default_value;  // as documented; "required" when the key must be given
  std::string_view meaning;        // one line
  /// The forms of the section the key belongs to, space-separated (e.g. "regular
  /// irregular" for waves, "hydraulic" for an actuator); empty: every form.
  std::string_view forms = {};
};

struct SchemaSection {
  std::string_view name;  // the section's id in docs/case-format.md, e.g. "solver", "joints[i]"
  std::span<const KeySpec> keys;
};

/// Every section the schema describes: the case's own in document order, then each force
/// kind's (its keys and nested sections, held by the kind in app/forces/), in registry
/// order.
std::span<const SchemaSection> case_schema();

/// The keys of one section (throws std::out_of_range for an unknown section: a
/// programming error).
std::span<const KeySpec> schema_keys(std::string_view section);

/// The key names of `section` that belong to `form` (every key when `form` is empty),
/// in table order: what a reader of that form accepts.
std::vector<std::string_view> accepted_keys(std::string_view section, std::string_view form = {});

}  // namespace heavesim
