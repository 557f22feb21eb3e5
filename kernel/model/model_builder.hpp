#pragma once
// Builds a Model from bodies and joints given in any order, by name.
#include <stdexcept>

#include "kernel/model/model.hpp"

namespace heavesim {

/// A structural or physical problem in the model definition. `item` names the
/// offending body or joint and `field` the offending datum (e.g. "mass", "parent"),
/// so that callers can point at the exact place in their input.
class ModelError : public std::runtime_error {
 public:
  enum class ItemKind { body, joint, constraint };
  ModelError(ItemKind kind, std::string item, std::string field, std::string found, std::string expected)
      : std::runtime_error((kind == ItemKind::body ? "body '" : kind == ItemKind::joint ? "joint '" : "constraint '") +
                           item + "', " + field + ": found " + found + "; expected " + expected),
        kind_(kind),
        item_(std::move(item)),
        field_(std::move(field)),
        found_(std::move(found)),
        expected_(std::move(expected)) {}
  ItemKind kind() const { return kind_; }
  const std::string& item() const { return item_; }
  const std::string& field() const { return field_; }
  const std::string& found() const { return found_; }
  const std::string& expected() const { return expected_; }

 private:
  ItemKind kind_;
  std::string item_, field_, found_, expected_;
};

struct BodyDefinition {
  std::string name;
  Inertia inertia;                       // about the body frame origin, body axes
  std::optional<Matrix6> added_inertia;  // about the body frame origin, body axes, [angular; linear]
};

struct JointDefinition {
  std::string name;
  JointKind kind = JointKind::revolute;
  Vector3 axis = Vector3::UnitZ();         // unit, joint frame: revolute, prismatic, cylindrical;
                                          // universal: first axis
  Vector3 second_axis = Vector3::UnitY();  // universal: second axis, perpendicular to `axis`
  std::string parent;                    // body name or "ground"
  std::string child;                     // body name
  Transform X_parent_joint;              // joint frame in the parent body frame
  Transform X_child_joint;               // joint frame in the child body frame
  std::optional<JointSpringDamper> spring;
  std::optional<JointLimits> limits;
};

/// A joint that closes a kinematic loop between two bodies already in the tree (a
/// cut joint): the same kinds, axes and frames as JointDefinition, but it adds
/// constraint equations instead of coordinates.
struct LoopJointDefinition {
  std::string name;
  JointKind kind = JointKind::revolute;
  Vector3 axis = Vector3::UnitZ();
  Vector3 second_axis = Vector3::UnitY();
  std::string parent;                    // body name or "ground" (side A)
  std::string child;                     // body name or "ground" (side B)
  Transform X_parent_joint;              // joint frame in the parent body frame
  Transform X_child_joint;               // joint frame in the child body frame
};

/// Keeps two points a fixed distance apart (a massless rod with ball ends).
struct DistanceConstraintDefinition {
  std::string name;
  std::string body_a, body_b;            // body names or "ground"
  Vector3 point_a = Vector3::Zero();     // m, in body a's frame
  Vector3 point_b = Vector3::Zero();     // m, in body b's frame
  double distance = 1.0;                 // m, > 0
};

/// Ties the coordinates of two 1-DoF joints: q_a = ratio q_b + offset (gears, belts,
/// two cylinders driven as one).
struct CouplerDefinition {
  std::string name;
  std::string joint_a, joint_b;
  double ratio = 1.0;
  double offset = 0.0;                   // rad or m
};

/// A coordinate an expression constraint reads: coordinate `coordinate` of `joint` (a
/// revolute, prismatic, cylindrical or universal joint: scalar coordinates, m or rad).
struct ExpressionVariable {
  std::string name;               // its symbol in the expression; ModelError fields are "variables.<name>"
  std::string joint;
  std::optional<int> coordinate;  // none: the joint's only coordinate
};

/// f(x, t) = 0 over the variables x (in the function's order); the function gives f and
/// its exact derivatives (constraint_function.hpp). A cam profile s = r sin(theta) reads
/// "s - r*sin(theta)" over the slider's and the crank's coordinates.
struct ExpressionConstraintDefinition {
  std::string name;
  std::vector<ExpressionVariable> variables;
  std::shared_ptr<const ConstraintFunction> function;
};

/// What a driver prescribes (docs/physics/drivers.md):
///   joint     q_joint,coordinate = f(t): one coordinate of a joint with plain
///             coordinates (revolute, prismatic, cylindrical, universal) [m or rad]
///   absolute  direction . p_world(body point) = f(t) [m]
///   distance  |p_b - p_a| = f(t) > 0 between two body points [m]
///   angle     the angle of frame b's x about frame a's z, from frame a's x, = f(t) [rad]
enum class DriverKind { joint, absolute, distance, angle };

/// A prescribed motion. The motion's velocity and acceleration must be its exact time
/// derivatives. Only the fields of its kind are read; ModelError fields are named
/// after the case keys of that kind (absolute: body, point, direction; distance:
/// body_a, body_b; angle: body_a, frame_a, body_b, frame_b).
struct DriverDefinition {
  std::string name;
  std::string joint;                      // joint
  int coordinate = 0;                     // joint
  DriverFunction motion;
  DriverKind kind = DriverKind::joint;
  std::string body_a;                     // distance, angle: body name or "ground"
  std::string body_b;                     // absolute (the body), distance, angle
  Transform X_body_a_frame;               // distance: the point (translation only); angle: frame a
  Transform X_body_b_frame;               // absolute, distance: the point; angle: frame b
  Vector3 direction = Vector3::UnitX();   // absolute: unit, world frame
};

/// A one-sided stop on a 1-DoF joint's coordinate (JointStopConstraint), met by event
/// location under IDA: q >= bound (lower) or q <= bound (upper) [m or rad].
struct JointStopConstraintDefinition {
  std::string name;
  std::string joint;
  double bound = 0.0;
  bool lower = true;
  double restitution = 0.0;  // Newton's e in [0, 1]
};

class ModelBuilder {
 public:
  static constexpr const char* ground_name = "ground";

