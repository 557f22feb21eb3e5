#include "hydro/elements/nonlinear_hydrostatics.hpp"

#include "hydro/elements/body_motion.hpp"

namespace heavesim::hydro {

NonlinearHydrostatics::NonlinearHydrostatics(std::string name, int link, HullMesh mesh, double density, double gravity)
    : name_(std::move(name)), link_(link), mesh_(std::move(mesh)), density_(density), gravity_(gravity) {
  channels_ = {{"displaced_volume", "m^3", "submerged hull volume below z = 0"},
               {"buoyancy_force_z", "N", "vertical hydrostatic force on the hull, world z, positive up"},
               {"centre_of_buoyancy_x", "m", "centre of buoyancy, world x"},
               {"centre_of_buoyancy_y", "m", "centre of buoyancy, world y"},
               {"centre_of_buoyancy_z", "m", "centre of buoyancy, world z"}};
}

WettedHull NonlinearHydrostatics::wetted(const Model& model, const Data& data) const {
  return wetted_hull(mesh_, data.X_world_link[link_] * model.links[link_].X_link_body, density_, gravity_);
}

void NonlinearHydrostatics::apply(double, const Model& model, const Data& data, Eigen::Ref<const VectorX>,
                                  AppliedForces& forces) const {
  const WettedHull hull = wetted(model, data);
  // wetted_hull's moment is already about the world origin, as the kernel wants.
  forces.external_force_world[link_] += Force(hull.buoyancy_moment, hull.buoyancy_force);
}

void NonlinearHydrostatics::outputs(double, const Model& model, const Data& data, Eigen::Ref<const VectorX>,
                                    std::span<double> values) const {
  const WettedHull hull = wetted(model, data);
  values[0] = hull.volume;
  values[1] = hull.buoyancy_force.z();
  values[2] = hull.centre_of_buoyancy.x();
  values[3] = hull.centre_of_buoyancy.y();
  values[4] = hull.centre_of_buoyancy.z();
}

}  // namespace heavesim::hydro
