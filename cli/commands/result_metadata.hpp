#pragma once
// Root attributes and run statistics of a result file (the contract in docs/result-file.md).
#include "app/case/case_definition.hpp"
#include "app/output/result_file.hpp"
#include "app/scene/scene.hpp"
#include "kernel/integrators/integrator.hpp"

namespace heavesim {

/// heavesim_version, case_name, case_file, case_sha256 (the SHA-256 of the resolved case
/// text, in hex), created_utc, complete = 0, units_system, frames, and /case/yaml (the
/// resolved case text).
void write_result_metadata(ResultFile& file, const CaseDefinition& definition);

/// Closed loops: rows, rank, redundant rows, how multipliers were chosen, assembly
/// (attributes of /constraints); nothing for a tree.
void write_constraint_summary(ResultFile& file, const Scene& scene);
/// Integrator statistics and timing in /summary.
void write_run_statistics(ResultFile& file, const IntegratorStatistics& statistics, double wall_seconds,
                          double simulated_seconds);

}  // namespace heavesim
