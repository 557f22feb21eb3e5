#pragma once
// The force kinds of `forces:`, registered once: the alternatives of ForceKindDefinition.
// Adding a kind is its file in app/forces/ (force_kind.hpp says what it provides), its
// include and its line here; the `type` choice, its did-you-mean, the key tables the
// readers accept (app/case/case_schema.cpp), the reading and the building all derive
// from this list (force_registry.cpp, app/scene/scene.cpp). The order here is the order
// the `type` choice lists them in.
#include <string>
#include <variant>

#include "app/forces/active_compensator.hpp"
#include "app/forces/added_mass.hpp"
#include "app/forces/body_load.hpp"
#include "app/forces/ground_contact.hpp"
#include "app/forces/hydrostatics.hpp"
#include "app/forces/joint_torque.hpp"
#include "app/forces/linear_damping.hpp"
#include "app/forces/mooring.hpp"
#include "app/forces/pneumatic_compensator.hpp"
#include "app/forces/quadratic_damping.hpp"
#include "app/forces/radiation.hpp"
#include "app/forces/wave_excitation.hpp"
#include "app/forces/point_force.hpp"
#include "app/forces/spring_damper.hpp"

namespace heavesim {

using ForceKindDefinition = std::variant<
    SpringDamperDefinition,
    PointForceDefinition,
    JointTorqueDefinition,
    GroundContactDefinition,
    PneumaticCompensatorDefinition,
    ActiveCompensatorDefinition,
    AddedMassDefinition,
    HydrostaticsDefinition,
    RadiationDefinition,
    WaveExcitationDefinition,
    LinearDampingDefinition,
    QuadraticDampingDefinition,
    MooringDefinition,
    BodyLoadDefinition>;

/// A force element declared in `forces:`: its name and its kind's typed definition.
struct ForceDefinition {
  std::string name;
  ForceKindDefinition kind;
};

}  // namespace heavesim
