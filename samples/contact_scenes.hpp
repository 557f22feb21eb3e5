#pragma once
// Contact scenes for the tests, the validation checks (P3, P4) and the benchmarks:
// boxes and spheres on free joints above a ground plane. Every body frame is the body's
// centre of mass with principal axes; q is the free joints' (position [m, world],
// quaternion w, x, y, z) per body, v their (angular; linear) in body axes.
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "kernel/contact/contact_model.hpp"
#include "kernel/model/model.hpp"

namespace heavesim::samples {

struct ContactScene {
  std::shared_ptr<const Model> model;
  ContactModel contacts;
  VectorX q;                    ///< initial configuration
  VectorX v;                    ///< initial velocity (zero unless said)
  std::vector<double> masses;   ///< kg, per body in link order (link i+1 = body i)
};

/// `count` cubes of edge `edge` [m] stacked on the ground plane z = 0, touching exactly,
/// masses from `bottom_mass` [kg] geometrically to mass_ratio x bottom_mass at the top;
/// one pair per touching faces (4 corner points each) with Coulomb coefficient `mu`.
ContactScene box_stack(int count, double edge, double bottom_mass, double mass_ratio, double mu);

/// A box (half sizes `half_extents` [m], `mass` [kg]) resting on an incline through the
/// origin, turned by `slope` [rad] about the world y axis (down-slope: the plane's +x,
/// (cos slope, 0, -sin slope)); Coulomb coefficient mu.
ContactScene box_on_incline(double slope, double mu, const Vector3& half_extents, double mass);

/// A solid sphere (radius, mass) with its centre `height` [m] above the ground plane
/// z = 0 (height = radius: resting on it), friction mu and restitution e.
ContactScene sphere_on_plane(double radius, double mass, double height, double mu, double restitution);

/// A deck moved by prescribed motions (regular-sea surge and heave of a platform):
///   surge x_d(t) = surge_amplitude sin(omega t), heave z_d(t) = heave_amplitude sin(omega t + phase)
/// [m, rad/s, rad] through the joint drivers "surge" (prismatic x, ground -> "carriage") and
/// "heave" (prismatic z, carriage -> "deck"); the deck's top is the plane z = z_d. A box
/// (half sizes `half_extents`, `mass`) rests on it, moving with it at t = 0; Coulomb mu.
struct MovingDeck {
  double surge_amplitude = 3.0, heave_amplitude = 2.0, omega = 1.0, phase = M_PI / 3;
};
ContactScene box_on_moving_deck(const MovingDeck& deck, double mu, const Vector3& half_extents, double mass);

/// A solid cylinder (radius, half_length [m], mass [kg]) standing on its end on the
/// ground plane z = 0, its axis along z and its centre at z = half_length: a drill bit
/// on the formation, touching at four rim points. Spun at `spin` [rad/s] about z.
ContactScene standing_cylinder_on_plane(double radius, double half_length, double mass, double mu, double spin);

/// A load hanging on a tension line from a tip that heaves: the tip (body "tip") on a
/// prismatic z joint driven by z_tip(t) = amplitude sin(omega t) [m, rad/s] (driver
/// "tip_motion"), the load (body "load", `mass` [kg]) on its own prismatic z joint from
/// the ground, the line (`length` [m]) from the tip's origin to the load's. At t = 0 the
/// line is taut and the load moves with the tip.
struct HeavingTip {
  double amplitude = 1.0, omega = 4.0;
};
ContactScene load_on_heaving_line(const HeavingTip& tip, double length, double mass, double restitution);

/// A load resting on a floor that heaves, by a one-sided joint stop rather than a
/// contact pair (the event-located stop of kernel/system/joint_stop_events.hpp): the
/// floor (body "floor") on a prismatic z joint driven by z_floor(t) = amplitude sin(omega
/// t) (driver "floor_motion"; amplitude 0: still), the load (body "load", `mass` [kg]) on
/// a prismatic z joint "lift" from the floor, its height above it s >= 0 by the stop
/// "lift.lower" at s = 0 (restitution e). Initial state: the load at height `drop` above
/// the floor, at rest (drop = 0: on it, moving with it).
struct StopScene {
  std::shared_ptr<const Model> model;
  VectorX q, v;
};
StopScene load_on_heaving_floor(const HeavingTip& floor, double mass, double restitution, double drop);

}  // namespace heavesim::samples
