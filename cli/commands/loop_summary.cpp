#include <fmt/format.h>

#include "cli/commands/commands.hpp"
#include "app/scene/scene.hpp"

namespace heavesim {

void print_loop_summary(const Scene& scene) {
  const Model& model = *scene.model;
  if (!model.has_constraints()) return;
  const Assembly& assembly = scene.assembly;
  int drivers = 0, stops = 0;
  for (const Constraint& constraint : model.constraints) {
    drivers += constraint.is_driver();
    stops += constraint.is_unilateral();
  }
  fmt::print("constraints: {} ({} prescribed-motion drivers{}), {} equations, rank {}, so {} free degrees of freedom; "
             "assembled in {} Newton iterations (largest change {:.3g} in q, {:.3g} in v; |Phi| = {:.2g})\n",
             model.constraints.size(), drivers,
             stops ? fmt::format(", {} joint-stop bounds: rows only while engaged, event-located", stops) : std::string(),
             model.num_constraint_rows, assembly.rank.rank,
             model.nv - assembly.rank.rank, assembly.newton_iterations, assembly.largest_position_change,
             assembly.largest_speed_change, assembly.position_residual);
  if (assembly.rank.redundant_rows.empty()) return;
  fmt::print("  {} redundant equations (over-constrained): {}\n"
             "  motion stays unique; multipliers are the minimum-norm solution, so the split of reactions along "
             "these directions is not unique (their resultant is)\n",
             assembly.rank.redundant_rows.size(), describe_redundant_rows(model, assembly.rank));
}

}  // namespace heavesim
