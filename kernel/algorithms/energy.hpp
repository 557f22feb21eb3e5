#pragma once
// Mechanical energy of the multibody system.
#include "kernel/model/data.hpp"

namespace heavesim {

/// Kinetic energy [J] 1/2 sum v_i^T I_i v_i, with I_i the total link inertia (rigid plus
/// any added mass), from the velocity stage's momenta; throws std::logic_error unless that
/// stage is current.
double kinetic_energy(const Model& model, const Data& data);

/// Gravitational potential energy [J] -sum m_i g . c_i (zero at the world origin);
/// requires the position stage.
double gravity_potential_energy(const Model& model, const Data& data);

}  // namespace heavesim
