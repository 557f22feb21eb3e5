#include "io/bem/bem_arrays.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include <fmt/format.h>

#include "io/bem/wamit_reader.hpp"

namespace heavesim::bem {
namespace {

std::vector<std::size_t> ascending_order(const std::vector<double>& values) {
  std::vector<std::size_t> order(values.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return values[a] < values[b]; });
  return order;
}

template <class T>
std::vector<T> permuted(const std::vector<T>& values, const std::vector<std::size_t>& order) {
  std::vector<T> result;
  result.reserve(order.size());
  for (std::size_t k : order) result.push_back(values[k]);
  return result;
}

void check_distinct(const hdf5::Reader& file, const std::string& dataset, const std::vector<double>& sorted,
                    const char* what, const char* unit) {
  for (std::size_t k = 1; k < sorted.size(); ++k)
    if (sorted[k] == sorted[k - 1])
      file.fail(dataset, fmt::format("the {} {:g} {} twice", what, sorted[k], unit), fmt::format("distinct {}s", what));
}

void require_a_finite_frequency(const hdf5::Reader& file, const std::string& dataset,
                                const std::vector<double>& angular_frequencies) {
  if (angular_frequencies.empty())
    file.fail(dataset, "no frequency 0 < w < inf (only w = 0 or w = inf entries)",
              "the finite frequencies of the BEM run: the coefficients at w = 0 and w = inf alone give no "
              "radiation damping or wave excitation");
}

}  // namespace

AxisArray::AxisArray(hdf5::Array array, const std::vector<int>& logical_to_stored) : array_(std::move(array)) {
  std::vector<std::size_t> stored_strides(array_.shape.size(), 1);
  for (int axis = static_cast<int>(array_.shape.size()) - 2; axis >= 0; --axis)
    stored_strides[axis] = stored_strides[axis + 1] * array_.shape[axis + 1];
  for (int stored : logical_to_stored) {
    strides_.push_back(stored_strides[stored]);
  }
}

double AxisArray::at(std::initializer_list<std::size_t> logical_index) const {
  std::size_t offset = 0, axis = 0;
  for (std::size_t index : logical_index) offset += index * strides_[axis++];
  return array_.values[offset];
}

void check_finite(const hdf5::Reader& file, const std::string& dataset, double value, const std::string& what) {
  if (!std::isfinite(value)) file.fail(dataset, fmt::format("{} = {}", what, value), "finite numbers");
}

double dimensional(const hdf5::Reader& file, const std::string& dataset, double stored, double factor,
                   const std::string& what) {
  check_finite(file, dataset, stored, what);
  const double value = factor * stored;
  if (!std::isfinite(value))
    file.fail(dataset, fmt::format("{} = {:g}, which overflows to {} once scaled by {:g}", what, stored, value, factor),
              "values whose dimensional (scaled) value is a finite number");
  return value;
}

void symmetrise_checked(const hdf5::Reader& file, const std::string& dataset, hydro::Matrix6& M, const char* what,
                        const std::string& at) {
  for (int i = 0; i < 6; ++i)
    for (int j = i + 1; j < 6; ++j) {
      const double scale = std::sqrt(std::abs(M(i, i))) * std::sqrt(std::abs(M(j, j)));  // no overflow
      if (std::abs(M(i, j) - M(j, i)) > bem::bem_symmetry_tolerance * scale + 1e-300)
        file.fail(dataset,
                  fmt::format("{}({},{}) = {:.6g} but {}({},{}) = {:.6g} {}", what, i + 1, j + 1, M(i, j), what, j + 1,
                              i + 1, M(j, i), at),
                  fmt::format("a symmetric matrix (within {} of sqrt({}_ii {}_jj))", bem::bem_symmetry_tolerance,
                              what, what));
      M(i, j) = M(j, i) = 0.5 * M(i, j) + 0.5 * M(j, i);  // halves: the sum may overflow
    }
}

void sort_by_frequency(const hdf5::Reader& file, const std::string& dataset, hydro::RadiationData& data) {
  require_a_finite_frequency(file, dataset, data.angular_frequencies);
  const std::vector<std::size_t> order = ascending_order(data.angular_frequencies);
  data.angular_frequencies = permuted(data.angular_frequencies, order);
  data.added_mass = permuted(data.added_mass, order);
  data.damping = permuted(data.damping, order);
  check_distinct(file, dataset, data.angular_frequencies, "frequency", "rad/s");
}

void sort_by_frequency_and_heading(const hdf5::Reader& file, const std::string& dataset,
                                   hydro::ExcitationData& data) {
  require_a_finite_frequency(file, dataset, data.angular_frequencies);
  const std::vector<std::size_t> frequencies = ascending_order(data.angular_frequencies);
  const std::vector<std::size_t> headings = ascending_order(data.headings);
  data.angular_frequencies = permuted(data.angular_frequencies, frequencies);
  data.headings = permuted(data.headings, headings);
  data.force = permuted(data.force, headings);
  for (auto& per_heading : data.force) per_heading = permuted(per_heading, frequencies);
  check_distinct(file, dataset, data.angular_frequencies, "frequency", "rad/s");
  check_distinct(file, dataset, data.headings, "heading", "rad");
}

}  // namespace heavesim::bem
