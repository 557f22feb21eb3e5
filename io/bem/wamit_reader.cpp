#include "io/bem/wamit_reader.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <numeric>
#include <set>
#include <sstream>

#include <fmt/format.h>

#include "hydro/data_file.hpp"

namespace heavesim::bem {

using hydro::BemData;
using hydro::ComplexVector6;
using hydro::DataError;
using hydro::ExcitationData;
using hydro::Matrix6;
using hydro::RadiationData;
using hydro::require_readable_data_file;
namespace {

struct Row {
  int line;
  std::vector<double> values;
};

/// Numeric rows of a WAMIT file, each with its 1-based line; blank lines skipped.
/// Every token must be a finite number and every row must have one of the allowed
/// column counts (checked by the caller through `columns`).
std::vector<Row> read_rows(const std::string& path) {
  require_readable_data_file(path, "WAMIT file");
  std::ifstream in(path);
  if (!in) throw DataError(path, 0, "a file that cannot be opened", "a readable WAMIT file");
  std::vector<Row> rows;
  std::string text;
  int line = 0;
  while (std::getline(in, text)) {
    ++line;
    std::istringstream words(text);
    std::string token;
    Row row{line, {}};
    while (words >> token) {
      char* end = nullptr;
      const double value = std::strtod(token.c_str(), &end);
      if (end == token.c_str() || *end != '\0')
        throw DataError(path, line, fmt::format("'{}' in column {}", token, row.values.size() + 1), "a number");
      if (!std::isfinite(value))
        throw DataError(path, line, fmt::format("'{}' in column {}", token, row.values.size() + 1), "a finite number");
      row.values.push_back(value);
    }
    if (!row.values.empty()) rows.push_back(std::move(row));
  }
  if (rows.empty()) throw DataError(path, line, "no numeric rows (empty file)", "WAMIT coefficient rows");
  return rows;
}

void check_columns(const std::string& path, const Row& row, size_t expected, const char* layout) {
  if (row.values.size() != expected)
    throw DataError(path, row.line, fmt::format("{} columns", row.values.size()),
                    fmt::format("{} columns ({})", expected, layout));
}

int mode_index(const std::string& path, const Row& row, size_t column, const char* name) {
  const double v = row.values[column];
  if (v != std::floor(v) || v < 1 || v > 6)
    throw DataError(path, row.line, fmt::format("{} = {:g}", name, v), fmt::format("{} an integer mode 1..6", name));
  return static_cast<int>(v) - 1;
}

/// L^k for a coefficient coupling modes i and j: k = base, base + 1, base + 2 for 0, 1
/// or 2 rotational modes.
double length_power(double L, int base, int i, int j) { return std::pow(L, base + (i >= 3) + (j >= 3)); }

double period_to_frequency(double period) { return 2.0 * M_PI / period; }

/// The frequency 2 pi / PER of a row with PER > 0; fails for a period so small that the
/// frequency overflows.
void check_frequency_finite(const std::string& path, const Row& row) {
  if (!std::isfinite(period_to_frequency(row.values[0])))
    throw DataError(path, row.line, fmt::format("PER = {:g}, whose frequency 2 pi / PER overflows", row.values[0]),
                    "a period whose frequency is a finite number");
}

/// `factor * row.values[column]`: a nondimensional coefficient made dimensional (rho g
/// L^k ...). Fails unless finite: a value near the largest double times rho g overflows.
double dimensional_column(const std::string& path, const Row& row, size_t column, double factor) {
  const double value = factor * row.values[column];
  if (!std::isfinite(value))
    throw DataError(path, row.line,
                    fmt::format("{:g} in column {}, which overflows to {} once made dimensional (x {:g})",
                                row.values[column], column + 1, value, factor),
                    "a coefficient whose dimensional value is a finite number");
  return value;
}

/// Checks |M_ij - M_ji| <= tol sqrt(|M_ii M_jj|) and symmetrises M.
void check_symmetric(const std::string& path, Matrix6& M, const Eigen::Matrix<int, 6, 6>& lines, const char* what,
                     double period) {
  for (int i = 0; i < 6; ++i)
    for (int j = i + 1; j < 6; ++j) {
      const double scale = std::sqrt(std::abs(M(i, i))) * std::sqrt(std::abs(M(j, j)));  // no overflow
      if (std::abs(M(i, j) - M(j, i)) > bem_symmetry_tolerance * scale + 1e-300) {
        const int line = std::max(lines(i, j), lines(j, i));
        throw DataError(path, line,
                        fmt::format("{}({},{}) = {:.6g} but {}({},{}) = {:.6g} at PER = {:g}", what, i + 1, j + 1,
                                    M(i, j), what, j + 1, i + 1, M(j, i), period),
                        fmt::format("a symmetric matrix (within {} of sqrt({}_ii {}_jj))", bem_symmetry_tolerance, what,
                                    what));
      }
      M(i, j) = M(j, i) = 0.5 * M(i, j) + 0.5 * M(j, i);  // halves: the sum may overflow
    }
}

struct Block {
  double period;
  int first_line;
  std::map<std::pair<int, int>, int> entries;  // (i, j) -> row index
};

}  // namespace

RadiationData read_wamit_1(const std::string& path, const WamitScaling& s) {
  const std::vector<Row> rows = read_rows(path);
  std::vector<Block> blocks;  // in order of appearance
  std::map<double, size_t> block_of_period;
  for (size_t r = 0; r < rows.size(); ++r) {
    const Row& row = rows[r];
    if (row.values.size() < 4)
      throw DataError(path, row.line, fmt::format("{} columns", row.values.size()),
                      "5 columns (PER I J A B), or 4 (PER I J A) for PER = -1 and 0");
    const double period = row.values[0];
    if (period < 0.0 && period != -1.0)
      throw DataError(path, row.line, fmt::format("PER = {:g}", period),
                      "a period > 0, or -1 (zero frequency) or 0 (infinite frequency)");
    if (period <= 0.0) {
      check_columns(path, row, 4, "PER I J A for the zero- and infinite-frequency rows");
    } else {
      check_columns(path, row, 5, "PER I J A B");
      check_frequency_finite(path, row);
    }
    const int i = mode_index(path, row, 1, "I"), j = mode_index(path, row, 2, "J");
    auto [it, inserted] = block_of_period.try_emplace(period, blocks.size());
    if (inserted) blocks.push_back({period, row.line, {}});
    Block& block = blocks[it->second];
    if (!block.entries.try_emplace({i, j}, r).second)
      throw DataError(path, row.line, fmt::format("a second row for PER = {:g}, I = {}, J = {}", period, i + 1, j + 1),
                      fmt::format("one row per (PER, I, J); the first is on line {}", rows[block.entries[{i, j}]].line));
  }
  if (!block_of_period.count(0.0))
    throw DataError(path, rows.back().line, "no rows with PER = 0 (the infinite-frequency added mass)",
                    "the PER = 0 rows: A(inf) is needed for the time-domain model (rerun WAMIT with them)");
  // Every finite period must carry the same (I, J) pairs.
  const Block* reference = nullptr;
  for (const Block& b : blocks) {
    if (b.period <= 0.0) continue;
    if (!reference) {
      reference = &b;
      continue;
    }
    for (const auto& [pair, r] : b.entries)
      if (!reference->entries.count(pair))
        throw DataError(path, rows[r].line,
                        fmt::format("I = {}, J = {} at PER = {:g}", pair.first + 1, pair.second + 1, b.period),
                        fmt::format("the same (I, J) pairs at every period; PER = {:g} (line {}) has no such row",
                                    reference->period, reference->first_line));
    for (const auto& [pair, r] : reference->entries)
      if (!b.entries.count(pair))
        throw DataError(path, b.first_line,
                        fmt::format("no row I = {}, J = {} in the block PER = {:g}", pair.first + 1, pair.second + 1,
                                    b.period),
                        fmt::format("the same (I, J) pairs at every period (PER = {:g} has it on line {})",
                                    reference->period, rows[r].line));
  }
  if (!reference) throw DataError(path, rows.back().line, "no finite-frequency rows", "rows with PER > 0");

  const double rho = s.density, L = s.length_scale;
  RadiationData data;
  std::vector<std::pair<double, const Block*>> finite;
  for (const Block& b : blocks) {
    Matrix6 A = Matrix6::Zero(), B = Matrix6::Zero();
    Eigen::Matrix<int, 6, 6> lines = Eigen::Matrix<int, 6, 6>::Zero();
    const double w = b.period > 0.0 ? period_to_frequency(b.period) : 0.0;
    for (const auto& [pair, r] : b.entries) {
      const auto [i, j] = pair;
      const double k = length_power(L, 3, i, j);
      A(i, j) = dimensional_column(path, rows[r], 3, rho * k);
      if (b.period > 0.0) B(i, j) = dimensional_column(path, rows[r], 4, rho * w * k);
      lines(i, j) = rows[r].line;
    }
    check_symmetric(path, A, lines, "A", b.period);
    if (b.period == -1.0) {
      data.added_mass_zero = A;
      data.has_added_mass_zero = true;
    } else if (b.period == 0.0) {
      data.added_mass_infinite = A;
    } else {
      // B is symmetric in theory too, but real files hold larger discretisation
      // asymmetry at short periods (MSS semisub: B15 and B51 differ by 6 % at 4.5 s), so
      // it is symmetrised without a check.
      B = symmetric_part(B);
      data.angular_frequencies.push_back(w);
      data.added_mass.push_back(A);
      data.damping.push_back(B);
    }
  }
  // Ascending frequency (WAMIT lists by period, in the order of its input).
  std::vector<size_t> order(data.angular_frequencies.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(),
            [&](size_t a, size_t b) { return data.angular_frequencies[a] < data.angular_frequencies[b]; });
  RadiationData sorted = data;
  for (size_t n = 0; n < order.size(); ++n) {
    sorted.angular_frequencies[n] = data.angular_frequencies[order[n]];
    sorted.added_mass[n] = data.added_mass[order[n]];
    sorted.damping[n] = data.damping[order[n]];
  }
  return sorted;
}

ExcitationData read_wamit_3(const std::string& path, const WamitScaling& s) {
  const std::vector<Row> rows = read_rows(path);
  std::map<double, std::map<double, std::map<int, int>>> table;  // period -> heading -> mode -> row
  std::map<double, int> first_line_of_period;
  for (size_t r = 0; r < rows.size(); ++r) {
    const Row& row = rows[r];
    check_columns(path, row, 7, "PER BETA I |X| phase Re Im");
    const double period = row.values[0], beta = row.values[1];
    if (!(period > 0.0))
      throw DataError(path, row.line, fmt::format("PER = {:g}", period), "a period > 0 s in an excitation file");
    check_frequency_finite(path, row);
    const int i = mode_index(path, row, 2, "I");
    const double modulus = row.values[3], re = row.values[5], im = row.values[6];
    // WAMIT prints 7 significant digits; |X| and (Re, Im) must describe the same number.
    if (std::abs(modulus - std::hypot(re, im)) > 1e-4 * std::max(modulus, std::hypot(re, im)) + 1e-12)
      throw DataError(path, row.line, fmt::format("|X| = {:.7g} but sqrt(Re^2 + Im^2) = {:.7g}", modulus, std::hypot(re, im)),
                      "|X| equal to the modulus of Re + i Im");
    first_line_of_period.try_emplace(period, row.line);
    auto& modes = table[period][beta];
    if (!modes.try_emplace(i, static_cast<int>(r)).second)
      throw DataError(path, row.line,
                      fmt::format("a second row for PER = {:g}, BETA = {:g}, I = {}", period, beta, i + 1),
                      fmt::format("one row per (PER, BETA, I); the first is on line {}", rows[modes[i]].line));
  }
  // Every period must have the same headings and modes.
  const auto& [reference_period, reference] = *table.begin();
  for (const auto& [period, headings] : table) {
    for (const auto& [beta, modes] : headings) {
      if (!reference.count(beta))
        throw DataError(path, rows[modes.begin()->second].line,
                        fmt::format("heading BETA = {:g} deg at PER = {:g}", beta, period),
                        fmt::format("the same headings at every period (PER = {:g} on line {} has no such heading)",
                                    reference_period, first_line_of_period[reference_period]));
      if (modes.size() != reference.at(beta).size())
        throw DataError(path, first_line_of_period[period],
                        fmt::format("{} modes at PER = {:g}, BETA = {:g}", modes.size(), period, beta),
                        fmt::format("{} modes, as at PER = {:g}", reference.at(beta).size(), reference_period));
    }
    if (headings.size() != reference.size())
      throw DataError(path, first_line_of_period[period],
                      fmt::format("{} headings at PER = {:g}", headings.size(), period),
                      fmt::format("{} headings, as at PER = {:g} (line {})", reference.size(), reference_period,
                                  first_line_of_period[reference_period]));
  }
  const double rho_g = s.density * s.gravity, L = s.length_scale;
  ExcitationData data;
  for (const auto& [beta, modes] : reference) data.headings.push_back(beta * M_PI / 180.0);
  // Periods descending = frequencies ascending.
  for (auto it = table.rbegin(); it != table.rend(); ++it) data.angular_frequencies.push_back(period_to_frequency(it->first));
  data.force.assign(data.headings.size(), std::vector<ComplexVector6>(data.angular_frequencies.size(), ComplexVector6::Zero()));
  size_t n = 0;
  for (auto it = table.rbegin(); it != table.rend(); ++it, ++n) {
    size_t h = 0;
    for (const auto& [beta, modes] : it->second) {
      for (const auto& [i, r] : modes) {
        const double scale = rho_g * std::pow(L, i < 3 ? 2 : 3);
        data.force[h][n][i] = {dimensional_column(path, rows[r], 5, scale), dimensional_column(path, rows[r], 6, scale)};
      }
      ++h;
    }
  }
  return data;
}

Matrix6 read_wamit_hst(const std::string& path, const WamitScaling& s) {
  const std::vector<Row> rows = read_rows(path);
  Matrix6 C = Matrix6::Zero();
  Eigen::Matrix<int, 6, 6> seen = Eigen::Matrix<int, 6, 6>::Zero();
  for (const Row& row : rows) {
    check_columns(path, row, 3, "I J C");
    const int i = mode_index(path, row, 0, "I"), j = mode_index(path, row, 1, "J");
    if (seen(i, j))
      throw DataError(path, row.line, fmt::format("a second row for I = {}, J = {}", i + 1, j + 1),
                      fmt::format("one row per (I, J); the first is on line {}", seen(i, j)));
    seen(i, j) = row.line;
    C(i, j) = dimensional_column(path, row, 2, s.density * s.gravity * length_power(s.length_scale, 2, i, j));
  }
  return C;
}

BemData read_wamit(const std::string& basename, const WamitScaling& scaling) {
  BemData data;
  data.radiation = read_wamit_1(basename + ".1", scaling);
  data.excitation = read_wamit_3(basename + ".3", scaling);
  data.hydrostatic_stiffness = read_wamit_hst(basename + ".hst", scaling);
  const auto& w1 = data.radiation.angular_frequencies;
  const auto& w3 = data.excitation.angular_frequencies;
  for (size_t n = 0; n < std::max(w1.size(), w3.size()); ++n) {
    if (n >= w1.size() || n >= w3.size() || std::abs(w1[n] - w3[n]) > 1e-6 * w1[n]) {
      // Find the line of the offending period in the .3 file for the message.
      const double period = n < w3.size() ? 2 * M_PI / w3[n] : 2 * M_PI / w1[n];
      int line = 0;
      for (const Row& row : read_rows(basename + ".3"))
        if (std::abs(row.values[0] - period) <= 1e-6 * period) {
          line = row.line;
          break;
        }
      throw DataError(basename + ".3", line,
                      fmt::format("period {:g} s as frequency number {} (of {})", period, n + 1, w3.size()),
                      fmt::format("the {} periods of {}.1", w1.size(), basename));
    }
  }
  return data;
}

}  // namespace heavesim::bem
