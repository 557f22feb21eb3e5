#include "app/case/case_node.hpp"

#include "hydro/data_file.hpp"

#include <yaml-cpp/anchor.h>
#include <yaml-cpp/depthguard.h>
#include <yaml-cpp/eventhandler.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>

namespace heavesim {

const CaseNode* CaseNode::find(const std::string& key) const {
  for (const Entry& entry : entries)
    if (entry.key == key) return &entry.value;
  return nullptr;
}

CaseNode* CaseNode::find(const std::string& key) {
  for (Entry& entry : entries)
    if (entry.key == key) return &entry.value;
  return nullptr;
}

std::string CaseNode::describe() const {
  switch (kind) {
    case Kind::null:
      return "nothing (empty value)";
    case Kind::scalar:  // a long text is cut: a message stays a line, whatever the input
      if (scalar.size() > 80) return "'" + scalar.substr(0, 60) + "...' (" + std::to_string(scalar.size()) + " characters)";
      return "'" + scalar + "'";
    case Kind::sequence: {
      std::string text = "[";
      for (std::size_t i = 0; i < items.size(); ++i) {
        if (i > 0) text += ", ";
        if (i == 6) return text + "...] (" + std::to_string(items.size()) + " items)";
        text += items[i].is_scalar() ? items[i].scalar : (items[i].is_map() ? "{...}" : "[...]");
      }
      return text + "]";
    }
    case Kind::map: {
      std::string text = "a map with keys ";
      for (std::size_t i = 0; i < entries.size(); ++i) text += (i ? ", " : "") + entries[i].key;
      return entries.empty() ? "an empty map" : text;
    }
  }
  return "?";
}

std::size_t CaseNode::count_values() const {
  std::size_t count = 1;
  for (const CaseNode& item : items) count += item.count_values();
  for (const Entry& entry : entries) count += entry.value.count_values();
  return count;
}

namespace {

SourceLocation location_of(const YAML::Mark& mark, const std::string& file) {
  if (mark.is_null()) return SourceLocation{file, 0, 0};
  return SourceLocation{file, mark.line + 1, mark.column + 1};
}

std::string child_path(const std::string& parent, const std::string& key) {
  return parent.empty() ? key : parent + "." + key;
}

/// Builds the CaseNode tree from yaml-cpp's parse events rather than from YAML::Load's
/// tree, because the events let every check happen while the tree grows: each value is
/// counted as it is made (an alias is copied, so an "alias bomb" would otherwise expand
/// without bound), nesting is bounded long before yaml-cpp's own recursion runs deep, a
/// duplicate key is reported with its full key path, an alias inside its own anchor (a
/// cycle YAML::Load turns into a self-referencing node) is caught, and a second document
/// is seen at its '---' instead of being ignored.
class TreeBuilder : public YAML::EventHandler {
 public:
  TreeBuilder(const std::string& text, std::string origin, std::size_t value_limit)
      : text_(text), origin_(std::move(origin)), value_limit_(value_limit) {
    root_.location = SourceLocation{origin_, 0, 0};
  }

  CaseNode take_root() { return std::move(root_); }

  void OnDocumentStart(const YAML::Mark& mark) override {
    if (++documents_ > 1)
      throw InputError(location_of(mark, origin_), "", "a second YAML document (after a '---' or '...' line)",
                       "one document per case file (combine files with include:)");
  }
  void OnDocumentEnd() override {}

  void OnAnchor(const YAML::Mark&, const std::string& name) override { anchor_names_.push_back(name); }

  void OnNull(const YAML::Mark& mark, YAML::anchor_t anchor) override { finish(make(mark, CaseNode::Kind::null), anchor); }

  void OnScalar(const YAML::Mark& mark, const std::string&, YAML::anchor_t anchor, const std::string& value) override {
    check_quote_closed(mark);
    CaseNode node = make(mark, CaseNode::Kind::scalar);
    node.scalar = value;
    finish(std::move(node), anchor);
  }

