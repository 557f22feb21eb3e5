#pragma once
// The BEM targets' one body: the bytes written as a file with the format's extension and
// read by every reader of that format (radiation, excitation, hydrostatics) through
// io/bem/bem_file.hpp, as a case's hydro elements read them. The contract
// (io/bem/bem_file.hpp, hydro/bem/bem_data.hpp): bad data is a hydro::DataError, and
// what a reader returns is what hydro's types promise -- finite coefficients, at least
// one frequency, 0 < w < inf strictly ascending, headings finite and ascending, arrays
// of matching sizes. Another exception, a crash or a broken promise (a NaN or inf let
// through) is a finding.
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "fuzz/fuzz_support.hpp"
#include "io/bem/bem_file.hpp"

namespace heavesim::fuzz {

[[noreturn]] inline void broken_promise(const char* target, const char* what) {
  std::fprintf(stderr, "\n%s: a reader returned data that breaks its promise: %s\n", target, what);
  std::abort();
}

template <class Matrix>
bool all_finite(const Matrix& matrix) {
  for (Eigen::Index k = 0; k < matrix.size(); ++k)
    if (!std::isfinite(std::abs(matrix.data()[k]))) return false;
  return true;
}

inline bool ascending_frequencies(const std::vector<double>& w) {
  if (w.empty()) return false;
  for (std::size_t n = 0; n < w.size(); ++n)
    if (!(w[n] > 0.0 && std::isfinite(w[n]) && (n == 0 || w[n] > w[n - 1]))) return false;
  return true;
}

inline void check_promises(const hydro::RadiationData& data, const char* target) {
  if (!ascending_frequencies(data.angular_frequencies)) broken_promise(target, "radiation frequencies");
  const std::size_t count = data.angular_frequencies.size();
  if (data.added_mass.size() != count || data.damping.size() != count) broken_promise(target, "radiation sizes");
  for (std::size_t n = 0; n < count; ++n)
    if (!all_finite(data.added_mass[n]) || !all_finite(data.damping[n])) broken_promise(target, "A(w) or B(w)");
  if (!all_finite(data.added_mass_infinite) || !all_finite(data.added_mass_zero))
    broken_promise(target, "A(inf) or A(0)");
}

inline void check_promises(const hydro::ExcitationData& data, const char* target) {
  if (!ascending_frequencies(data.angular_frequencies)) broken_promise(target, "excitation frequencies");
  for (std::size_t h = 0; h < data.headings.size(); ++h)
    if (!std::isfinite(data.headings[h]) || (h > 0 && !(data.headings[h] > data.headings[h - 1])))
      broken_promise(target, "headings");
  if (data.headings.empty() || data.force.size() != data.headings.size()) broken_promise(target, "excitation sizes");
  for (const std::vector<hydro::ComplexVector6>& per_heading : data.force) {
    if (per_heading.size() != data.angular_frequencies.size()) broken_promise(target, "excitation sizes");
    for (const hydro::ComplexVector6& X : per_heading)
      if (!all_finite(X)) broken_promise(target, "X(w, beta)");
  }
}

inline void check_promises(const hydro::Matrix6& stiffness, const char* target) {
  if (!all_finite(stiffness)) broken_promise(target, "hydrostatic stiffness");
}

inline void read_bem_file_every_way(const std::uint8_t* data, std::size_t size, const char* file_name,
                                    const char* target) {
  const std::filesystem::path path = scratch_directory() / file_name;
  write_file(path, as_text(data, size));
  const bem::WamitScaling scaling{1025.0, 9.81, 2.0};
  auto read_checked = [&](auto read) {
    try {
      check_promises(read(path.string(), scaling), target);
    } catch (const hydro::DataError&) {
    } catch (...) {
      report_unexpected_exception(target);
    }
  };
  read_checked(bem::read_radiation_file);
  read_checked(bem::read_excitation_file);
  read_checked(bem::read_hydrostatic_stiffness_file);
}

}  // namespace heavesim::fuzz
