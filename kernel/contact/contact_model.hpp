#pragma once
// What may touch what: contact shapes fixed on links, the pairs that are checked and
// their Coulomb friction and restitution, and one-sided stops on 1-DoF joints. Immutable
// like Model; ContactStepper holds the per-step work (docs/physics/contact.md).
#include <string>
#include <vector>

#include "kernel/spatial/transform.hpp"

namespace heavesim {

/// A convex contact shape, in its own frame (placed on a link by ContactGeometry):
///   sphere    radius about the frame origin
///   box       half_extents along the frame's x, y, z, centred on the origin
///   cylinder  radius about the frame's z axis, from z = -half_length to +half_length
///   plane     the half-space z <= 0 of the frame: its surface is z = 0, its outward
///             normal +z (a deck, the sea floor, an incline). Unbounded.
enum class ContactShapeKind { sphere, box, cylinder, plane };
const char* to_string(ContactShapeKind kind);

struct ContactShape {
  ContactShapeKind kind = ContactShapeKind::sphere;
  double radius = 0.0;                     ///< m: sphere, cylinder
  double half_length = 0.0;                ///< m: cylinder, along its z
  Vector3 half_extents = Vector3::Zero();  ///< m: box
};

struct ContactGeometry {
  std::string name;
  int link = 0;                   ///< model link index; 0 = ground
  Transform X_link_shape;         ///< the shape frame in the link frame
  ContactShape shape;
};

/// Two geometries that are checked for contact (a and b by index into geometries), with
/// the Coulomb coefficient mu >= 0 and Newton's restitution 0 <= e <= 1 of their impacts.
struct ContactPair {
  std::string name;  ///< for outputs and messages
  int geometry_a = 0;
  int geometry_b = 0;
  double friction_coefficient = 0.0;
  double restitution = 0.0;
};

/// A one-sided stop on the coordinate of a 1-DoF joint (revolute or prismatic): the
/// coordinate stays within [lower, upper] (m or rad; either may be infinite), by an
/// impulse when it reaches a bound, with restitution e. The compensator's stroke ends.
struct JointStop {
  std::string name;  ///< for outputs and messages
  int joint = 0;
  double lower = 0.0;
  double upper = 0.0;
  double restitution = 0.0;
};

struct ContactModel {
  std::vector<ContactGeometry> geometries;
  std::vector<ContactPair> pairs;
  std::vector<JointStop> joint_stops;
  /// Contact points are kept while their gap is below this [m], so a resting contact
  /// stays in the problem from one step to the next (the velocity-level constraint
  /// lets a positive gap close exactly, it never pulls).
  double margin = 1e-3;
};

/// Throws ParameterError (field: the item's path in the ContactModel, e.g.
/// "pairs[0].friction_coefficient"; found: the value and the names involved) if the
/// contact model cannot be used with `model`: a geometry on a link that does not exist
/// or with a size <= 0, a pair of shapes without a contact routine (two planes), mu < 0,
/// e outside [0, 1], a stop on a joint that is not 1-DoF or with lower >= upper.
struct Model;
void check_contact_model(const Model& model, const ContactModel& contacts);

}  // namespace heavesim
