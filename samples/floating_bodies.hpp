#pragma once
// Floating bodies for the hydrodynamic tests and checks: a body on a free joint, and
// the MSS semi-submersible on a vertical slide.
#include <memory>
#include <optional>
#include <string>

#include "kernel/model/model.hpp"

namespace heavesim::samples {

/// One body `body_name` with `inertia` (mass, CoM and inertia about the CoM in the body
/// frame, SI) and an optional `added_inertia` (6x6, body frame about its origin,
/// [angular; linear]) on the free joint "float" from the ground; the body frame
/// coincides with the world frame at the neutral configuration. q = [position (m,
/// world); quaternion w, x, y, z], v = [angular; linear] in body axes. Gravity
/// `gravity` [m/s^2, world].
std::shared_ptr<const Model> free_floating_body(const std::string& body_name, const Inertia& inertia,
                                                const std::optional<Matrix6>& added_inertia = std::nullopt,
                                                const Vector3& gravity = Vector3(0, 0, -9.81));

/// Mass [kg] of the MSS semi-submersible (data/mss_semisub/semisub.frc).
inline constexpr double mss_semisub_mass = 51979800.0;

/// The MSS semi-submersible "semisub" on the prismatic joint "heave" along world Z:
/// body frame origin = the BEM reference point on the mean free surface, CoG 0.5 m
/// below it, radii of gyration from semisub.frc (inertia diag(5.66e10, 6.01e10,
/// 7.31e10) kg m^2 about the CoG), `added_inertia` = A(inf) in the body frame about
/// its origin, [angular; linear] (kernel order). q = heave [m]; gravity 9.81 m/s^2
/// along world -Z.
std::shared_ptr<const Model> heaving_mss_semisub(const Matrix6& added_inertia);

}  // namespace heavesim::samples