  void OnAlias(const YAML::Mark& mark, YAML::anchor_t anchor) override {
    const auto anchored = anchors_.find(anchor);
    if (anchored == anchors_.end())  // yaml-cpp rejects unknown anchors: this one is still open
      throw InputError(location_of(mark, origin_), path_for_message(), "the alias *" + anchor_name(anchor) +
                                                                    " inside the value it names (a cycle)",
                       "an alias to a value that is complete before it");
    if (values_ + anchored->second.values > value_limit_) too_many_values(mark);
    values_ += anchored->second.values;
    CaseNode copy = anchored->second.node;
    copy.location = location_of(mark, origin_);  // a value wrong through an alias is reported at the alias
    finish(std::move(copy), YAML::NullAnchor);
  }

  void OnSequenceStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t anchor,
                       YAML::EmitterStyle::value) override {
    open(mark, CaseNode::Kind::sequence, anchor);
  }
  void OnSequenceEnd() override { close(); }

  void OnMapStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t anchor, YAML::EmitterStyle::value) override {
    open(mark, CaseNode::Kind::map, anchor);
  }
  void OnMapEnd() override { close(); }

 private:
  struct Open {
    CaseNode node;
    YAML::anchor_t anchor;
    std::size_t values_before;  // the count when it opened: the anchored value's size
    std::string path;
    bool has_key = false;  // a map's key read, its value not yet
    CaseNode::Entry pending;
  };
  struct Anchored {
    CaseNode node;
    std::size_t values;
  };

  CaseNode make(const YAML::Mark& mark, CaseNode::Kind kind) {
    if (values_ + 1 > value_limit_) too_many_values(mark);
    ++values_;
    CaseNode node;
    node.kind = kind;
    node.location = location_of(mark, origin_);
    return node;
  }

  void open(const YAML::Mark& mark, CaseNode::Kind kind, YAML::anchor_t anchor) {
    if (static_cast<int>(open_.size()) >= max_case_nesting)
      throw InputError(location_of(mark, origin_), path_for_message(),
                       "lists and maps nested more than " + std::to_string(max_case_nesting) + " levels deep",
                       "at most " + std::to_string(max_case_nesting) + " levels of nesting");
    const std::string path = path_here();
    const std::size_t before = values_;
    open_.push_back(Open{make(mark, kind), anchor, before, path, false, CaseNode::Entry{}});
  }

  void close() {
    Open done = std::move(open_.back());
    open_.pop_back();
    if (done.anchor != YAML::NullAnchor) anchors_[done.anchor] = Anchored{done.node, values_ - done.values_before};
    attach(std::move(done.node));
  }

  void finish(CaseNode node, YAML::anchor_t anchor) {
    if (anchor != YAML::NullAnchor) anchors_[anchor] = Anchored{node, node.count_values()};
    attach(std::move(node));
  }

  /// Hands a complete node to the collection being built (or makes it the document).
  void attach(CaseNode node) {
    if (open_.empty()) {
      root_ = std::move(node);
      return;
    }
    Open& parent = open_.back();
    if (parent.node.is_sequence()) {
      parent.node.items.push_back(std::move(node));
      return;
    }
    if (!parent.has_key) {
      if (!node.is_scalar())
        throw InputError(node.location, parent.path, node.describe() + " as a map key", "plain text keys");
      parent.pending.key = std::move(node.scalar);
      parent.pending.key_location = node.location;
      parent.has_key = true;
      return;
    }
    for (const CaseNode::Entry& earlier : parent.node.entries)
      if (earlier.key == parent.pending.key)
        throw InputError(parent.pending.key_location, child_path(parent.path, earlier.key),
                         "key '" + earlier.key + "' a second time in the same map",
                         "each key once (first given at line " + std::to_string(earlier.key_location.line) + ")");
    parent.pending.value = std::move(node);
    parent.node.entries.push_back(std::move(parent.pending));
    parent.pending = CaseNode::Entry{};
    parent.has_key = false;
  }

