#pragma once
// The plug-in point for everything outside the kernel that pushes on bodies:
// hydrostatics, radiation, waves, mooring, pneumatic and hydraulic compensators,
// controllers. The kernel knows only this interface.
#include <span>
#include <string>
#include <vector>

#include "kernel/model/data.hpp"

namespace heavesim {

/// Loads applied to the multibody system during one evaluation.
struct AppliedForces {
  explicit AppliedForces(const Model& model)
      : external_force_world(model.num_links(), Force::Zero()), joint_force(VectorX::Zero(model.nv)) {}
  void clear() {
    for (Force& f : external_force_world) f = Force::Zero();
    joint_force.setZero();
  }
  /// Adds a force f [N] acting at point p [m] (both world frame) on link i.
  void add_force_at_point(int link, const Vector3& point_world, const Vector3& force_world) {
    external_force_world[link] += Force::at_point(point_world, force_world);
  }

  AlignedVector<Force> external_force_world;  // per link, world coordinates about the world origin
  VectorX joint_force;                        // nv, generalized forces along joint coordinates
};

/// One scalar output of a force element (a gas pressure, a stroke, a valve flow), for
/// recorders: its name, SI units and a description that states sign and frame.
struct ElementChannel {
  std::string name;         // e.g. "gas_pressure"; unique within the element
  std::string units;        // e.g. "Pa"
  std::string description;  // what it is, its sign convention and frame
};

/// What an element's loads (apply) and state rates (state_derivative) can depend on.
/// The implicit forms difference the applied forces column by column in q, v and z
/// (DynamicsDifferentiator); a column group that no element (and no joint element)
/// depends on is exactly zero and is skipped. Conservative by default: everything.
struct ElementDependencies {
  bool time = true;            // t [s] (waves, prescribed loads)
  bool configuration = true;   // q, through the position stage (where a point or body is)
  bool velocity = true;        // v, through the velocity stage (world velocities depend on q too)
  bool element_states = true;  // its own z
  /// The evaluations before this one: a load that is not a function of (t, q, v, z) alone
  /// (a convolution over the velocities it stored at earlier calls; contact loads a
  /// stepper set). Without it, a second copy of the system gives the same loads at the
  /// same (t, y), so the recorder may evaluate its samples on one (app/output/recorder.hpp).
  bool history = true;
};

/// A force element may own internal states z with dz/dt = g(t, q, v, z)
/// (radiation memory, gas temperature, chamber pressures, controller integrators).
/// apply() and state_derivative() see the position and velocity stages in Data.
/// Its const methods may keep what they computed (a convolution's history, the last
/// evaluation: evaluation_key.hpp): one element is called by one thread at a time, and
/// a second thread works on a second build of the scene.
class ForceElement {
 public:
  virtual ~ForceElement() = default;
  virtual const std::string& name() const = 0;

  virtual int state_size() const { return 0; }
  virtual void initial_state(Eigen::Ref<VectorX> /*z*/) const {}

  /// Adds this element's loads at time t [s] for internal state z.
  virtual void apply(double t, const Model& model, const Data& data, Eigen::Ref<const VectorX> z,
                     AppliedForces& forces) const = 0;

  virtual void state_derivative(double /*t*/, const Model& /*model*/, const Data& /*data*/,
                                Eigen::Ref<const VectorX> /*z*/, Eigen::Ref<VectorX> /*zdot*/) const {}

  /// What apply() and state_derivative() read (see ElementDependencies); the default,
  /// everything, is always correct.
  virtual ElementDependencies dependencies() const { return {}; }

  /// The element's stored potential energy [J] at the stages in Data and state z, for
  /// the energy channels: V with the conservative part of the load = -dV/d(position)
  /// (springs, gas, restoring). 0 for elements that store none (dampers, excitation).
  virtual double potential_energy(const Model& /*model*/, const Data& /*data*/, Eigen::Ref<const VectorX> /*z*/) const {
    return 0.0;
  }

  /// The element's output channels, fixed once the element is built (none by default).
  virtual const std::vector<ElementChannel>& channels() const {
    static const std::vector<ElementChannel> none;
    return none;
  }
  /// Values of channels() at time t for state z, on the stages in Data (as apply()
  /// sees them); values.size() == channels().size(). Must write every value (the
  /// recorder records one left unwritten as NaN) and not allocate.
  virtual void outputs(double /*t*/, const Model& /*model*/, const Data& /*data*/, Eigen::Ref<const VectorX> /*z*/,
                       std::span<double> /*values*/) const {}
};

}  // namespace heavesim
