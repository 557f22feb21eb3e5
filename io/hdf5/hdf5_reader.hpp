#pragma once
// Read-only access to the datasets of an HDF5 file, for the BEM readers (BEMIO .h5 and
// Capytaine's netCDF4 .nc, which is HDF5 underneath). Every failure is a
// hydro::DataError whose file is "<path>:<dataset path>": in an HDF5 file the dataset
// is what a line is in a text file. The message says what was found and what was
// expected, like the WAMIT reader's.
#include <hdf5.h>

#include <optional>
#include <string>
#include <vector>

#include "hydro/data_error.hpp"
#include "io/hdf5/hdf5_handle.hpp"

namespace heavesim::hdf5 {

/// A numeric dataset converted to double, values in C (row-major) order of its shape.
struct Array {
  std::vector<hsize_t> shape;  // HDF5 (C) order of the dimensions as stored
  std::vector<double> values;
};

class Reader {
 public:
  /// Opens `path` read-only; `kind` names the format for errors ("a BEMIO HDF5 file").
  Reader(std::string path, std::string kind);
  Reader(const Reader&) = delete;
  Reader& operator=(const Reader&) = delete;

  bool has(const std::string& object) const;

  /// The dataset's shape, whatever it holds.
  std::vector<hsize_t> shape(const std::string& dataset) const;
  /// A numeric dataset of any stored type, converted to double (NaN and inf kept).
  Array read(const std::string& dataset) const;
  /// A dataset holding exactly one number.
  double read_scalar(const std::string& dataset) const;
  /// A string dataset (fixed or variable length), one entry per element.
  std::vector<std::string> read_strings(const std::string& dataset) const;
  /// The dataset's string attribute `name`, if it has one.
  std::optional<std::string> text_attribute(const std::string& object, const std::string& name) const;
  /// The object's numeric attribute `name` (its first element, as double), if it has one.
  std::optional<double> number_attribute(const std::string& object, const std::string& name) const;
  /// The names of the object's attributes, in HDF5's (alphabetical) order.
  std::vector<std::string> attribute_names(const std::string& object) const;
  /// The object's attribute `name` when it is one number (integer or float, one
  /// element); nothing when it is text, a record or an array.
  std::optional<double> scalar_number_attribute(const std::string& object, const std::string& name) const;
  /// Every dataset in the file, as absolute paths, in HDF5's (alphabetical) order.
  std::vector<std::string> datasets() const;
  /// The dataset's dimension names (netCDF4: the names of the dimension scales attached
  /// to each axis, H5DS); "" for an axis with none.
  std::vector<std::string> dimension_names(const std::string& dataset) const;

  /// Fails unless the `units` attribute, when the dataset has one, is one of `accepted`.
  void check_units(const std::string& dataset, const std::vector<std::string>& accepted) const;

  /// Throws the DataError for `object` ("<path>:<object>: found ...; expected ...").
  [[noreturn]] void fail(const std::string& object, const std::string& found, const std::string& expected) const;

 private:
  Handle open_dataset(const std::string& dataset) const;

  std::string path_, kind_;
  Handle file_;
};

/// "(a, b, c)" for a shape, in messages.
std::string shape_text(const std::vector<hsize_t>& shape);

}  // namespace heavesim::hdf5
