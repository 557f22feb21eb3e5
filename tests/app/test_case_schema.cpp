// The case schema (app/case/case_schema.cpp) and docs/case-format.md agree: every key a
// reader accepts is documented with its unit and default in the table marked
// `<!-- keys: <section> -->`, and every documented key is accepted, in both directions.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <map>
#include <set>

#include "app/case/case_schema.hpp"
#include "tests/app/documented_keys.hpp"
#include "tests/test_support.hpp"

namespace heavesim {
namespace {

/// Section -> key -> unit and default, from docs/case-format.md's `<!-- keys: ... -->` tables.
std::map<std::string, std::map<std::string, testing::DocumentedKey>> documented_keys() {
  return testing::documented_keys("docs/case-format.md", "<!-- keys: ");
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
