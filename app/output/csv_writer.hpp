#pragma once
// Plain CSV export: one row per output time, one column per recorded value. Every write
// is checked: a full disk or a file-size limit is an OutputError naming the file, not a
// CSV cut off under a run that reports success.
#include <fstream>
#include <string>
#include <vector>

#include "app/output/output_error.hpp"

namespace heavesim {

class CsvWriter {
 public:
  /// Creates (truncates) the file; throws OutputError if it cannot.
  explicit CsvWriter(const std::string& path);
  void write_header(const std::vector<std::string>& column_names);
  void write_row(const std::vector<double>& values);
  void flush();
  /// Flushes and closes the file; throws OutputError if the last of it could not be written.
  void close();

 private:
  /// Throws OutputError with the system's cause if the stream has failed.
  void check(const char* action);

  std::string path_;
  std::ofstream out_;
};

}  // namespace heavesim
