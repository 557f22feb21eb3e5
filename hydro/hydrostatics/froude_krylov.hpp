#pragma once
// Nonlinear hydrostatic + Froude-Krylov load (WEC-Sim's nonlinearHydro,
// docs/physics/hydrodynamics.md §8): the undisturbed pressure of the incident wave,
//   p = -rho g z + rho g sum_j R(t) a_j e^{k_j z*} cos(w_j t - k_j (x cos b_j + y sin b_j) + phi_j),
// integrated over the hull below the instantaneous incident surface z = eta(x, y, t),
// with Wheeler stretching z* = z - eta (deep water: maps [-inf, eta] onto [-inf, 0], so
// p = 0 on the surface). Panels are clipped at the surface through their vertices'
// signed heights z - eta (linear along the edges), and the pressure, no longer
// linear, is integrated on each clipped triangle with the 7-point degree-5 rule of
// Dunavant (1985). No diffraction: that is the BEM excitation's job (and do not add
// both). Deep water only (the stretching above).
#include "hydro/hydrostatics/hull_mesh.hpp"
#include "hydro/waves/wave_train.hpp"
#include "kernel/spatial/transform.hpp"

namespace heavesim::hydro {

struct FroudeKrylovLoad {
  Vector3 force = Vector3::Zero();   // N, world frame
  Vector3 moment = Vector3::Zero();  // N m about the world origin, world frame
  double wetted_area = 0.0;          // m^2 below the incident surface
};

/// The load on `mesh` (body frame) placed at X_world_body at time t [s] in `waves`.
/// Allocates nothing.
FroudeKrylovLoad froude_krylov_load(const HullMesh& mesh, const Transform& X_world_body, const WaveTrain& waves, double t,
                                    double density, double gravity);

}  // namespace heavesim::hydro