  void set_gravity(const Vector3& gravity_world) { gravity_ = gravity_world; }
  void add_body(BodyDefinition body) { bodies_.push_back(std::move(body)); }
  void add_joint(JointDefinition joint) { joints_.push_back(std::move(joint)); }
  void add_loop_joint(LoopJointDefinition joint) { loop_joints_.push_back(std::move(joint)); }
  void add_distance_constraint(DistanceConstraintDefinition constraint) {
    distances_.push_back(std::move(constraint));
  }
  void add_coupler(CouplerDefinition coupler) { couplers_.push_back(std::move(coupler)); }
  void add_driver(DriverDefinition driver) { drivers_.push_back(std::move(driver)); }
  void add_expression_constraint(ExpressionConstraintDefinition constraint) {
    expressions_.push_back(std::move(constraint));
  }
  void add_joint_stop(JointStopConstraintDefinition stop) { stops_.push_back(std::move(stop)); }

  /// Checks the topology (each body the child of exactly one joint, no cycle, all
  /// connected to ground), the physical data and the constraints; throws ModelError.
  Model build() const;

 private:
  void add_constraints(Model& model) const;
  Vector3 gravity_ = Vector3(0.0, 0.0, -9.81);
  std::vector<BodyDefinition> bodies_;
  std::vector<JointDefinition> joints_;
  std::vector<LoopJointDefinition> loop_joints_;
  std::vector<DistanceConstraintDefinition> distances_;
  std::vector<CouplerDefinition> couplers_;
  std::vector<DriverDefinition> drivers_;
  std::vector<ExpressionConstraintDefinition> expressions_;
  std::vector<JointStopConstraintDefinition> stops_;
};

}  // namespace heavesim
