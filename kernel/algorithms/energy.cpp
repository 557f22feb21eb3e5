#include "kernel/algorithms/energy.hpp"

#include <stdexcept>

namespace heavesim {

double kinetic_energy(const Model& model, const Data& data) {
  // The momenta are the velocity stage's: after another position stage they would be a
  // configuration's other than the placements and inertias around them.
  if (!(data.stages.current & StageMarker::velocities))
    throw std::logic_error("kinetic_energy: the velocity stage of this Data is not current");
  double energy = 0.0;
  // The velocity stage's momenta h_i = I_i v_i: recomputing them was 1.3 % of the drilling
  // run's instructions (its energy channels read this once a sample).
  for (int i = 1; i < model.num_links(); ++i) energy += 0.5 * dot(data.velocity_world[i], data.momentum_world[i]);
  return energy;
}

double gravity_potential_energy(const Model& model, const Data& data) {
  double energy = 0.0;
  for (int i = 1; i < model.num_links(); ++i) {
    const Inertia& inertia = model.links[i].inertia;
    energy -= inertia.mass() * model.gravity.dot(data.X_world_link[i].act_point(inertia.com()));
  }
  return energy;
}

}  // namespace heavesim
