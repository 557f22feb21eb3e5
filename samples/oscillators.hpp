#pragma once
// Bodies on vertical prismatic joints: a spring-mass oscillator with optional soft
// limits, and the one- and two-slider stroke models the compensator tests and checks
// drive. Every prismatic joint here slides along world +Z (the joint frame's z axis,
// joint frame = world frame at q = 0); q is the displacement [m].
#include <memory>
#include <optional>

#include "kernel/model/model.hpp"

namespace heavesim::samples {

/// One body "block" of `mass` [kg] (CoM on the joint, unit rotational inertia
/// [kg m^2], which a pure translation never excites) on prismatic joint "slide" along
/// world Z from the ground. `stiffness` [N/m] > 0 adds a joint spring
/// tau = -stiffness q (rest 0, no damping); 0 adds none. Optional soft `limits`;
/// gravity [m/s^2, world] zero by default, so q'' = -(stiffness / mass) q.
Model prismatic_oscillator(double mass, double stiffness, std::optional<JointLimits> limits = std::nullopt,
                           const Vector3& gravity = Vector3::Zero());

/// One body ("load", mass [kg], rotational inertia mass * 1 [kg m^2]) on a prismatic
/// joint "stroke" along world z from the ground: q = stroke [m].
std::shared_ptr<const Model> vertical_slider(double mass, const Vector3& gravity = Vector3(0, 0, -9.81));

/// A base body ("base") on a vertical prismatic joint "heave" from the ground, and a
/// load ("load") on a vertical prismatic joint "stroke" from the base: q = [heave,
/// stroke] [m]; both point masses as in vertical_slider.
std::shared_ptr<const Model> base_and_load(double base_mass, double load_mass,
                                           const Vector3& gravity = Vector3(0, 0, -9.81));

}  // namespace heavesim::samples
