#pragma once
// The sweep's index: DIR/index.h5 and DIR/index.csv, one row per run in plan order
// (docs/sweeps.md states the layout; the operability analysis reads it).
#include <string>
#include <vector>

#include "app/sweep/run_record.hpp"
#include "app/sweep/sweep_plan.hpp"

namespace heavesim {

/// Writes DIR/index.h5 (built as index.h5.partial and renamed when whole) and
/// DIR/index.csv. `records` holds one record per run of `plan`, in plan order.
/// Throws OutputError when a file cannot be written.
void write_sweep_index(const std::string& directory, const SweepDefinition& sweep, const SweepPlan& plan,
                       const std::vector<RunRecord>& records);

}  // namespace heavesim
