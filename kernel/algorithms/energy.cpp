#include "kernel/algorithms/energy.hpp"

#include "kernel/algorithms/kinematics.hpp"

namespace heavesim {

double kinetic_energy(const Model& model, const Data& data) {
  double energy = 0.0;
  for (int i = 1; i < model.num_links(); ++i)
    energy += 0.5 * dot(data.velocity_world[i], link_momentum(model, data, i, data.velocity_world[i]));
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
