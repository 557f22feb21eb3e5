#include "app/sweep/sweep_schema.hpp"

#include <stdexcept>
#include <string>

namespace heavesim {
namespace {

constexpr KeySpec sweep_root_keys[] = {
    {"base", "text or list", "–", "required", "the case every run starts from, or a list of cases each run in turn (paths relative to the sweep file)"},
    {"set", "map", "–", "none", "`key.path: value` overrides applied to every run (as `--set`)"},
    {"variables", "list", "–", "none (required without `scatter`)", "the variables, each a `--set` key path"},
    {"sampling", "choice", "–", "grid", "`grid` (every combination), `zip` (i-th values together), `latin_hypercube`"},
    {"samples", "number", "–", "required for `latin_hypercube`", "Latin hypercube sample size N (1 … 1e6)"},
    {"seed", "number", "–", "1", "seed of the Latin hypercube's generator (mt19937_64)"},
    {"scatter", "map", "–", "none", "a scatter diagram of sea states, run for every variant"},
    {"statistics", "list", "–", "none", "channel paths whose response statistics go into the index"},
    {"duration", "number", "s", "10800", "D of the most probable maxima of `statistics` (3 h)"},
};

constexpr KeySpec variable_keys[] = {
    {"path", "text", "–", "required", "the case key path the variable sets, as for `--set`"},
    {"values", "list", "as the key", "one of values, range, sample", "the values, in order"},
    {"range", "map", "as the key", "one of values, range, sample", "evenly spaced values `{from, to, step}` or `{from, to, count}`"},
    {"sample", "map", "as the key", "one of values, range, sample", "`{from, to}`: the interval a Latin hypercube samples"},
};

constexpr KeySpec range_keys[] = {
    {"from", "number", "as the key", "required", "first value"},
    {"to", "number", "as the key", "required", "last value (≥ from; with `step`: the last value not beyond it)"},
    {"step", "number", "as the key", "one of step, count", "spacing (> 0)"},
    {"count", "number", "–", "one of step, count", "number of values (≥ 2, or 1 when from = to)"},
};

constexpr KeySpec sample_keys[] = {
    {"from", "number", "as the key", "required", "lower end of the interval"},
    {"to", "number", "as the key", "required", "upper end (> from)"},
};

constexpr KeySpec scatter_keys[] = {
    {"file", "text", "–", "required", "the scatter-diagram table (path relative to the sweep file)"},
    {"hs", "text", "m", "required", "the case key path that receives Hs"},
    {"tp", "text", "s", "required", "the case key path that receives Tp"},
};

constexpr SchemaSection sections[] = {
    {"sweep", sweep_root_keys}, {"variables[i]", variable_keys}, {"range", range_keys},
    {"sample", sample_keys},    {"scatter", scatter_keys},
};

}  // namespace

std::span<const SchemaSection> sweep_schema() { return sections; }

std::vector<std::string_view> sweep_keys(std::string_view section) {
  for (const SchemaSection& s : sections)
    if (s.name == section) {
      std::vector<std::string_view> keys;
      for (const KeySpec& spec : s.keys) keys.push_back(spec.key);
      return keys;
    }
  throw std::out_of_range("no sweep section '" + std::string(section) + "'");
}

}  // namespace heavesim
