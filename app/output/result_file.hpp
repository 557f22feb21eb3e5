#pragma once
// The HDF5 result file (contract in docs/result-file.md): time series that grow in
// chunks as the run goes and are flushed to disk, so that a run stopped early still
// leaves a readable file with complete = 0.
#include <string>
#include <vector>

#include "io/hdf5/hdf5_handle.hpp"

namespace heavesim {

class ResultFile {
 public:
  /// Creates (truncates) the file; throws std::runtime_error if it cannot.
  explicit ResultFile(const std::string& path);
  ~ResultFile();
  ResultFile(const ResultFile&) = delete;
  ResultFile& operator=(const ResultFile&) = delete;

  const std::string& path() const { return path_; }

  void set_attribute(const std::string& object_path, const std::string& name, const std::string& value);
  void set_attribute(const std::string& object_path, const std::string& name, double value);
  void set_attribute(const std::string& object_path, const std::string& name, long value);
  void set_attribute(const std::string& object_path, const std::string& name, const std::vector<double>& values);

  /// A fixed string dataset (e.g. /case/yaml).
  void write_text(const std::string& dataset_path, const std::string& text, const std::string& description);

  /// A growing series: shape (N) when columns == 0, else (N, columns).
  /// Returns its id for append(); `units` and `description` become attributes.
  int add_series(const std::string& dataset_path, int columns, const std::string& units,
                 const std::string& description);
  /// Appends one row (max(columns, 1) values) to the series' in-memory buffer.
  void append(int series, const double* row);
  /// Ends one sample (a row appended to every series). The buffers go to disk only here,
  /// once a chunk of samples has accumulated: the file then holds whole samples, every
  /// series the same length, wherever the process is stopped (even by SIGKILL).
  void end_sample();
  /// Writes buffered rows of every series and flushes the file to disk.
  void flush();

 private:
  struct Series {
    hdf5::Handle dataset;
    int columns = 0;
    hsize_t rows_written = 0;
    std::vector<double> buffer;
  };
  /// The group or dataset at `object_path`, created as a group (with its parents) if missing.
  hdf5::Handle open_object(const std::string& object_path);

  std::string path_;
  hdf5::Handle file_;
  std::vector<Series> series_;
  hsize_t buffered_samples_ = 0;  // samples appended since the last flush
  static constexpr hsize_t chunk_rows = 1024;
};

}  // namespace heavesim
