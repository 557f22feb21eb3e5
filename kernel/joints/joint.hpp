#pragma once
// The joint library as one closed set of concrete types (Pinocchio-style variant),
// and the user-facing joint kinds from which the model builder makes them.
#include <string>
#include <variant>

#include "kernel/joints/cylindrical_joint.hpp"
#include "kernel/joints/fixed_joint.hpp"
#include "kernel/joints/free_joint.hpp"
#include "kernel/joints/prismatic_joint.hpp"
#include "kernel/joints/revolute_joint.hpp"
#include "kernel/joints/spherical_joint.hpp"
#include "kernel/joints/universal_joint.hpp"

namespace heavesim {

using JointType = std::variant<FixedJoint, RevoluteJoint, PrismaticJoint, CylindricalJoint,
                               UniversalJoint, SphericalJoint, FreeJoint>;

/// The kinds of joint a user can ask for; axes come separately (JointDefinition).
enum class JointKind { fixed, revolute, prismatic, cylindrical, universal, spherical, free };

/// The canonical joint type of a kind (axis on z; universal about x then y).
inline JointType canonical_joint_type(JointKind kind) {
  switch (kind) {
    case JointKind::fixed: return FixedJoint{};
    case JointKind::revolute: return RevoluteJoint{};
    case JointKind::prismatic: return PrismaticJoint{};
    case JointKind::cylindrical: return CylindricalJoint{};
    case JointKind::universal: return UniversalJoint{};
    case JointKind::spherical: return SphericalJoint{};
    case JointKind::free: return FreeJoint{};
  }
  return FixedJoint{};
}

inline int joint_nq(const JointType& type) {
  return std::visit([](const auto& j) { return std::decay_t<decltype(j)>::nq; }, type);
}
inline int joint_nv(const JointType& type) {
  return std::visit([](const auto& j) { return std::decay_t<decltype(j)>::nv; }, type);
}
inline std::string joint_type_name(const JointType& type) {
  return std::visit([](const auto& j) { return std::string(std::decay_t<decltype(j)>::type_name); }, type);
}
/// True when the joint's coordinates are plain numbers (q and v have the same size and
/// meaning), so springs, limits and drivers act on q directly.
inline bool joint_has_scalar_coordinates(const JointType& type) { return joint_nq(type) == joint_nv(type); }

}  // namespace heavesim
