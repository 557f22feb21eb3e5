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
/// Friction acts along k = friction_directions tangents evenly spaced over half a turn,
/// each impulse boxed by |z_d| <= mu tan(pi / 2k) z_n: the sum of the k boxes is the
/// regular 2k-gon whose faces touch the Coulomb circle (k = 2: the four-facet pyramid;
/// the largest excess over mu, along a corner, is 1 / cos(pi / 2k) - 1).
struct ContactPair {
  std::string name;  ///< for outputs and messages
  int geometry_a = 0;
  int geometry_b = 0;
  double friction_coefficient = 0.0;
  double restitution = 0.0;
  int friction_directions = 2;
  static constexpr int max_friction_directions = 16;
  /// m: friction against spinning about the normal at each point, |tau_n| <= mu_t z_n
  /// (MuJoCo's torsional friction, condim 4): the moment of a contact patch that a point
  /// contact lacks. A drill bit's face: mu_b D / 3 (Pessier & Fear 1992). 0: none.
  double torsional_friction = 0.0;
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

/// A line that carries tension only -- a hoist line, a rope, a tether -- from point_a on
/// link_a to point_b on link_b (each in its link frame, m): the distance between the two
/// points stays <= length; below it the line is slack and carries nothing. Taut again,
/// it stops the points' separation by an impulse (a snap load) with restitution e.
/// Inextensible: a line whose stretch matters is a spring (`spring_damper`).
struct TensionLine {
  std::string name;  ///< for outputs and messages
  int link_a = 0;
  Vector3 point_a = Vector3::Zero();  ///< m, link_a frame
  int link_b = 0;
  Vector3 point_b = Vector3::Zero();  ///< m, link_b frame
  double length = 0.0;                ///< m, > 0
  double restitution = 0.0;
};

struct ContactModel {
  std::vector<ContactGeometry> geometries;
  std::vector<ContactPair> pairs;
  std::vector<JointStop> joint_stops;
  std::vector<TensionLine> lines;
  /// Contact points are kept while their gap is below this [m], so a resting contact
  /// stays in the problem from one step to the next (the velocity-level constraint
  /// lets a positive gap close exactly, it never pulls).
  double margin = 1e-3;
};

/// Throws ParameterError (field: the item's path in the ContactModel, e.g.
/// "pairs[0].friction_coefficient"; found: the value and the names involved) if the
/// contact model cannot be used with `model`: a geometry on a link that does not exist
/// or with a size <= 0, a pair of shapes without a contact routine (two planes), mu < 0,
/// e outside [0, 1], friction directions outside 2..16, a torsional friction < 0, a stop on a joint that is not
/// 1-DoF or with lower >= upper, a line between points of one link or of length <= 0.
struct Model;
void check_contact_model(const Model& model, const ContactModel& contacts);

}  // namespace heavesim
