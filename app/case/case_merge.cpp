#include "app/case/case_merge.hpp"

#include <algorithm>
#include <charconv>
#include <filesystem>
#include <set>

namespace heavesim {
namespace {

bool is_named_list(const CaseNode& node) {
  if (!node.is_sequence() || node.items.empty()) return false;
  return std::all_of(node.items.begin(), node.items.end(), [](const CaseNode& item) {
    const CaseNode* name = item.is_map() ? item.find("name") : nullptr;
    return name && name->is_scalar();
  });
}

CaseNode* find_named(CaseNode& list, const std::string& name) {
  for (CaseNode& item : list.items) {
    const CaseNode* item_name = item.find("name");
    if (item_name && item_name->scalar == name) return &item;
  }
  return nullptr;
}

/// The includes being followed, and what the case has loaded so far (the bounds are on
/// the whole case, so that a file included many times cannot multiply past them).
struct IncludeState {
  std::vector<std::string> chain;          // canonical paths, outermost first
  std::vector<std::string> chain_as_given;  // the same files as their paths were given
  std::size_t values = 0;
  std::size_t files = 0;
};

std::string canonical_path(const std::string& path) {
  std::error_code error;
  const std::filesystem::path canonical = std::filesystem::weakly_canonical(path, error);
  return error ? std::filesystem::absolute(path, error).lexically_normal().string() : canonical.string();
}

CaseNode load_with_includes(const std::string& path, IncludeState& state) {
  state.chain.push_back(canonical_path(path));
  state.chain_as_given.push_back(path);
  CaseNode document = load_yaml_file(path, max_case_values - state.values);
  state.values += document.count_values();
  if (document.is_null()) {  // an empty file: an empty map at its first line
    document.kind = CaseNode::Kind::map;
    document.location = SourceLocation{path, 1, 1};
  }
  if (!document.is_map())
    throw InputError(document.location, "", document.describe() + " at the top level",
                     "a map of sections (bodies, joints, solver, ...)");

  CaseNode merged;
  merged.kind = CaseNode::Kind::map;
  merged.location = document.location;
  auto include_it = std::find_if(document.entries.begin(), document.entries.end(),
                                 [](const CaseNode::Entry& e) { return e.key == "include"; });
  if (include_it != document.entries.end()) {
    const CaseNode& include = include_it->value;
    std::vector<std::pair<const CaseNode*, std::string>> files;  // each file name and its key path
    if (include.is_scalar()) {
      files.emplace_back(&include, "include");
    } else if (include.is_sequence()) {
      for (std::size_t i = 0; i < include.items.size(); ++i) {
        const CaseNode& item = include.items[i];
        const std::string key_path = "include[" + std::to_string(i) + "]";
        if (!item.is_scalar()) throw InputError(item.location, key_path, item.describe(), "a file name");
        files.emplace_back(&item, key_path);
      }
    } else {
      throw InputError(include.location, "include", include.describe(), "a file name or a list of file names");
    }
    const std::filesystem::path directory = std::filesystem::path(path).parent_path();
    for (const auto& [file, key_path] : files) {
      const std::string included = (directory / file->scalar).string();
      const std::string named = "'" + file->scalar + "' (looked for " + included + ")";
      if (const std::string problem = unreadable_case_file(included); !problem.empty())
        throw InputError(file->location, key_path, named + ", which is " + problem,
                         readable_case_file_expectation() + ", relative to the including file");
      if (std::find(state.chain.begin(), state.chain.end(), canonical_path(included)) != state.chain.end()) {
        std::string cycle;
        for (const std::string& link : state.chain_as_given) cycle += link + " -> ";
        throw InputError(file->location, key_path, named + ", which closes a cycle of includes: " + cycle + included,
                         "includes that form no cycle");
      }
      if (++state.files > max_included_files)
        throw InputError(file->location, key_path, "more than " + std::to_string(max_included_files) +
                                                       " included files in the case",
                         "at most " + std::to_string(max_included_files) + " includes in all");
      merge_into(merged, load_with_includes(included, state));
    }
    document.entries.erase(include_it);
  }
  merge_into(merged, document);
  state.chain.pop_back();
  state.chain_as_given.pop_back();
  return merged;
}

}  // namespace

CaseNode load_case_tree(const std::string& path) {
  IncludeState state;
  return load_with_includes(path, state);
}

void merge_into(CaseNode& base, const CaseNode& overlay) {
  // A map or list the overlay writes into takes the overlay's position (and so does a
  // key it writes again): an error in the merged value then points at the file that
  // had the last word on it, the including one, not at the included base.
  if (base.is_map() && overlay.is_map()) {
    for (const CaseNode::Entry& entry : overlay.entries) {
      auto existing = std::find_if(base.entries.begin(), base.entries.end(),
                                   [&](const CaseNode::Entry& e) { return e.key == entry.key; });
      if (existing != base.entries.end()) {
        existing->key_location = entry.key_location;
        merge_into(existing->value, entry.value);
      } else {
        base.entries.push_back(entry);
      }
    }
    base.location = overlay.location;
    return;
  }
  if (is_named_list(base) && is_named_list(overlay)) {
    for (const CaseNode& item : overlay.items) {
      if (CaseNode* existing = find_named(base, item.find("name")->scalar))
        merge_into(*existing, item);
      else
        base.items.push_back(item);
    }
    base.location = overlay.location;
    return;
  }
  base = overlay;
}

namespace {

/// One step of an override path: a key, or a [selector] (an index or an item's name).
struct PathStep {
  bool is_key;
  std::string text;
};

/// Splits "a.b[2].c" into its steps; a path that does not follow key(.key|[selector])*
/// is rejected rather than guessed at ("a..b" is not "a.b").
std::vector<PathStep> split_override_path(const std::string& path, const SourceLocation& origin) {
  const std::string form = "key.path or key[index] or key[name], e.g. bodies[0].mass or joints[elbow].axis";
  auto reject = [&](const std::string& found, std::size_t at) {
    throw InputError(origin, path.substr(0, at), found + " at character " + std::to_string(at + 1) + " of '" + path + "'",
                     form);
  };
  std::vector<PathStep> steps;
  std::size_t position = 0;
  bool expect_key = true;  // at the start and after '.', a key must follow
  while (position < path.size()) {
    if (expect_key) {
      const std::size_t end = std::min(path.find_first_of(".[]", position), path.size());
      if (end == position) reject(path[position] == ']' ? "a ']' without '['" : "an empty key", position);
      steps.push_back(PathStep{true, path.substr(position, end - position)});
      position = end;
      expect_key = false;
    } else if (path[position] == '.') {
      ++position;
      expect_key = true;
    } else if (path[position] == '[') {
      const std::size_t close = path.find_first_of("[]", position + 1);
      if (close == std::string::npos || path[close] != ']') reject("a '[' that is not closed", position);
      if (close == position + 1) reject("an empty selector []", position);
      steps.push_back(PathStep{false, path.substr(position + 1, close - position - 1)});
      position = close + 1;
    } else {
      reject(path[position] == ']' ? "a ']' without '['" : "'" + std::string(1, path[position]) + "' after a key or ']'",
             position);
    }
  }
  if (expect_key) reject(path.empty() ? "an empty key path" : "an empty key after the last '.'", path.size());
  return steps;
}

/// The item of `list` that `selector` names: an index (0-based) or the value of a `name`.
CaseNode* select_item(CaseNode& list, const std::string& selector, const std::string& walked,
                      const SourceLocation& origin) {
  const std::size_t size = list.items.size();
  if (std::all_of(selector.begin(), selector.end(), [](char c) { return c >= '0' && c <= '9'; })) {
    std::size_t index = 0;
    const auto [end, error] = std::from_chars(selector.data(), selector.data() + selector.size(), index);
    if (error == std::errc() && end == selector.data() + selector.size() && index < size) return &list.items[index];
    throw InputError(origin, walked + "[" + selector + "]", "index " + selector + " in a list of " +
                                                                std::to_string(size) + " items",
                     size == 0 ? "a list with items (this one is empty)"
                               : "an index from 0 to " + std::to_string(size - 1) + " or the name of an item");
  }
  if (CaseNode* item = find_named(list, selector)) return item;
  throw InputError(origin, walked + "[" + selector + "]", "no item named '" + selector + "'",
                   size == 0 ? "a list with items (this one is empty)"
                             : "an index from 0 to " + std::to_string(size - 1) + " or the name of an item");
}

}  // namespace

void apply_override(CaseNode& root, const std::string& assignment) {
  // Messages name the override; a long value is cut so that a message stays a line.
  const std::size_t shown = 120;
  const SourceLocation origin{"--set " + (assignment.size() > shown ? assignment.substr(0, shown) + "..." : assignment),
                              0, 0};
  const auto equals = assignment.find('=');
  if (equals == std::string::npos || equals == 0)
    throw InputError(origin, "", "'" + origin.file.substr(6) + "'", "key.path=value");
  const std::string path = assignment.substr(0, equals);
  const std::vector<PathStep> steps = split_override_path(path, origin);
  CaseNode value = parse_yaml_text(assignment.substr(equals + 1), "--set " + path);

  CaseNode* node = &root;
  std::string walked;
  for (const PathStep& step : steps) {
    if (step.is_key) {
      if (node->is_null()) node->kind = CaseNode::Kind::map;
      if (!node->is_map())
        throw InputError(origin, walked, node->describe(), "a map to hold key '" + step.text + "'");
      CaseNode* child = node->find(step.text);
      if (!child) {
        node->entries.push_back(CaseNode::Entry{step.text, origin, CaseNode{}});
        child = &node->entries.back().value;
        child->location = origin;
      }
      node = child;
      walked += (walked.empty() ? "" : ".") + step.text;
    } else {
      if (!node->is_sequence())
        throw InputError(origin, walked, node->describe(), "a list to select [" + step.text + "] from");
      node = select_item(*node, step.text, walked, origin);
      walked += "[" + step.text + "]";
    }
  }
  *node = std::move(value);
}

}  // namespace heavesim
