#pragma once
// The sea and the hydrodynamic force elements of a case (docs/case-format.md,
// "environment", "waves", "Hydrodynamic forces"), as read from the case: plain values
// and resolved file paths. The BEM and mesh files are read when the scene is built
// (app/scene/hydro_scene.cpp), so that only declared elements cost anything.
#include <array>
#include <limits>
#include <optional>
#include <string>

#include "hydro/elements/body_motion.hpp"
#include "hydro/elements/element_factories.hpp"
#include "hydro/excitation/semisubmersible_heave.hpp"
#include "hydro/waves/ramp.hpp"
#include "hydro/waves/wave_train.hpp"

namespace heavesim {

/// Water properties (environment.water_density, environment.water_depth).
struct WaterDefinition {
  double density = 1025.0;                                 // rho [kg/m^3]
  double depth = std::numeric_limits<double>::infinity();  // h [m]; infinite by default
};

/// The incident sea (`waves:`); none when the case declares no waves.
struct WaveDefinition {
  enum class Type { none, regular, jonswap, pierson_moskowitz };
  Type type = Type::none;
  double heading = 0.0;  // beta [rad], direction of travel from +x toward +y (0: head seas along +x)
  hydro::Ramp ramp;      // start-up ramp on elevation and excitation
  // regular
  double amplitude = 0.0;  // a [m]
  double period = 0.0;     // T [s]
  double phase = 0.0;      // phi [rad]
  // irregular
  double significant_height = 0.0;  // Hs [m]
  double peak_period = 0.0;         // Tp [s]
  double peak_enhancement = 3.3;    // gamma [-] (JONSWAP)
  hydro::IrregularSeaSettings irregular;  // components, band, seed, discretization
  bool declared() const { return type != Type::none; }
};

/// One hydrodynamic force element in `forces:` on one body's reference point (its body
/// frame origin, WAMIT order [surge, sway, heave, roll, pitch, yaw], world axes).
struct HydroForceDefinition {
  enum class Type { hydrostatics, radiation, wave_excitation, linear_damping, quadratic_damping, mooring, added_mass };
  std::string name;
  Type type = Type::hydrostatics;
  std::string body;
  std::string file;          // hst / .1 / .3 / mesh path, resolved against the case file's directory
  std::string file_key;      // the key the file came from ("hst", "mesh", "file"), for errors
  bool nonlinear = false;    // hydrostatics from a panel mesh (.gdf, .stl), clipped every evaluation
  /// wave_excitation from the semi-submersible hand estimate instead of a .3 file.
  std::optional<hydro::SemisubmersibleHeaveEstimate> heave_estimate;
  double length_scale = 1.0;  // WAMIT ULEN [m]
  /// Linear hydrostatics: buoyancy rho g V at the reference pose; when absent, equal to the
  /// body's weight (the reference pose is then the static equilibrium).
  std::optional<double> displaced_volume;  // V [m^3]
  /// Linear hydrostatics: the .hst is WAMIT's "hydrostatic and gravitational" matrix of a
  /// run given the CG (MSS semisub.hst); its gravitational part is taken out because the
  /// kernel applies the weight at the centre of mass itself (docs/physics/hydrodynamics.md §7).
  bool hst_includes_gravity = false;
  /// radiation: state space or convolution, kernel sampling, modes (hydro's own settings)
  hydro::RadiationMemorySettings memory;
  // About the reference point, WAMIT order, world axes:
  /// hydrostatics given as `stiffness` (C), mooring (K) [N/m, N, N m/rad]
  hydro::Matrix6 stiffness = hydro::Matrix6::Zero();
  hydro::Matrix6 damping = hydro::Matrix6::Zero();     // linear_damping: B [N s/m, N s, N m s/rad]
  hydro::Matrix6 added_mass = hydro::Matrix6::Zero();  // added_mass: A [kg, kg m, kg m^2]
  /// quadratic_damping: b_quad [N s^2/m^2, N m s^2/rad^2]
  hydro::Vector6 quadratic_coefficients = hydro::Vector6::Zero();
  hydro::Vector6 pretension = hydro::Vector6::Zero();  // mooring: f0 [N, N m]
};

}  // namespace heavesim
