#pragma once
// A small HDF5 file of tables written in one go (the sweep's index.h5, `heavesim rao`'s
// rao.h5), through io/hdf5's handles: datasets of numbers, integers or texts, each with
// `units` and `description` attributes, and attributes on any object. Every failure is an
// OutputError naming the file and what it is ("the sweep index").
#include <string>
#include <vector>

#include "io/hdf5/hdf5_handle.hpp"

namespace heavesim {

class TableFile {
 public:
  /// Creates (truncates) `path`; `what` names the file in errors.
  TableFile(const std::string& path, std::string what);
  void attribute(const std::string& object, const std::string& name, const std::string& value);
  void attribute(const std::string& object, const std::string& name, double value);
  void attribute(const std::string& object, const std::string& name, long value);
  /// values row-major, `columns` per row: (rows) when columns = 1, else (rows, columns).
  void numbers(const std::string& path, const std::vector<double>& values, std::size_t columns, const std::string& units,
               const std::string& description);
  void integers(const std::string& path, const std::vector<long>& values, const std::string& description);
  void texts(const std::string& path, const std::vector<std::string>& values, const std::string& description);
  void close();

 private:
  void write(const std::string& path, hid_t file_type, hid_t memory_type, int rank, const hsize_t* dims, const void* data,
             const std::string& units, const std::string& description);
  void write_attribute(const std::string& object, const std::string& name, hid_t type, hid_t space, const void* data);
  void check(bool succeeded, const std::string& action);
  std::string path_, what_;
  hdf5::Handle file_;
};

}  // namespace heavesim
