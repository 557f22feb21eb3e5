#pragma once
// The time axis of a result file as the commands that read one back (stats, rao) need it:
// the whole samples only (the first `samples_written` rows, docs/result-file.md, so that a
// file a killed or still-running run left is read as far as it is whole) and their
// uniform step, which spectra and crossing periods assume.
#include <cstddef>
#include <string>
#include <vector>

#include "io/hdf5/hdf5_reader.hpp"

namespace heavesim {

struct RecordedTime {
  std::vector<double> time;  ///< s, the whole samples
  double step = 0.0;         ///< s, (last - first) / (samples - 1)
};

/// /time of `file` (opened from `path`, which errors name), cut to samples_written. Bad
/// input (exit 2) if /time cannot be read, has fewer than `minimum_samples` whole samples
/// or a step that differs from the mean step by more than 1e-6 of it.
RecordedTime read_recorded_time(const hdf5::Reader& file, const std::string& path, std::size_t minimum_samples);

}  // namespace heavesim
