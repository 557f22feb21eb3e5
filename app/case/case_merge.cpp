#include "app/case/case_merge.hpp"

#include <algorithm>
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

CaseNode load_with_includes(const std::string& path, std::vector<std::string>& chain) {
  const std::string canonical = std::filesystem::weakly_canonical(path).string();
  if (std::find(chain.begin(), chain.end(), canonical) != chain.end())
    throw InputError(SourceLocation{path, 0, 0}, "include", "a file that includes itself (through " +
                                                                std::to_string(chain.size()) + " levels)",
                     "includes that form no cycle");
  chain.push_back(canonical);
  CaseNode document = load_yaml_file(path);
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
    std::vector<const CaseNode*> files;
    if (include.is_scalar()) {
      files.push_back(&include);
    } else if (include.is_sequence()) {
      for (const CaseNode& item : include.items) {
        if (!item.is_scalar())
          throw InputError(item.location, "include", item.describe(), "a file name");
        files.push_back(&item);
      }
    } else {
      throw InputError(include.location, "include", include.describe(), "a file name or a list of file names");
    }
    const std::filesystem::path directory = std::filesystem::path(path).parent_path();
    for (const CaseNode* file : files) {
      const std::string included = (directory / file->scalar).string();
      if (!std::filesystem::exists(included))
        throw InputError(file->location, "include", "'" + file->scalar + "', which does not exist (looked for " +
                                                        included + ")",
                         "an existing file, relative to the including file");
      merge_into(merged, load_with_includes(included, chain));
    }
    document.entries.erase(include_it);
  }
  merge_into(merged, document);
  chain.pop_back();
  return merged;
}

}  // namespace

CaseNode load_case_tree(const std::string& path) {
  std::vector<std::string> chain;
  return load_with_includes(path, chain);
}

void merge_into(CaseNode& base, const CaseNode& overlay) {
  if (base.is_map() && overlay.is_map()) {
    for (const CaseNode::Entry& entry : overlay.entries) {
      if (CaseNode* existing = base.find(entry.key))
        merge_into(*existing, entry.value);
      else
        base.entries.push_back(entry);
    }
    return;
  }
  if (is_named_list(base) && is_named_list(overlay)) {
    for (const CaseNode& item : overlay.items) {
      if (CaseNode* existing = find_named(base, item.find("name")->scalar))
        merge_into(*existing, item);
      else
        base.items.push_back(item);
    }
    return;
  }
  base = overlay;
}

void apply_override(CaseNode& root, const std::string& assignment) {
  const SourceLocation origin{"--set " + assignment, 0, 0};
  const auto equals = assignment.find('=');
  if (equals == std::string::npos || equals == 0)
    throw InputError(origin, "", "'" + assignment + "'", "key.path=value");
  const std::string path = assignment.substr(0, equals);
  CaseNode value = parse_yaml_text(assignment.substr(equals + 1), "--set " + path);

  // Split "a.b[2].c" into segments: a key, optionally followed by [selector]s.
  CaseNode* node = &root;
  std::string walked;
  std::size_t position = 0;
  while (position < path.size()) {
    const std::size_t end = path.find_first_of(".[", position);
    const std::string key = path.substr(position, end == std::string::npos ? std::string::npos : end - position);
    if (!key.empty()) {
      if (node->is_null()) node->kind = CaseNode::Kind::map;
      if (!node->is_map())
        throw InputError(origin, walked, node->describe(), "a map to hold key '" + key + "'");
      CaseNode* child = node->find(key);
      if (!child) {
        node->entries.push_back(CaseNode::Entry{key, origin, CaseNode{}});
        child = &node->entries.back().value;
        child->location = origin;
      }
      node = child;
      walked += (walked.empty() ? "" : ".") + key;
    }
    position = end == std::string::npos ? path.size() : end;
    if (position < path.size() && path[position] == '.') {
      ++position;
    } else if (position < path.size() && path[position] == '[') {
      const std::size_t close = path.find(']', position);
      if (close == std::string::npos) throw InputError(origin, walked, "an unclosed '['", "key[index] or key[name]");
      const std::string selector = path.substr(position + 1, close - position - 1);
      if (!node->is_sequence())
        throw InputError(origin, walked, node->describe(), "a list to select [" + selector + "] from");
      CaseNode* item = nullptr;
      if (!selector.empty() && std::all_of(selector.begin(), selector.end(), ::isdigit)) {
        const std::size_t index = std::stoul(selector);
        if (index < node->items.size()) item = &node->items[index];
      } else {
        item = find_named(*node, selector);
      }
      if (!item)
        throw InputError(origin, walked + "[" + selector + "]", "no such item",
                         "an index below " + std::to_string(node->items.size()) + " or the name of an item");
      node = item;
      walked += "[" + selector + "]";
      position = close + 1;
      if (position < path.size() && path[position] == '.') ++position;
    }
  }
  *node = value;
}

}  // namespace heavesim
