#include "cli/commands/result_metadata.hpp"

#include <fmt/format.h>

#include "app/case/sha256.hpp"
#include "app/output/utc_now.hpp"
#include "app/version.hpp"

namespace heavesim {

void write_result_metadata(ResultFile& file, const CaseDefinition& definition) {
  file.set_attribute("/", "heavesim_version", std::string(heavesim_version));
  file.set_attribute("/", "case_name", definition.name);
  file.set_attribute("/", "case_file", definition.source_path);
  file.set_attribute("/", "case_sha256", sha256_hex(definition.resolved_yaml));
  file.set_attribute("/", "created_utc", utc_now());
  file.set_attribute("/", "complete", 0L);
  file.set_attribute("/", "units_system", std::string("SI"));
  file.set_attribute("/", "frames", std::string("world: Z up, origin on the mean free surface; "
                                                "spatial vectors [angular; linear]; quaternions w, x, y, z"));
  file.write_text("/case/yaml", definition.resolved_yaml, "the resolved case (after include and --set)");
}

void write_constraint_summary(ResultFile& file, const Scene& scene) {
  const Model& model = *scene.model;
  if (!model.has_constraints()) return;
  const Assembly& assembly = scene.assembly;
  file.set_attribute("/constraints", "rows", static_cast<long>(model.num_constraint_rows));
  file.set_attribute("/constraints", "rank", static_cast<long>(assembly.rank.rank));
  file.set_attribute("/constraints", "redundant_rows", describe_redundant_rows(model, assembly.rank));
  file.set_attribute("/constraints", "multipliers",
                     std::string(assembly.rank.redundant_rows.empty()
                                     ? "unique"
                                     : "minimum-norm: the split of reactions along redundant rows is not unique; "
                                       "their resultant is"));
  file.set_attribute("/constraints", "assembly_newton_iterations", static_cast<long>(assembly.newton_iterations));
  file.set_attribute("/constraints", "assembly_largest_position_change", assembly.largest_position_change);
  file.set_attribute("/constraints", "assembly_largest_speed_change", assembly.largest_speed_change);
  file.set_attribute("/constraints", "assembly_position_residual", assembly.position_residual);
}

void write_run_statistics(ResultFile& file, const IntegratorStatistics& statistics, double wall_seconds,
                          double simulated_seconds) {
  file.set_attribute("/summary", "integrator_steps", statistics.steps);
  file.set_attribute("/summary", "rhs_evaluations", statistics.rhs_evaluations);
  file.set_attribute("/summary", "jacobian_evaluations", statistics.jacobian_evaluations);
  file.set_attribute("/summary", "error_test_failures", statistics.error_test_failures);
  file.set_attribute("/summary", "nonlinear_iterations", statistics.nonlinear_iterations);
  file.set_attribute("/summary", "convergence_failures", statistics.convergence_failures);
  file.set_attribute("/summary", "wall_time_s", wall_seconds);
  file.set_attribute("/summary", "simulated_time_s", simulated_seconds);
  file.set_attribute("/summary", "real_time_factor", wall_seconds > 0.0 ? simulated_seconds / wall_seconds : 0.0);
  file.flush();
}

}  // namespace heavesim
