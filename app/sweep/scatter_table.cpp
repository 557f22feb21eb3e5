#include "app/sweep/scatter_table.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <set>

#include <fmt/format.h>

#include "app/case/case_node.hpp"
#include "app/case/input_error.hpp"

namespace heavesim {
namespace {

struct Cell {
  std::string text;
  int column = 0;  // 1-based
};

/// The cells of one line: separated by blanks or commas, up to a '#'.
std::vector<Cell> split_cells(const std::string& line) {
  std::vector<Cell> cells;
  const std::size_t end = std::min(line.find('#'), line.size());
  for (std::size_t i = 0; i < end;) {
    if (line[i] == ' ' || line[i] == '\t' || line[i] == ',' || line[i] == '\r') {
      ++i;
      continue;
    }
    const std::size_t start = i;
    while (i < end && line[i] != ' ' && line[i] != '\t' && line[i] != ',' && line[i] != '\r') ++i;
    cells.push_back({line.substr(start, i - start), static_cast<int>(start) + 1});
  }
  return cells;
}

bool parse_number(const std::string& text, double& value) {
  std::size_t used = 0;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    return false;
  }
  return used == text.size();
}

}  // namespace

ScatterTable read_scatter_table(const std::string& path) {
  const SourceLocation whole{path, 0, 0};
  if (const std::string problem = unreadable_case_file(path); !problem.empty())
    throw InputError(whole, "", problem, readable_case_file_expectation() + " holding a scatter diagram");
  std::ifstream in(path);
  if (!in) throw InputError(whole, "", "a file that cannot be opened", "a readable scatter-diagram file");

  ScatterTable table;
  std::string line;
  bool header = false;
  for (int number = 1; std::getline(in, line); ++number) {
    const std::vector<Cell> cells = split_cells(line);
    if (cells.empty()) continue;
    auto fail = [&](const Cell& cell, const std::string& found, const std::string& expected) {
      throw InputError(SourceLocation{path, number, cell.column}, "", found, expected);
    };
    if (!header) {
      // The header: the Tp class centres, after an optional label.
      double value = 0.0;
      const std::size_t first = parse_number(cells[0].text, value) ? 0 : 1;
      if (first >= cells.size()) fail(cells[0], "a header with no periods", "the Tp class centres [s] in one row");
      for (std::size_t i = first; i < cells.size(); ++i) {
        if (!parse_number(cells[i].text, value)) fail(cells[i], "'" + cells[i].text + "'", "a peak period Tp [s]");
        if (!(value > 0.0 && value <= 1000.0))
          fail(cells[i], fmt::format("Tp = {} s", value), "a period 0 < Tp <= 1000 s");
        if (std::find(table.tp.begin(), table.tp.end(), value) != table.tp.end())
          fail(cells[i], fmt::format("Tp = {} s a second time", value), "each period class once");
        table.tp.push_back(value);
      }
      header = true;
      continue;
    }
    if (cells.size() != table.tp.size() + 1)
      fail(cells.back(), fmt::format("{} cells", cells.size()),
           fmt::format("{} cells: Hs [m] and one occurrence per period of the header", table.tp.size() + 1));
    double hs = 0.0;
    if (!parse_number(cells[0].text, hs)) fail(cells[0], "'" + cells[0].text + "'", "a significant wave height Hs [m]");
    if (!(hs > 0.0 && hs <= 100.0)) fail(cells[0], fmt::format("Hs = {} m", hs), "a height 0 < Hs <= 100 m");
    if (std::find(table.hs.begin(), table.hs.end(), hs) != table.hs.end())
      fail(cells[0], fmt::format("Hs = {} m a second time", hs), "each height class once");
    std::vector<double> row;
    for (std::size_t i = 1; i < cells.size(); ++i) {
      double occurrence = 0.0;
      if (!parse_number(cells[i].text, occurrence))
        fail(cells[i], "'" + cells[i].text + "'", "an occurrence (a count or a probability)");
      if (!(occurrence >= 0.0 && occurrence <= 1e15))
        fail(cells[i], fmt::format("{}", occurrence), "an occurrence >= 0 (and finite)");
      row.push_back(occurrence);
      table.total += occurrence;
    }
    table.hs.push_back(hs);
    table.occurrence.push_back(std::move(row));
  }
  if (!header || table.hs.empty())
    throw InputError(whole, "", header ? "a header and no rows" : "no table",
                     "a header row of Tp [s] and at least one row of Hs [m] with its occurrences");
  if (!(table.total > 0.0)) throw InputError(whole, "", "every occurrence zero", "at least one sea state that occurs");
  return table;
}

}  // namespace heavesim
