#pragma once
// Nonlinear hydrostatics + Froude-Krylov as a force element: the incident-wave and
// hydrostatic pressure on the hull below the instantaneous incident surface
// (froude_krylov.hpp), every evaluation. Use instead of NonlinearHydrostatics, and with
// only the diffraction part of the BEM excitation (or none), never with the full X.
// No allocation in apply().
#include "hydro/hydrostatics/froude_krylov.hpp"
#include "kernel/elements/force_element.hpp"

namespace heavesim::hydro {

class FroudeKrylovForce : public ForceElement {
 public:
  FroudeKrylovForce(std::string name, int link, HullMesh mesh, WaveTrain waves, double density = 1025.0,
                    double gravity = 9.81)
      : name_(std::move(name)), link_(link), mesh_(std::move(mesh)), waves_(std::move(waves)), density_(density),
        gravity_(gravity) {}
  const std::string& name() const override { return name_; }
  void apply(double t, const Model& model, const Data& data, Eigen::Ref<const VectorX>,
             AppliedForces& forces) const override {
    const FroudeKrylovLoad load = froude_krylov_load(mesh_, data.X_world_link[link_] * model.links[link_].X_link_body,
                                                     waves_, t, density_, gravity_);
    forces.external_force_world[link_] += Force(load.moment, load.force);  // moment already about the world origin
  }
  /// Time (the incident wave) and the body's pose.
  ElementDependencies dependencies() const override { return {true, true, false, false, false}; }

 private:
  std::string name_;
  int link_;
  HullMesh mesh_;
  WaveTrain waves_;
  double density_, gravity_;
};

}  // namespace heavesim::hydro