  /// Key path of the node about to be made (a.b[2].c).
  std::string path_here() const {
    if (open_.empty()) return "";
    const Open& parent = open_.back();
    if (parent.node.is_sequence()) return parent.path + "[" + std::to_string(parent.node.items.size()) + "]";
    return parent.has_key ? child_path(parent.path, parent.pending.key) : parent.path;
  }

  /// The same for a message: a path 100 levels deep is cut so that the message stays a line.
  std::string path_for_message() const {
    const std::string path = path_here();
    return path.size() > 100 ? path.substr(0, 80) + "..." : path;
  }

  /// yaml-cpp ends a quoted scalar that is never closed at the end of the input without
  /// complaint: the rest of the file becomes one string and the error surfaced later as
  /// a missing key. A quote that opens a scalar must close before the end of the text.
  void check_quote_closed(const YAML::Mark& mark) const {
    if (mark.is_null() || mark.pos < 0) return;
    // yaml-cpp counts positions in UTF-8 bytes after a byte-order mark; other
    // encodings are not checked.
    const std::size_t bom = text_.rfind("\xEF\xBB\xBF", 0) == 0 ? 3 : 0;
    const std::size_t start = bom + static_cast<std::size_t>(mark.pos);
    if (start >= text_.size() || (text_[start] != '"' && text_[start] != '\'')) return;
    const char quote = text_[start];
    for (std::size_t i = start + 1; i < text_.size(); ++i) {
      if (quote == '"' && text_[i] == '\\') {
        ++i;  // an escaped character
      } else if (text_[i] == quote) {
        if (quote == '\'' && i + 1 < text_.size() && text_[i + 1] == '\'') {
          ++i;  // '' is a quote inside single quotes
        } else {
          return;
        }
      }
    }
    throw InputError(location_of(mark, origin_), path_for_message(),
                     std::string("a ") + quote + " that opens a quoted text and is never closed",
                     std::string("a closing ") + quote + " (a quoted text may span lines but must end)");
  }

  [[noreturn]] void too_many_values(const YAML::Mark& mark) const {
    throw InputError(location_of(mark, origin_), path_for_message(),
                     "the case growing past " + std::to_string(max_case_values) +
                         " values here (each use of an alias copies its anchor's value; included files count too)",
                     "at most " + std::to_string(max_case_values) + " values in a case and its includes");
  }

  std::string anchor_name(YAML::anchor_t anchor) const {
    // yaml-cpp numbers anchors 1, 2, ... in the order it reports them.
    return anchor >= 1 && anchor <= anchor_names_.size() ? anchor_names_[anchor - 1] : std::to_string(anchor);
  }

  const std::string& text_;
  std::string origin_;
  std::size_t value_limit_;
  std::size_t values_ = 0;
  int documents_ = 0;
  CaseNode root_;
  std::vector<Open> open_;
  std::map<YAML::anchor_t, Anchored> anchors_;
  std::vector<std::string> anchor_names_;
};

/// Rejects a flow collection longer than max_flow_collection_bytes before yaml-cpp sees
/// it. Every bracket counts, also in quotes and comments: a check that never lets a long
/// collection through, at the price of refusing a file over 1 MiB with a stray '[' in a
/// text (the closing clamps at zero, so stray ']' cannot hide later openings).
void check_flow_collections(const std::string& text, const std::string& origin) {
  std::size_t depth = 0, opened_at = 0;
  for (std::size_t i = 0; i <= text.size(); ++i) {
    const bool end = i == text.size();
    if (!end && (text[i] == '[' || text[i] == '{')) {
      if (depth++ == 0) opened_at = i;
    } else if (!end && (text[i] == ']' || text[i] == '}')) {
      if (depth > 0) --depth;
    }
    if (depth > 0 && i - opened_at > max_flow_collection_bytes) {
      const std::size_t line_start = text.rfind('\n', opened_at);
      const int line = 1 + static_cast<int>(std::count(text.begin(), text.begin() + opened_at, '\n'));
      const int column = static_cast<int>(opened_at - (line_start == std::string::npos ? 0 : line_start + 1)) + 1;
      throw InputError(SourceLocation{origin, line, column}, "",
                       std::string("a '") + text[opened_at] + "' whose flow collection runs on for more than " +
                           std::to_string(max_flow_collection_bytes) + " bytes",
                       "flow collections ([...], {...}) of at most 1 MiB; longer lists in block style, one "
                       "'- item' per line");
    }
    if (end) break;
  }
}

}  // namespace

