// Reads and interpolates tabulated motions (docs/case-format.md, "drivers[i]", `table`).
#include "app/case/motion_table.hpp"

#include <Eigen/SparseLU>

#include <charconv>
#include <cmath>
#include <fstream>
#include <stdexcept>

#include <fmt/format.h>

#include "hydro/data_error.hpp"
#include "hydro/data_file.hpp"

namespace heavesim {

namespace {

using Spline = Eigen::Spline<double, 1, 3>;

/// The row's text without surrounding blanks.
std::string_view trimmed(std::string_view text) {
  const std::size_t first = text.find_first_not_of(" \t\r");
  if (first == std::string_view::npos) return {};
  return text.substr(first, text.find_last_not_of(" \t\r") - first + 1);
}

}  // namespace

MotionTable::MotionTable(const std::vector<double>& times, const std::vector<double>& values) {
  const Eigen::Index n = static_cast<Eigen::Index>(times.size());
  if (n < minimum_rows || values.size() != times.size())
    throw std::invalid_argument("a motion table needs at least 4 samples");
  for (Eigen::Index i = 1; i < n; ++i)
    if (!(times[i] > times[i - 1])) throw std::invalid_argument("a motion table's times must increase");
  start_ = times.front();
  end_ = times.back();
  // Data sites in u = (t - t_0)/(t_n - t_0), the spline's parameter on [0, 1].
  Spline::KnotVectorType sites(n);
  for (Eigen::Index i = 0; i < n; ++i) sites(i) = (times[i] - start_) / (end_ - start_);
  sites(n - 1) = 1.0;
  Spline::KnotVectorType knots;
  Eigen::KnotAveraging(sites, 3, knots);
  // Interpolation conditions sum_j N_j(u_i) c_j = f_i: only the 4 basis functions of u_i's
  // knot span are nonzero, so the collocation matrix is banded (de Boor ch. XIII).
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(4 * n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const Eigen::Index span = Spline::Span(sites(i), 3, knots);
    const Spline::BasisVectorType basis = Spline::BasisFunctions(sites(i), 3, knots);
    for (Eigen::Index k = 0; k < 4; ++k) entries.emplace_back(i, span - 3 + k, basis(k));
  }
  Eigen::SparseMatrix<double> collocation(n, n);
  collocation.setFromTriplets(entries.begin(), entries.end());
  Eigen::SparseLU<Eigen::SparseMatrix<double>> solver(collocation);
  if (solver.info() != Eigen::Success) throw std::invalid_argument("the spline's collocation matrix is singular");
  const Eigen::VectorXd controls = solver.solve(Eigen::Map<const Eigen::VectorXd>(values.data(), n));
  spline_ = Spline(knots, controls.transpose());
}

DriverMotion MotionTable::operator()(double t) const {
  const double duration = end_ - start_;
  const auto derivatives = spline_.derivatives<2>((t - start_) / duration);  // d^k f / du^k, k = 0, 1, 2
  return {derivatives(0, 0), derivatives(0, 1) / duration, derivatives(0, 2) / (duration * duration)};
}

MotionTable MotionTable::read_csv(const std::string& path) {
  hydro::require_readable_data_file(path, "motion table (CSV)");
  std::ifstream in(path);
  if (!in) throw hydro::DataError(path, 0, "a file that cannot be opened", "a readable CSV file");
  const std::string expected = "a header line, then rows 'time [s], value' of two finite numbers, times increasing";
  std::vector<double> times, values;
  std::string line;
  int number = 0;
  int last_row_line = 0;
  while (std::getline(in, line)) {
    ++number;
    if (number == 1) continue;  // the header
    const std::string_view row = trimmed(line);
    if (row.empty()) continue;
    const std::size_t comma = row.find(',');
    if (comma == std::string_view::npos || row.find(',', comma + 1) != std::string_view::npos)
      throw hydro::DataError(path, number, fmt::format("'{}', not two comma-separated columns", row), expected);
    double cells[2];
    const std::string_view texts[2] = {trimmed(row.substr(0, comma)), trimmed(row.substr(comma + 1))};
    for (int column = 0; column < 2; ++column) {
      const char* end = texts[column].data() + texts[column].size();
      const auto [stop, error] = std::from_chars(texts[column].data(), end, cells[column]);
      if (error != std::errc() || stop != end || texts[column].empty())
        throw hydro::DataError(path, number, fmt::format("'{}' in column {}, not a number", texts[column], column + 1),
                               expected);
      if (!std::isfinite(cells[column]))
        throw hydro::DataError(path, number, fmt::format("'{}' in column {}, not finite", texts[column], column + 1),
                               expected);
    }
    if (!times.empty() && !(cells[0] > times.back()))
      throw hydro::DataError(path, number,
                             fmt::format("time {:g} s after {:g} s (line {})", cells[0], times.back(), last_row_line),
                             expected);
    times.push_back(cells[0]);
    values.push_back(cells[1]);
    last_row_line = number;
  }
  if (static_cast<int>(times.size()) < minimum_rows)
    throw hydro::DataError(path, number, fmt::format("{} rows of samples", times.size()),
                           fmt::format("at least {} rows (a cubic spline needs four samples)", minimum_rows));
  return MotionTable(times, values);
}

}  // namespace heavesim
