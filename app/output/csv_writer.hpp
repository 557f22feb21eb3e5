#pragma once
// Plain CSV export: one row per output time, one column per recorded value.
#include <fstream>
#include <string>
#include <vector>

namespace heavesim {

class CsvWriter {
 public:
  /// Creates (truncates) the file; throws std::runtime_error if it cannot.
  explicit CsvWriter(const std::string& path);
  void write_header(const std::vector<std::string>& column_names);
  void write_row(const std::vector<double>& values);
  void flush() { out_.flush(); }

 private:
  std::ofstream out_;
};

}  // namespace heavesim
