#pragma once
// What a compensator needs from the model at the initial state before a run: the
// load it carries along its stroke, the mass it moves along it, and the gas pressure
// that carries the load (the passive compensator's static balance).
#include "control/pneumatic/pneumatic_compensator.hpp"
#include "control/stroke/stroke_axis.hpp"
#include "kernel/system/multibody_system.hpp"

namespace heavesim {

/// Q (nv) of a unit force [1 N] along the stroke at the position stage held in `data`.
VectorX unit_stroke_generalized_force(const StrokeAxis& axis, const Model& model, const Data& data);

/// The force [N] along the stroke that holds the configuration q0 at rest at time t0
/// against gravity and the loads of the force elements already in `system`: with
/// needed = RNEA(q0, 0, 0) - Q_elements (the generalized force that holds q0), the
/// least-squares load along `unit` (the stroke's unit generalized force) is
/// unit . needed / |unit|^2; for a joint-form stroke exactly that coordinate's load.
/// With constraint rows (loop joints, couplers, drivers held at t0) part of the load
/// goes through them: needed = unit F + J^T lambda, solved for (F, lambda) in the
/// least-squares, minimum-norm sense (Haug 1989, sec. 6.4: the static multipliers).
/// Throws ParameterError("gas_pressure") when the constraints hold the stroke itself.
double static_stroke_load(const Model& model, Data& data, const MultibodySystem& system, double t0,
                          const VectorX& q0, const VectorX& unit);

/// Mass [kg] seen along the stroke with every other coordinate held:
/// m = Q^T M Q / |Q|^4 for the stroke's unit generalized force Q and the mass matrix M
/// (M_jj for a joint-form stroke on coordinate j).
double apparent_stroke_mass(const MatrixX& mass_matrix, const VectorX& unit);

/// `parameters` with gas_pressure [Pa, at mid-stroke] set so that the gas carries
/// `load` [N] at rest at `initial_stroke` [m]: p = p_atm + load / A at the initial stroke,
/// taken to mid-stroke by p0 = p (V/V0)^n (polytropic, no gas state) or p (V/V0) (with a
/// gas state, which starts at the initial temperature), V = V0 + A s.
/// Throws ParameterError("gas_pressure") when that pressure is below atmospheric (the
/// load pulls the stroke out).
PneumaticParameters balanced_pneumatic(PneumaticParameters parameters, double load, double initial_stroke);

}  // namespace heavesim
