// Reading a sweep file (docs/sweeps.md) with the case's own YAML tree and NodeReader, so
// that every error names the sweep file's line, column and key path.
#include <cmath>
#include <filesystem>

#include <fmt/format.h>

#include "app/case/expression.hpp"
#include "app/case/node_reader.hpp"
#include "app/sweep/sweep_definition.hpp"
#include "app/sweep/sweep_schema.hpp"

namespace heavesim {
namespace {

/// Values one variable (and the whole sweep) may have: a bound that keeps the plan in memory.
constexpr double max_runs = 1e6;

/// `path` as written, relative to the sweep file's directory unless absolute.
std::string beside(const std::string& sweep_file, const std::string& path) {
  const std::filesystem::path written(path);
  if (written.is_absolute()) return path;
  return (std::filesystem::path(sweep_file).parent_path() / written).lexically_normal().string();
}

/// A file the sweep names (base case, scatter diagram): refused at its key unless readable.
std::string existing_file(const NodeReader& key, const std::string& sweep_file) {
  const std::string path = beside(sweep_file, key.text());
  if (const std::string problem = unreadable_case_file(path); !problem.empty())
    key.fail(problem + " at " + path, readable_case_file_expectation());
  return path;
}

/// The YAML text of a value given in the sweep file, as `--set` takes it.
std::string value_text(const CaseNode& node) {
  if (node.is_scalar()) return node.scalar;
  std::string text = to_yaml_text(node);
  while (!text.empty() && text.back() == '\n') text.pop_back();
  return text;
}

std::vector<double> range_values(const NodeReader& range) {
  range.expect_keys(sweep_keys("range"));
  const double from = range["from"].number(), to = range["to"].number();
  if (to < from) range["to"].fail(fmt::format("{} < from = {}", to, from), "to >= from");
  const bool has_step = range.has("step"), has_count = range.has("count");
  if (has_step == has_count) range.fail(has_step ? "both step and count" : "neither step nor count", "one of step, count");
  std::vector<double> values;
  if (has_step) {
    const NodeReader step_key = range["step"];
    const double step = step_key.number();
    if (!(step > 0.0)) step_key.fail(fmt::format("{}", step), "a step > 0");
    // The last value is the last one not beyond `to` (with round-off's allowance).
    const double intervals = std::floor((to - from) / step * (1.0 + 1e-12) + 1e-9);
    if (intervals + 1.0 > max_runs) step_key.fail(fmt::format("{:g} values", intervals + 1.0), "at most 1e6 values");
    for (long k = 0; k <= static_cast<long>(intervals); ++k) values.push_back(from + static_cast<double>(k) * step);
  } else {
    const NodeReader count_key = range["count"];
    const long count = count_key.integer();
    if (count < 1 || count > static_cast<long>(max_runs) || (count == 1 && to != from))
      count_key.fail(fmt::format("{}", count), to == from ? "a count from 1 to 1e6" : "a count from 2 to 1e6");
    for (long k = 0; k < count; ++k)
      values.push_back(count == 1 ? from : from + (to - from) * static_cast<double>(k) / static_cast<double>(count - 1));
  }
  return values;
}

SweepVariable read_variable(const NodeReader& item) {
  item.expect_keys(sweep_keys("variables[i]"));
  SweepVariable variable;
  const NodeReader path = item["path"];
  variable.path = path.text();
  variable.location = path.location();
  if (variable.path.empty() || variable.path.find('=') != std::string::npos)
    path.fail("'" + variable.path + "'", "a case key path such as parameters.T or waves.amplitude");
  const int given = item.has("values") + item.has("range") + item.has("sample");
  if (given != 1)
    item.fail(given == 0 ? "none of values, range, sample" : "more than one of values, range, sample",
              "exactly one of values, range, sample");
  if (auto values = item.optional("values")) {
    if (!values->node().is_sequence() || values->node().items.empty())
      values->fail(values->node().is_sequence() ? "an empty list" : values->node().describe(),
                   "a list of at least one number");
    for (const NodeReader& value : values->items()) {
      variable.values.push_back(value.number());
      variable.value_locations.push_back(value.location());
    }
  } else if (auto range = item.optional("range")) {
    variable.values = range_values(*range);
    variable.value_locations.assign(variable.values.size(), range->location());
  } else {
    const NodeReader sample = item["sample"];
    sample.expect_keys(sweep_keys("sample"));
    const double from = sample["from"].number(), to = sample["to"].number();
    if (!(to > from)) sample["to"].fail(fmt::format("{} <= from = {}", to, from), "to > from");
    variable.sample = {from, to};
  }
  return variable;
}

}  // namespace

const char* sampling_name(Sampling sampling) {
  switch (sampling) {
    case Sampling::grid: return "grid";
    case Sampling::zip: return "zip";
    case Sampling::latin_hypercube: return "latin_hypercube";
  }
  return "";
}

SweepDefinition read_sweep_file(const std::string& path) {
  const CaseNode tree = load_yaml_file(path);
  ExpressionContext expressions;
  const NodeReader root(tree, "", expressions);
  root.expect_keys(sweep_keys("sweep"));

  SweepDefinition sweep;
  sweep.sweep_file = path;
  const NodeReader base = root["base"];
  if (base.node().is_sequence()) {
    if (base.node().items.empty()) base.fail("an empty list", "a case file or a list of case files");
    for (const NodeReader& item : base.items()) sweep.base_cases.push_back(existing_file(item, path));
  } else {
    sweep.base_cases.push_back(existing_file(base, path));
  }
  if (auto set = root.optional("set")) {
    if (!set->node().is_map()) set->fail("a map of key.path: value");
    for (const CaseNode::Entry& entry : set->node().entries)
      sweep.set.push_back({entry.key, value_text(entry.value), entry.value.location});
  }

  if (auto sampling = root.optional("sampling")) {
    const std::string name = sampling->choice({"grid", "zip", "latin_hypercube"});
    sweep.sampling = name == "grid" ? Sampling::grid : name == "zip" ? Sampling::zip : Sampling::latin_hypercube;
    sweep.sampling_location = sampling->location();
  }
  const bool latin = sweep.sampling == Sampling::latin_hypercube;
  if (auto samples = root.optional("samples")) {
    if (!latin) samples->fail("samples with sampling: " + std::string(sampling_name(sweep.sampling)),
                              "samples only with sampling: latin_hypercube");
    sweep.samples = samples->integer();
    if (sweep.samples < 1 || sweep.samples > static_cast<long>(max_runs))
      samples->fail(fmt::format("{}", sweep.samples), "a sample size from 1 to 1e6");
  } else if (latin) {
    root.optional("sampling")->fail("latin_hypercube without samples", "samples: N (the Latin hypercube's size)");
  }
  if (auto seed = root.optional("seed")) {
    const long value = seed->integer();
    if (value < 0) seed->fail(fmt::format("{}", value), "a seed >= 0");
    sweep.seed = static_cast<unsigned long long>(value);
  }

  if (auto variables = root.optional("variables")) {
    if (!variables->node().is_sequence() || variables->node().items.empty())
      variables->fail(variables->node().is_sequence() ? "an empty list" : variables->node().describe(),
                      "a list of variables, each {path, values | range | sample}");
    for (const NodeReader& item : variables->items()) {
      SweepVariable variable = read_variable(item);
      for (const SweepVariable& earlier : sweep.variables)
        if (earlier.path == variable.path) item["path"].fail("'" + variable.path + "' a second time", "each path once");
      if (latin != variable.sample.has_value())
        item.fail(latin ? "values or range with sampling: latin_hypercube" : "sample without sampling: latin_hypercube",
                  latin ? "sample: {from, to} for every variable of a Latin hypercube"
                        : "values or range (sample only with sampling: latin_hypercube)");
      sweep.variables.push_back(std::move(variable));
    }
  }

  if (auto scatter = root.optional("scatter")) {
    scatter->expect_keys(sweep_keys("scatter"));
    SweepScatter diagram;
    diagram.file = existing_file((*scatter)["file"], path);
    diagram.hs_path = (*scatter)["hs"].text();
    diagram.tp_path = (*scatter)["tp"].text();
    diagram.hs_location = (*scatter)["hs"].location();
    diagram.tp_location = (*scatter)["tp"].location();
    diagram.table = read_scatter_table(diagram.file);
    sweep.scatter = std::move(diagram);
  }
  if (sweep.variables.empty() && !sweep.scatter)
    root.fail("no variables and no scatter", "variables: [...] or scatter: {file, hs, tp} (or both)");

  // zip: the i-th values of every variable together, so the lists are of one length.
  if (sweep.sampling == Sampling::zip)
    for (const SweepVariable& variable : sweep.variables)
      if (variable.values.size() != sweep.variables.front().values.size())
        throw InputError(variable.location, "variables", fmt::format("{} values for {}", variable.values.size(), variable.path),
                         fmt::format("{} values, as many as {} (sampling: zip)", sweep.variables.front().values.size(),
                                     sweep.variables.front().path));

  if (auto statistics = root.optional("statistics")) {
    if (!statistics->node().is_sequence()) statistics->fail("a list of channel paths");
    for (const NodeReader& channel : statistics->items()) {
      std::string name = channel.text();
      if (name.empty()) channel.fail("an empty path", "a channel path such as /joints/td_string/reaction_force");
      if (name.front() != '/') name = "/" + name;
      sweep.statistics.push_back(name);
    }
  }
  if (auto duration = root.optional("duration")) sweep.duration = duration->positive_number();
  return sweep;
}

}  // namespace heavesim
