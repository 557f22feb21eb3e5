#include "app/scene/run_size.hpp"

#include <cmath>

#include <fmt/format.h>

#include "app/scene/scene.hpp"

namespace heavesim {

RunSize estimate_run_size(const CaseDefinition& definition, const Scene& scene) {
  const OutputSettings& output = definition.output;
  const Model& model = *scene.model;
  RunSize size;
  size.samples = static_cast<double>(output_sample_count(definition.solver, output.interval));
  size.columns = 1;  // time
  for (int i = 1; i < model.num_links(); ++i) {
    const Joint& joint = model.joints[i];
    if (output.bodies) size.columns += 3 + 4 + 6;
    if (output.joints && joint.nv > 0) size.columns += joint.nq + 2 * joint.nv;
    if (output.reactions) size.columns += 12;
  }
  if (model.has_constraints()) {
    size.columns += 2;
    for (const Constraint& constraint : model.constraints)
      if (constraint.is_driver())
        size.columns += 4;  // /drivers/<name>: force or torque, position, velocity, acceleration
      else if (output.reactions)
        size.columns += static_cast<long>(constraint.rows.size()) + (constraint.acts_on_frames() ? 6 : 0);
  }
  if (output.forces)
    for (const auto& element : scene.system->force_elements()) size.columns += static_cast<long>(element->channels().size());
  if (output.energy) size.columns += 3;
  return size;
}

void check_run_size(const CaseDefinition& definition, const Scene& scene) {
  const RunSize size = estimate_run_size(definition, scene);
  if (size.bytes() <= RunLimits::max_output_bytes || definition.limits.allow_large_runs) return;
  const bool interval_given = definition.sources.count("output.interval") > 0;
  const double largest_samples = RunLimits::max_output_bytes / (8.0 * static_cast<double>(size.columns));
  throw definition.error_at(
      interval_given ? "output.interval" : "solver.t_end",
      fmt::format("{} s, a result of {:.3g} GiB ({:.3g} samples x {} columns x 8 bytes; the CSV text about 3x more)",
                  interval_given ? definition.output.interval : definition.solver.t_end, size.bytes() / (1 << 30),
                  size.samples, size.columns),
      fmt::format("at most {:g} GiB of output ({:.3g} samples, an output.interval of {:.3g} s or more, or fewer "
                  "output.channels), or --allow-large-runs for a run meant to be this large",
                  RunLimits::max_output_bytes / (1 << 30), largest_samples,
                  (definition.solver.t_end - definition.solver.t_start) / (largest_samples - 1.0)));
}

}  // namespace heavesim
