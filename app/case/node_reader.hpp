#pragma once
// Typed, path-aware reading of a CaseNode: every failure becomes an InputError
// naming the file position, the key path, what was found and what was expected.
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "app/case/case_node.hpp"
#include "app/case/expression.hpp"
#include "app/case/quantity_range.hpp"
#include "kernel/spatial/types.hpp"

namespace heavesim {

/// The closest of `candidates` to `word` within a small edit distance, or "".
std::string closest_match(const std::string& word, const std::vector<std::string>& candidates);

class NodeReader {
 public:
  NodeReader(const CaseNode& node, std::string path, const ExpressionContext& expressions)
      : node_(&node), path_(std::move(path)), expressions_(&expressions) {}

  const CaseNode& node() const { return *node_; }
  const std::string& path() const { return path_; }
  const SourceLocation& location() const { return node_->location; }
  /// The case's expression context: its named parameters (for expressions of t that are
  /// evaluated during the run, such as a joint torque's).
  const ExpressionContext& expressions() const { return *expressions_; }

  // --- maps ---
  /// Requires a map whose keys are all keys of `form` of the schema section `section`
  /// (app/case/case_schema.hpp); an unknown key is an error with a did-you-mean.
  void expect_section(std::string_view section, std::string_view form = {}) const;
  /// Requires a map whose keys are all in `allowed` (for files other than a case, e.g. a
  /// sweep file, whose key tables are their own); an unknown key has a did-you-mean.
  void expect_keys(const std::vector<std::string_view>& allowed) const;
  bool has(const std::string& key) const;
  /// A required entry.
  NodeReader operator[](const std::string& key) const;
  std::optional<NodeReader> optional(const std::string& key) const;

  // --- scalars ---
  /// A finite number within any_number (app/case/quantity_range.hpp): NaN, infinity and
  /// magnitudes whose products overflow are refused at their key.
  double number() const;
  /// A number within `range` (a length, a mass, ...), which replaces any_number.
  double number_in(const QuantityRange& range) const;
  double number_or(const std::string& key, double default_value) const;
  /// A number > 0 (>= 0) within `range`.
  double positive_number(const QuantityRange& range = any_number) const;
  double non_negative_number(const QuantityRange& range = any_number) const;
  long integer() const;
  std::string text() const;
  bool boolean() const;
  /// One of `options`; anything else is an error with a did-you-mean.
  std::string choice(std::initializer_list<std::string_view> options) const;
  std::string choice(const std::vector<std::string_view>& options) const;

  // --- sequences ---
  std::vector<NodeReader> items() const;
  std::vector<double> numbers() const;
  Vector3 vector3() const;
  /// A 3-vector whose components are all within `range` (a position: length_range).
  Vector3 vector3_in(const QuantityRange& range) const;
  /// A 3-vector of length 1 (tolerance 1e-6).
  Vector3 unit_vector3() const;

  [[noreturn]] void fail(const std::string& expected) const;
  [[noreturn]] void fail(const std::string& found, const std::string& expected) const;

 private:
  /// The scalar's value as an expression, unchecked.
  double evaluate() const;
  /// Fails unless lower <= value <= upper (so NaN fails too).
  void check_range(double value, const QuantityRange& range) const;

  const CaseNode* node_;
  std::string path_;
  const ExpressionContext* expressions_;
};

}  // namespace heavesim
