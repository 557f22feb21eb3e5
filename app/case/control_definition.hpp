#pragma once
// Compensators declared in `forces:` (types pneumatic_compensator and
// active_compensator, docs/case-format.md), as read from the case: control/'s
// parameters plus what only the model can resolve (bodies, joints, the static-balance
// pressure, the initial references), which the scene fills in.
#include <optional>
#include <string>

#include "control/active/active_compensator.hpp"
#include "control/pneumatic/pneumatic_compensator.hpp"

namespace heavesim {

/// Where a compensator acts: a prismatic joint, or two body points and an axis.
struct StrokeDefinition {
  std::string joint;                     // joint form: a prismatic joint's name
  std::string base_body, moving_body;    // body form ("ground" allowed for the base)
  Vector3 base_point = Vector3::Zero();  // m, base body frame
  Vector3 moving_point = Vector3::Zero();  // m, moving body frame
  Vector3 axis = Vector3::UnitZ();       // unit, base body frame
  double mid_stroke = 0.0;               // m: q, or the axial distance, at s = 0
  bool joint_form() const { return !joint.empty(); }
};

struct CompensatorDefinition {
  enum class Type { pneumatic, active };
  std::string name;
  Type type = Type::pneumatic;
  StrokeDefinition stroke;
  // pneumatic
  PneumaticParameters pneumatic;
  bool balance_pressure = true;  // gas_pressure: balance -> set from static equilibrium
  // active
  ActiveCompensatorParameters active;
  std::optional<std::string> controlled_body;  // default: the moving side
  Vector3 controlled_point = Vector3::Zero();  // m, that body's frame
  /// Hydraulic cylinder stroke range [m] over which both chamber volumes stay positive.
  double cylinder_lower = 0.0, cylinder_upper = 0.0;
};

}  // namespace heavesim
