#pragma once
// The key tables of a Markdown document (docs/case-format.md, docs/sweeps.md): rows of
// `key` | unit | default | meaning under a line `<!-- keys: <section> -->` (or another
// marker), read so that a test can compare them with the code's key tables.
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "tests/test_support.hpp"

namespace heavesim::testing {

struct DocumentedKey {
  std::string unit, default_value;
};

inline std::string trim(const std::string& text) {
  const std::size_t first = text.find_first_not_of(' '), last = text.find_last_not_of(' ');
  return first == std::string::npos ? "" : text.substr(first, last - first + 1);
}

/// The cells of a Markdown table row; "\|" does not separate cells.
inline std::vector<std::string> cells(const std::string& row) {
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

/// Section -> key -> unit and default, from the tables of `document` (relative to the
/// source tree) marked `<marker><section> -->`.
inline std::map<std::string, std::map<std::string, DocumentedKey>> documented_keys(const std::string& document,
                                                                              const std::string& marker) {
  std::ifstream in(source_path(document));
  std::map<std::string, std::map<std::string, DocumentedKey>> sections;
  std::string line, section;
  int row = 0;
  while (std::getline(in, line)) {
    if (line.rfind(marker, 0) == 0) {
      section = line.substr(marker.size(), line.find(" -->") - marker.size());
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

}  // namespace heavesim::testing
