#include "app/case/node_reader.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "app/case/case_schema.hpp"

namespace heavesim {

namespace {

std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> previous(b.size() + 1), current(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) previous[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    current[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j)
      current[j] = std::min({previous[j] + 1, current[j - 1] + 1, previous[j - 1] + (a[i - 1] != b[j - 1])});
    std::swap(previous, current);
  }
  return previous[b.size()];
}

template <class Words>
std::string join(const Words& words) {
  std::string text;
  for (std::string_view word : words) text += (text.empty() ? "" : ", ") + std::string(word);
  return text;
}

}  // namespace

std::string closest_match(const std::string& word, const std::vector<std::string>& candidates) {
  std::string best;
  std::size_t best_distance = std::max<std::size_t>(2, word.size() / 3) + 1;
  for (const std::string& candidate : candidates) {
    const std::size_t distance = edit_distance(word, candidate);
    if (distance < best_distance) {
      best_distance = distance;
      best = candidate;
    }
  }
  return best;
}

void NodeReader::fail(const std::string& expected) const { fail(node_->describe(), expected); }

void NodeReader::fail(const std::string& found, const std::string& expected) const {
  throw InputError(node_->location, path_, found, expected);
}

void NodeReader::expect_section(std::string_view section, std::string_view form) const {
  expect_keys(accepted_keys(section, form));
}

void NodeReader::expect_keys(const std::vector<std::string_view>& allowed) const {
  if (!node_->is_map()) fail("a map with keys " + join(allowed));
  for (const CaseNode::Entry& entry : node_->entries) {
    if (std::find(allowed.begin(), allowed.end(), entry.key) != allowed.end()) continue;
    const std::vector<std::string> candidates(allowed.begin(), allowed.end());
    const std::string suggestion = closest_match(entry.key, candidates);
    const std::string key_path = path_.empty() ? entry.key : path_ + "." + entry.key;
    throw InputError(entry.key_location, key_path, "unknown key '" + entry.key + "'",
                     suggestion.empty() ? "one of: " + join(allowed)
                                        : "'" + suggestion + "' (did you mean it?); allowed here: " + join(allowed));
  }
}

bool NodeReader::has(const std::string& key) const {
  return node_->is_map() && node_->find(key) != nullptr;
}

NodeReader NodeReader::operator[](const std::string& key) const {
  const std::string key_path = path_.empty() ? key : path_ + "." + key;
  if (!node_->is_map()) fail("a map containing '" + key + "'");
  const CaseNode* child = node_->find(key);
  if (!child) throw InputError(node_->location, key_path, "no '" + key + "' key", "'" + key + "' (required)");
  return NodeReader(*child, key_path, *expressions_);
}

std::optional<NodeReader> NodeReader::optional(const std::string& key) const {
  if (!has(key)) return std::nullopt;
  const CaseNode* child = node_->find(key);
  if (child->is_null()) return std::nullopt;
  return NodeReader(*child, path_.empty() ? key : path_ + "." + key, *expressions_);
}

double NodeReader::evaluate() const {
  if (!node_->is_scalar()) fail("a number or an expression such as deg(90)");
  try {
    return expressions_->evaluate(node_->scalar);
  } catch (const std::invalid_argument& e) {
    fail(node_->describe() + " (" + e.what() + ")", "a number or an expression such as deg(90)");
  }
}

double NodeReader::number() const { return number_in(any_number); }

double NodeReader::number_in(const QuantityRange& range) const {
  const double value = evaluate();
  check_range(value, range);
  return value;
}

void NodeReader::check_range(double value, const QuantityRange& range) const {
  if (value >= range.lower && value <= range.upper) return;
  const std::string unit = range.unit.empty() ? "" : " " + std::string(range.unit);
  const std::string value_text = fmt::format("{:g}", value);
  const std::string given = !node_->is_scalar()          ? node_->describe()
                            : node_->scalar == value_text ? value_text
                                                          : fmt::format("{} (= {})", node_->describe(), value_text);
  fail(given, fmt::format("{} in [{:g}, {:g}]{}", range.kind, range.lower, range.upper, unit));
}

double NodeReader::number_or(const std::string& key, double default_value) const {
  const auto child = optional(key);
  return child ? child->number() : default_value;
}

double NodeReader::positive_number(const QuantityRange& range) const {
  const double value = number_in(range);
  if (!(value > 0.0)) fail(fmt::format("{} (= {:g})", node_->describe(), value), "a positive number");
  return value;
}

double NodeReader::non_negative_number(const QuantityRange& range) const {
  const double value = number_in(range);
  if (value < 0.0) fail(fmt::format("{} (= {:g})", node_->describe(), value), "a number >= 0");
  return value;
}

long NodeReader::integer() const {
  const double value = number();
  if (value != std::floor(value) || std::abs(value) > 1e15) fail("a whole number");
  return static_cast<long>(value);
}

std::string NodeReader::text() const {
  if (!node_->is_scalar()) fail("text");
  return node_->scalar;
}

bool NodeReader::boolean() const {
  if (node_->is_scalar()) {
    const std::string& s = node_->scalar;
    if (s == "true" || s == "yes" || s == "on") return true;
    if (s == "false" || s == "no" || s == "off") return false;
  }
  fail("true or false");
}

std::string NodeReader::choice(std::initializer_list<std::string_view> options) const {
  return choice(std::vector<std::string_view>(options));
}

std::string NodeReader::choice(const std::vector<std::string_view>& options) const {
  const std::string value = node_->is_scalar() ? node_->scalar : std::string();
  if (std::find(options.begin(), options.end(), value) != options.end()) return value;
  const std::string suggestion =
      node_->is_scalar() ? closest_match(value, std::vector<std::string>(options.begin(), options.end())) : "";
  fail(suggestion.empty() ? "one of: " + join(options)
                          : "'" + suggestion + "' (did you mean it?); one of: " + join(options));
}

std::vector<NodeReader> NodeReader::items() const {
  if (!node_->is_sequence()) fail("a list");
  std::vector<NodeReader> result;
  for (std::size_t i = 0; i < node_->items.size(); ++i)
    result.emplace_back(node_->items[i], path_ + "[" + std::to_string(i) + "]", *expressions_);
  return result;
}

std::vector<double> NodeReader::numbers() const {
  std::vector<double> values;
  for (const NodeReader& item : items()) values.push_back(item.number());
  return values;
}

Vector3 NodeReader::vector3() const {
  if (!node_->is_sequence() || node_->items.size() != 3) fail("a list of 3 numbers [x, y, z]");
  const std::vector<double> values = numbers();
  return Vector3(values[0], values[1], values[2]);
}

Vector3 NodeReader::vector3_in(const QuantityRange& range) const {
  if (!node_->is_sequence() || node_->items.size() != 3) fail("a list of 3 numbers [x, y, z]");
  const std::vector<NodeReader> components = items();
  return Vector3(components[0].number_in(range), components[1].number_in(range), components[2].number_in(range));
}

Vector3 NodeReader::unit_vector3() const {
  const Vector3 value = vector3();
  if (std::abs(value.norm() - 1.0) > 1e-6)
    fail(fmt::format("{} with length {:.6g}", node_->describe(), value.norm()),
         "a unit vector (length 1)" +
             (value.norm() > 0.0 ? fmt::format(", e.g. [{:.6g}, {:.6g}, {:.6g}]", value.x() / value.norm(),
                                               value.y() / value.norm(), value.z() / value.norm())
                                 : std::string()));
  return value;
}

}  // namespace heavesim
