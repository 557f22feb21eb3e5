#pragma once
// Root attributes and run statistics of a result file (the contract in docs/result-file.md).
#include "app/case/case_definition.hpp"
#include "app/output/result_file.hpp"
#include "app/scene/scene.hpp"
#include "kernel/integrators/integrator.hpp"

namespace heavesim {

/// The result file's case_sha256: the SHA-256 of the resolved case text, in hex. Apart from
/// write_result_metadata so that `run` can compute it beside the scene build (OpenSSL's
/// first digest sets up its providers, ~2 ms).
std::string resolved_case_sha256(const CaseDefinition& definition);

/// heavesim_version, case_name, case_sha256 (`case_sha256`: resolved_case_sha256 of the
/// definition), created_utc, complete = 0, units_system, and /case/yaml (the resolved case text).
void write_result_metadata(ResultFile& file, const CaseDefinition& definition, const std::string& case_sha256);

/// Closed loops: rows, rank, redundant rows, how multipliers were chosen, assembly
/// (attributes of /constraints); nothing for a tree.
void write_constraint_summary(ResultFile& file, const Scene& scene);
/// Integrator statistics and timing in /summary.
void write_run_statistics(ResultFile& file, const IntegratorStatistics& statistics, double wall_seconds,
                          double simulated_seconds);

}  // namespace heavesim
