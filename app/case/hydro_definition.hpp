#pragma once
// The sea of a case (docs/case-format.md, "environment", "waves"), as read from the
// case; the hydrodynamic force kinds are in app/forces/ (hydro_force.hpp).
#include <limits>

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

}  // namespace heavesim
