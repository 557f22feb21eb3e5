#pragma once
// The fastest mode of a multibody system's equations linearized at a state, and what
// makes it fast: the explanation of an explicit method's instability (its step beyond
// the stability limit, a few times 1/|lambda|) and of an implicit method's step
// collapse on an undamped stiff oscillation. Error path only: allocates.
#include "kernel/system/failure_diagnosis.hpp"
#include "kernel/system/multibody_system.hpp"

namespace heavesim {

/// Linearizes the equations of motion at (t, y = [q; v; z]) on the constraint manifold's
/// tangent space (M x'' + C x' + K x + F_z z = 0, z' = R_q x + R_v x' + R_z z with x in
/// the null space of J; K includes the constraint forces' geometric stiffness) and
/// returns the eigenvalue of largest modulus, the body that moves most in it and the
/// force element, joint spring or joint limit whose modal stiffness and damping
/// dominate. Throws NumericalError if the state cannot be evaluated.
FastestMode find_fastest_mode(MultibodySystem& system, double t, const VectorX& y);

}  // namespace heavesim
