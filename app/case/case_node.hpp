#pragma once
// A YAML document as a tree whose every node remembers its source position, so that
// errors can name file, line and column even after includes are merged and
// command-line overrides applied.
#include <string>
#include <vector>

#include "app/case/input_error.hpp"

namespace heavesim {

class CaseNode {
 public:
  enum class Kind { null, scalar, sequence, map };
  struct Entry;

  Kind kind = Kind::null;
  std::string scalar;            // Kind::scalar: the text as written
  std::vector<CaseNode> items;   // Kind::sequence
  std::vector<Entry> entries;    // Kind::map, in file order
  SourceLocation location;

  bool is_null() const { return kind == Kind::null; }
  bool is_scalar() const { return kind == Kind::scalar; }
  bool is_sequence() const { return kind == Kind::sequence; }
  bool is_map() const { return kind == Kind::map; }

  const CaseNode* find(const std::string& key) const;
  CaseNode* find(const std::string& key);
  /// A short rendering of this node for messages: 'abc', [1, 2, 3], a map with keys a, b.
  std::string describe() const;
};

struct CaseNode::Entry {
  std::string key;
  SourceLocation key_location;
  CaseNode value;
};

/// Parses a YAML file (throws InputError on syntax errors and duplicate keys).
CaseNode load_yaml_file(const std::string& path);
/// Parses YAML text; `origin` names it in messages.
CaseNode parse_yaml_text(const std::string& text, const std::string& origin);
/// Emits the tree as YAML text.
std::string to_yaml_text(const CaseNode& node);

}  // namespace heavesim
