#include "app/case/case_node.hpp"

#include <yaml-cpp/yaml.h>

#include <fstream>
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
    case Kind::scalar:
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

namespace {

SourceLocation location_of(const YAML::Mark& mark, const std::string& file) {
  if (mark.is_null()) return SourceLocation{file, 0, 0};
  return SourceLocation{file, mark.line + 1, mark.column + 1};
}

CaseNode convert(const YAML::Node& node, const std::string& file) {
  CaseNode result;
  result.location = location_of(node.Mark(), file);
  switch (node.Type()) {
    case YAML::NodeType::Undefined:
    case YAML::NodeType::Null:
      result.kind = CaseNode::Kind::null;
      break;
    case YAML::NodeType::Scalar:
      result.kind = CaseNode::Kind::scalar;
      result.scalar = node.Scalar();
      break;
    case YAML::NodeType::Sequence:
      result.kind = CaseNode::Kind::sequence;
      for (const YAML::Node& item : node) result.items.push_back(convert(item, file));
      break;
    case YAML::NodeType::Map:
      result.kind = CaseNode::Kind::map;
      for (const auto& pair : node) {
        const SourceLocation key_location = location_of(pair.first.Mark(), file);
        if (!pair.first.IsScalar())
          throw InputError(key_location, "", "a non-scalar map key", "plain text keys");
        const std::string key = pair.first.Scalar();
        for (const CaseNode::Entry& earlier : result.entries)
          if (earlier.key == key)
            throw InputError(key_location, key, "key '" + key + "' a second time in the same map",
                             "each key once (first given at line " + std::to_string(earlier.key_location.line) +
                                 ")");
        result.entries.push_back(CaseNode::Entry{key, key_location, convert(pair.second, file)});
      }
      break;
  }
  return result;
}

}  // namespace

CaseNode parse_yaml_text(const std::string& text, const std::string& origin) {
  try {
    return convert(YAML::Load(text), origin);
  } catch (const YAML::ParserException& e) {
    throw InputError(location_of(e.mark, origin), "", "a YAML syntax error (" + e.msg + ")", "valid YAML");
  } catch (const YAML::Exception& e) {
    throw InputError(location_of(e.mark, origin), "", "unreadable YAML (" + e.msg + ")", "valid YAML");
  }
}

CaseNode load_yaml_file(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(SourceLocation{path, 0, 0}, "", "no readable file", "an existing YAML case file");
  std::stringstream buffer;
  buffer << in.rdbuf();
  return parse_yaml_text(buffer.str(), path);
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
