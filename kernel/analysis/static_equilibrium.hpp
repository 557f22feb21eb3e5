#pragma once
// Static equilibrium of a multibody system with its force elements and constraints
// (Haug 1989, sec. 6.4 "static equilibrium analysis"; Geradin & Cardona 2001, ch. 10):
// the rest state y = [q; v = 0; z] and multipliers lambda with
//   r(q, lambda, z) = ID(q, 0, 0) - Q(t, q, 0, z) - J(q)^T lambda = 0   (nv; N or N m)
//   Phi(q, t) = 0                                                   (m; m or rad)
//   g(t, q, 0, z) = 0                                               (element states with a rest)
// at a fixed time t (drivers held at f(t)). ID at zero speed and acceleration is the
// weight (the kernel applies gravity as m g at each CoM) less the applied loads, so r
// is minus the generalized force of everything acting, constraint forces included.
//
// Newton's method with a backtracking line search on the unknowns (tangent steps dq in
// velocity coordinates, mapped by integrate_configuration; lambda; the states z that
// have a rest), the tangent matrix
//   [ dr/dq   -J^T   dr/dz ]    dr/dq = dID/dq - dQ/dq - d(J^T lambda)/dq: the
//   [ J        0      0    ]    stiffness (DynamicsDifferentiator: analytic for the
//   [ dg/dq    0     dg/dz ]    rigid bodies, differences for the elements)
// solved in the least-squares, minimum-norm sense (column-pivoted complete orthogonal
// decomposition of the equilibrated matrix): a direction nothing loads or restrains (a
// free body's surge with no mooring) gets no step, so the solve does not wander along it.
// A residual outside the matrix's range means there is no equilibrium: the load along
// that direction has nothing to balance it (a free body under gravity alone).
//
// Stability (Lagrange-Dirichlet): the stiffness reduced to the directions the
// constraints allow, N^T K N, with the element states condensed out, against the mass
// matrix there: K x = w^2 M x. All w^2 > 0: stable; one w^2 < 0: unstable (a pendulum
// upside down); w^2 = 0 within round-off: neutral (a free direction).
#include <string>
#include <vector>

#include "kernel/system/multibody_system.hpp"

namespace heavesim {

struct EquilibriumSettings {
  /// Converged when max |r| <= tolerance * load_scale, max |Phi| <= tolerance [m or rad]
  /// and max |g| <= tolerance [element states are of order one, per s].
  double tolerance = 1e-10;
  int max_iterations = 50;  // Newton iterations
};

enum class EquilibriumStability { stable, neutral, unstable };

struct EquilibriumResult {
  VectorX state;        // y = [q; 0; z] at rest
  VectorX multipliers;  // lambda (m; N or N m), minimum norm over redundant rows
  int iterations = 0;   // Newton iterations taken
  double load_scale = 0.0;          // the largest load [N]: weights, applied forces, joint forces, multipliers
  double force_residual = 0.0;      // max |r| / load_scale
  double constraint_residual = 0.0;  // max |Phi| [m or rad]
  double rate_residual = 0.0;       // max |g| over the states with a rest
  /// Element states (indices into z) whose rates do not depend on q or z at rest (no
  /// rest value: they were held at their initial values).
  std::vector<int> held_states;
  EquilibriumStability stability = EquilibriumStability::stable;
  double lowest_squared_frequency = 0.0;  // smallest Re(w^2) of K x = w^2 M x on the manifold [1/s^2]
  VectorX lowest_mode;                    // its shape in velocity coordinates (nv), largest entry 1
  int neutral_directions = 0;             // how many w^2 are zero within round-off
};

/// The rest state nearest (in Newton's sense) to y_guess at time t. y_guess's speeds are
/// ignored; its q is the starting guess, its z the starting (and, for held states,
/// final) element states. Throws NumericalError when there is no equilibrium (naming the
/// unbalanced coordinate and its world direction) or Newton does not converge (naming
/// the largest residual).
EquilibriumResult solve_static_equilibrium(MultibodySystem& system, double t, const VectorX& y_guess,
                                           const EquilibriumSettings& settings);

/// "translation along world (0, 0, 1) of joint 'platform_motion' (body 'platform')" for
/// velocity coordinate k, the direction read from the current position stage.
std::string describe_velocity_coordinate(const Model& model, const Data& data, int k);

}  // namespace heavesim
