#pragma once
// The `contacts` section of a case (docs/case-format.md, "contacts"): shapes on bodies,
// the pairs checked for contact with their friction and restitution, and one-sided
// stops on joints and tension lines between body points, by name. The scene resolves the names into the kernel's
// ContactModel (kernel/contact/contact_model.hpp), whose check states the rules on the
// values; run by `solver.integrator: contact` (docs/physics/contact.md).
#include <string>
#include <vector>

#include "kernel/contact/contact_model.hpp"

namespace heavesim {

struct ContactGeometryDefinition {
  std::string name;
  std::string body;         ///< a body or "ground"
  Transform X_body_shape;   ///< the shape frame in the body frame (`frame`)
  ContactShape shape;
};

struct ContactPairDefinition {
  std::string name;
  std::string geometry_a, geometry_b;  ///< geometry names; a is pushed along the normal from b
  double friction_coefficient = 0.0;
  double restitution = 0.0;
  int friction_directions = 2;  ///< tangents per point: a friction polygon of 2k faces
  double torsional_friction = 0.0;  ///< m: |spin moment| <= this x normal force, per point
};

struct JointStopDefinition {
  std::string name;
  std::string joint;
  double lower = -std::numeric_limits<double>::infinity();  ///< m or rad
  double upper = std::numeric_limits<double>::infinity();
  double restitution = 0.0;
};

/// A line that carries tension only (hoist line, rope, tether) between two body points.
struct TensionLineDefinition {
  std::string name;
  std::string body_a, body_b;  ///< bodies or "ground"
  Vector3 point_a = Vector3::Zero(), point_b = Vector3::Zero();  ///< m, in each body's frame
  double length = 0.0;  ///< m
  double restitution = 0.0;
};

struct ContactDefinition {
  std::vector<ContactGeometryDefinition> geometries;
  std::vector<ContactPairDefinition> pairs;
  std::vector<JointStopDefinition> joint_stops;
  std::vector<TensionLineDefinition> lines;
  double margin = 1e-3;  ///< m
  bool empty() const { return geometries.empty() && pairs.empty() && joint_stops.empty() && lines.empty(); }
};

}  // namespace heavesim
