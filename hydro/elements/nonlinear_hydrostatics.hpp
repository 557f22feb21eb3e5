#pragma once
// Buoyancy of a panel hull by clipping at the still-water plane at every evaluation
// (wetted_hull.hpp): force and moment of the hydrostatic pressure rho g (-z) on the
// instantaneous wetted surface. Gravity is the kernel's; no allocation in apply().
#include "hydro/hydrostatics/wetted_hull.hpp"
#include "kernel/elements/force_element.hpp"

namespace heavesim::hydro {

class NonlinearHydrostatics : public ForceElement {
 public:
  /// mesh in the body frame of the body on `link`; density [kg/m^3], gravity [m/s^2].
  NonlinearHydrostatics(std::string name, int link, HullMesh mesh, double density = 1025.0, double gravity = 9.81);
  const std::string& name() const override { return name_; }
  void apply(double t, const Model& model, const Data& data, Eigen::Ref<const VectorX> z,
             AppliedForces& forces) const override;
  /// The body's pose only (the still-water surface).
  ElementDependencies dependencies() const override { return {false, true, false, false, false}; }
  const std::vector<ElementChannel>& channels() const override { return channels_; }
  void outputs(double t, const Model& model, const Data& data, Eigen::Ref<const VectorX> z,
               std::span<double> values) const override;
  /// The wetted hull at the current position stage.
  WettedHull wetted(const Model& model, const Data& data) const;

 private:
  std::string name_;
  int link_;
  HullMesh mesh_;
  double density_, gravity_;
  std::vector<ElementChannel> channels_;
};

}  // namespace heavesim::hydro
