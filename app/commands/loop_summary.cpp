#include <fmt/format.h>

#include "app/commands/commands.hpp"
#include "app/scene/scene.hpp"

namespace heavesim {

void print_loop_summary(const Scene& scene) {
  const Model& model = *scene.model;
  if (!model.has_constraints()) return;
  const Assembly& assembly = scene.assembly;
  fmt::print("closed loops: {} constraints, {} equations, rank {}; assembled in {} Newton iterations "
             "(largest change {:.3g} in q, {:.3g} in v; |Phi| = {:.2g})\n",
             model.constraints.size(), model.num_constraint_rows, assembly.rank.rank, assembly.newton_iterations,
             assembly.largest_position_change, assembly.largest_speed_change, assembly.position_residual);
  if (assembly.rank.redundant_rows.empty()) return;
  fmt::print("  {} redundant equations (over-constrained): {}\n"
             "  motion stays unique; multipliers are the minimum-norm solution, so the split of reactions along "
             "these directions is not unique (their resultant is)\n",
             assembly.rank.redundant_rows.size(), describe_redundant_rows(model, assembly.rank));
}

}  // namespace heavesim
