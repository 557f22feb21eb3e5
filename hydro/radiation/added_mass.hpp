#pragma once
// Infinite-frequency added mass A(inf) as part of the body's spatial inertia (Cummins
// 1962: (M + A(inf)) x'' + int K x' + C x = F; docs/physics/hydrodynamics.md §2-3): no lagged
// force, no algebraic loop. BEM data are in WAMIT order [surge, sway, heave, roll,
// pitch, yaw] = [linear; angular] about the BEM reference point; the kernel wants
// [angular; linear] (Featherstone) about the body frame origin, body axes
// (BodyDefinition::added_inertia). Like a rigid inertia, the 6x6 moves with the body.
#include "kernel/spatial/inertia.hpp"

namespace heavesim::hydro {

/// Reorders a WAMIT-ordered 6x6 ([linear; angular]) to the kernel's [angular; linear]
/// (and back: the permutation is its own inverse).
Matrix6 swap_linear_angular(const Matrix6& wamit_order);

/// A(inf) [kg, kg m, kg m^2], WAMIT order about the BEM reference point, whose
/// position in the body frame is r [m] (axes parallel to the body's), as the kernel's
/// added_inertia about the body frame origin. Symmetrised.
Matrix6 added_inertia_in_body_frame(const Matrix6& added_mass_wamit, const Vector3& bem_reference_in_body = Vector3::Zero());

}  // namespace heavesim::hydro
