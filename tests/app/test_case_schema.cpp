// The case schema (app/case/case_schema.cpp) and docs/case-format.md agree: every key a
// reader accepts is documented with its unit and default in the table marked
// `<!-- keys: <section> -->`, and every documented key is accepted, in both directions.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <map>
#include <set>

#include "app/case/case_schema.hpp"
#include "tests/test_support.hpp"

namespace heavesim {
namespace {

struct DocumentedKey {
  std::string unit, default_value;
};

std::string trim(const std::string& text) {
  const std::size_t first = text.find_first_not_of(' '), last = text.find_last_not_of(' ');
  return first == std::string::npos ? "" : text.substr(first, last - first + 1);
}

/// The cells of a Markdown table row; "\|" does not separate cells.
std::vector<std::string> cells(const std::string& row) {
  std::vector<std::string> result;
  std::string cell;
  for (std::size_t i = 1; i < row.size(); ++i) {
    if (row[i] == '|' && row[i - 1] != '\\') {
      result.push_back(trim(cell));
      cell.clear();
    } else {
      cell += row[i];
    }
  }
  return result;
}

/// Section -> key -> unit and default, from the tables marked `<!-- keys: ... -->`.
std::map<std::string, std::map<std::string, DocumentedKey>> documented_keys() {
  std::ifstream in(testing::source_path("docs/case-format.md"));
  std::map<std::string, std::map<std::string, DocumentedKey>> sections;
  std::string line, section;
  int row = 0;
  while (std::getline(in, line)) {
    if (line.rfind("<!-- keys: ", 0) == 0) {
      section = line.substr(11, line.find(" -->") - 11);
      EXPECT_EQ(sections.count(section), 0u) << "two tables for " << section;
      sections[section];
      row = 0;
      continue;
    }
    if (section.empty()) continue;
    if (line.empty() || line[0] != '|') {
      section.clear();
      continue;
    }
    if (++row <= 2) continue;  // header and separator
    const std::vector<std::string> columns = cells(line);
    EXPECT_GE(columns.size(), 4u) << line;
    if (columns.size() < 4) continue;
    const std::string& key = columns[0];
    EXPECT_TRUE(key.size() > 2 && key.front() == '`' && key.back() == '`' && key.find(',') == std::string::npos)
        << "one `key` per row: " << line;
    sections[section][key.substr(1, key.size() - 2)] = {columns[1], columns[2]};
  }
  return sections;
}

TEST(CaseSchema, EveryAcceptedKeyIsDocumentedWithItsUnitAndDefault) {
  const auto documented = documented_keys();
  for (const SchemaSection& section : case_schema()) {
    SCOPED_TRACE(std::string(section.name));
    const auto table = documented.find(std::string(section.name));
    ASSERT_NE(table, documented.end()) << "no table '<!-- keys: " << section.name << " -->' in docs/case-format.md";
    for (const KeySpec& spec : section.keys) {
      const auto key = table->second.find(std::string(spec.key));
      if (key == table->second.end()) {
        ADD_FAILURE() << "'" << spec.key << "' is accepted but not documented";
        continue;
      }
      EXPECT_EQ(key->second.unit, spec.unit) << spec.key;
      EXPECT_EQ(key->second.default_value, spec.default_value) << spec.key;
      EXPECT_FALSE(spec.meaning.empty()) << spec.key;
    }
  }
}

TEST(CaseSchema, EveryDocumentedKeyIsAccepted) {
  std::map<std::string, std::set<std::string>> schema;
  for (const SchemaSection& section : case_schema())
    for (const KeySpec& spec : section.keys) schema[std::string(section.name)].insert(std::string(spec.key));
  for (const auto& [section, keys] : documented_keys()) {
    SCOPED_TRACE(section);
    ASSERT_EQ(schema.count(section), 1u) << "a documented section the schema does not have";
    for (const auto& [key, documented] : keys)
      EXPECT_EQ(schema[section].count(key), 1u) << "'" << key << "' is documented but not accepted";
  }
}

TEST(CaseSchema, FormsSelectTheKeysOfOneForm) {
  const std::vector<std::string_view> regular = accepted_keys("waves", "regular");
  EXPECT_EQ(regular, (std::vector<std::string_view>{"type", "amplitude", "period", "heading", "phase", "ramp"}));
  EXPECT_EQ(accepted_keys("waves", "none"), (std::vector<std::string_view>{"type"}));
  const std::vector<std::string_view> root = accepted_keys("top-level");
  EXPECT_EQ(std::count(root.begin(), root.end(), "include"), 0) << "merged away before the reader";
}

}  // namespace
}  // namespace heavesim