CaseNode parse_yaml_text(const std::string& text, const std::string& origin, std::size_t value_limit) {
  check_flow_collections(text, origin);
  std::istringstream stream(text);
  TreeBuilder builder(text, origin, value_limit);
  try {
    YAML::Parser parser(stream);
    while (parser.HandleNextDocument(builder)) {
    }
  } catch (const YAML::DeepRecursion& e) {  // not reached while max_case_nesting is below yaml-cpp's limit
    throw InputError(location_of(e.mark, origin), "", "nesting deeper than the YAML reader follows (depth " +
                                                          std::to_string(e.depth()) + ")",
                     "at most " + std::to_string(max_case_nesting) + " levels of nesting");
  } catch (const YAML::ParserException& e) {
    throw InputError(location_of(e.mark, origin), "", "a YAML syntax error (" + e.msg + ")", "valid YAML");
  } catch (const YAML::Exception& e) {
    throw InputError(location_of(e.mark, origin), "", "unreadable YAML (" + e.msg + ")", "valid YAML");
  }
  return builder.take_root();
}

std::string unreadable_case_file(const std::string& path) {
  return hydro::unreadable_file(path, max_case_file_bytes);
}

std::string readable_case_file_expectation() {
  return "a regular file of at most " + std::to_string(max_case_file_bytes / (1024 * 1024)) + " MiB (" +
         std::to_string(max_case_file_bytes) + " bytes)";
}

CaseNode load_yaml_file(const std::string& path, std::size_t value_limit) {
  const SourceLocation whole_file{path, 0, 0};
  if (const std::string problem = unreadable_case_file(path); !problem.empty())
    throw InputError(whole_file, "", problem, readable_case_file_expectation());
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw InputError(whole_file, "", "a file that cannot be opened (" + std::string(std::strerror(errno)) + ")",
                     readable_case_file_expectation());
  // Read at most one byte past the limit: the size checked above may be stale or, for
  // files such as those in /proc, not the length of what reads return.
  std::string text;
  std::array<char, 65536> buffer;
  while (in.read(buffer.data(), buffer.size()) || in.gcount() > 0) {
    text.append(buffer.data(), static_cast<std::size_t>(in.gcount()));
    if (text.size() > max_case_file_bytes)
      throw InputError(whole_file, "", "a file of more than " + std::to_string(max_case_file_bytes) + " bytes",
                       readable_case_file_expectation());
  }
  return parse_yaml_text(text, path, value_limit);
}

namespace {

void emit(YAML::Emitter& out, const CaseNode& node) {
  switch (node.kind) {
    case CaseNode::Kind::null:
      out << YAML::Null;
      break;
    case CaseNode::Kind::scalar:
      out << node.scalar;
      break;
    case CaseNode::Kind::sequence: {
      bool flat = node.items.size() <= 16;
      for (const CaseNode& item : node.items) flat = flat && item.is_scalar();
      if (flat) out << YAML::Flow;
      out << YAML::BeginSeq;
      for (const CaseNode& item : node.items) emit(out, item);
      out << YAML::EndSeq;
      break;
    }
    case CaseNode::Kind::map:
      out << YAML::BeginMap;
      for (const CaseNode::Entry& entry : node.entries) {
        out << YAML::Key << entry.key << YAML::Value;
        emit(out, entry.value);
      }
      out << YAML::EndMap;
      break;
  }
}

}  // namespace

std::string to_yaml_text(const CaseNode& node) {
  YAML::Emitter out;
  emit(out, node);
  return std::string(out.c_str()) + "\n";
}

}  // namespace heavesim
