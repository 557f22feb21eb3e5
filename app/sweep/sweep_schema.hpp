#pragma once
// The keys of a sweep file (docs/sweeps.md documents them in tables marked
// `<!-- sweep-keys: <section> -->`; tests/app/test_sweep_file.cpp checks both agree).
#include <span>
#include <string_view>
#include <vector>

#include "app/case/case_schema.hpp"

namespace heavesim {

/// The sections of a sweep file: "sweep", "variables[i]", "range", "sample", "scatter".
std::span<const SchemaSection> sweep_schema();
/// The key names of one section of sweep_schema().
std::vector<std::string_view> sweep_keys(std::string_view section);

}  // namespace heavesim
