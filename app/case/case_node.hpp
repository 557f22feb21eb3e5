#pragma once
// A YAML document as a tree whose every node remembers its source position, so that
// errors can name file, line and column even after includes are merged and
// command-line overrides applied.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "app/case/input_error.hpp"

namespace heavesim {

// What one case may hold. Beyond these, input is rejected (exit 2) instead of hanging,
// exhausting memory or overflowing the stack; a real case is far inside all three.
/// Bytes in one case file (16 MiB).
inline constexpr std::uintmax_t max_case_file_bytes = 16u * 1024u * 1024u;
/// Values (scalars, lists, maps) in a case with its includes, counting every expansion of
/// a YAML alias: a bound on the tree an "alias bomb" would build.
inline constexpr std::size_t max_case_values = 1'000'000;
/// Levels of lists and maps inside one another.
inline constexpr int max_case_nesting = 100;
/// Bytes from a flow collection's opening [ or { to its closing bracket (1 MiB). yaml-cpp
/// holds every token of a flow collection in memory until it is closed (about 150 bytes
/// per byte of text): 16 MiB of unclosed '[' took 3.9 GB.
inline constexpr std::size_t max_flow_collection_bytes = 1024 * 1024;

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
  /// This node and all nodes below it.
  std::size_t count_values() const;
};

struct CaseNode::Entry {
  std::string key;
  SourceLocation key_location;
  CaseNode value;
};

/// Why `path` cannot be read as a case file, as the thing found there ("a directory",
/// "a named pipe (FIFO)", "a file of 20000000 bytes", ...), or "" when it is a regular
/// file of at most max_case_file_bytes. Looks without opening: opening a FIFO blocks.
std::string unreadable_case_file(const std::string& path);
/// What a case file must be, for messages ("a regular file of at most 16 MiB").
std::string readable_case_file_expectation();

/// Parses a YAML file (throws InputError on syntax errors, duplicate keys, a second
/// document, and anything unreadable_case_file rejects); at most `value_limit` values.
CaseNode load_yaml_file(const std::string& path, std::size_t value_limit = max_case_values);
/// Parses YAML text holding one document; `origin` names it in messages.
CaseNode parse_yaml_text(const std::string& text, const std::string& origin,
                         std::size_t value_limit = max_case_values);
/// Emits the tree as YAML text.
std::string to_yaml_text(const CaseNode& node);

}  // namespace heavesim
