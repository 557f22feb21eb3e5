#include "kernel/model/model_builder.hpp"

#include <functional>
#include <map>
#include <unordered_map>
#include <sstream>
#include <tuple>

#include <Eigen/Eigenvalues>

namespace heavesim {
namespace {

std::string format_number(double value) {
  std::ostringstream text;
  text << value;
  return text.str();
}

ModelError body_error(const std::string& body, const std::string& field, const std::string& found,
                      const std::string& expected) {
  return ModelError(ModelError::ItemKind::body, body, field, found, expected);
}

ModelError joint_error(const std::string& joint, const std::string& field, const std::string& found,
                       const std::string& expected) {
  return ModelError(ModelError::ItemKind::joint, joint, field, found, expected);
}

void check_body(const BodyDefinition& body) {
  const Inertia& I = body.inertia;
  if (!(I.mass() >= 0.0) || !std::isfinite(I.mass()))
    throw body_error(body.name, "mass", format_number(I.mass()), "a positive, finite mass in kg (or 0 for a massless connector)");
  const Matrix3& J = I.inertia_com();
  // A massless connector (a slider carriage whose mass is lumped elsewhere) has no
  // rotational inertia either; it must carry other bodies (checked in build()).
  if (I.mass() == 0.0 && !J.isZero(0.0))
    throw body_error(body.name, "inertia", "a rotational inertia on a massless body", "zero inertia when mass = 0");
  if (!J.allFinite()) throw body_error(body.name, "inertia", "non-finite entries", "finite numbers (kg m^2)");
  const Vector3 principal = Eigen::SelfAdjointEigenSolver<Matrix3>(J).eigenvalues();
  const double scale = std::max(principal.cwiseAbs().maxCoeff(), 1e-300);
  if (principal.minCoeff() < -1e-12 * scale)
    throw body_error(body.name, "inertia",
                     "principal moments " + format_number(principal[0]) + ", " + format_number(principal[1]) + ", " +
                         format_number(principal[2]),
                     "a positive semi-definite inertia about the CoM");
  // Triangle inequality of principal moments: any real mass distribution satisfies it.
  const double a = principal[0], b = principal[1], c = principal[2];
  if (a + b < c * (1.0 - 1e-9) || a + c < b * (1.0 - 1e-9) || b + c < a * (1.0 - 1e-9))
    throw body_error(body.name, "inertia",
                     "principal moments " + format_number(a) + ", " + format_number(b) + ", " + format_number(c),
                     "moments satisfying the triangle inequality (each <= the sum of the other two)");
}

ModelError constraint_error(const std::string& name, const std::string& field, const std::string& found,
                            const std::string& expected) {
  return ModelError(ModelError::ItemKind::constraint, name, field, found, expected);
}

/// The canonical joint frame's axes in the user's joint frame: Q e_z = axis for
/// axial joints; Q e_x = axis, Q e_y = second_axis for a universal joint.
template <class Definition>
Matrix3 canonical_axes(const Definition& joint, ModelError::ItemKind item) {
  auto error = [&](const std::string& field, const std::string& found, const std::string& expected) {
    return ModelError(item, joint.name, field, found, expected);
  };
  if (std::abs(joint.axis.norm() - 1.0) > 1e-6)
    throw error("axis", "an axis of length " + format_number(joint.axis.norm()), "a unit vector");
  Matrix3 Q = Matrix3::Identity();
  switch (joint.kind) {
    case JointKind::revolute:
    case JointKind::prismatic:
    case JointKind::cylindrical: {
      const Vector3 z = joint.axis, x = z.unitOrthogonal();
      Q << x, z.cross(x), z;
      break;
    }
    case JointKind::universal:
      if (std::abs(joint.second_axis.norm() - 1.0) > 1e-6 || std::abs(joint.axis.dot(joint.second_axis)) > 1e-6)
        throw error("axes", "axes that are not perpendicular unit vectors", "perpendicular unit axes (a Hooke joint)");
      Q << joint.axis, joint.second_axis, joint.axis.cross(joint.second_axis);
      break;
    default:
      break;
  }
  return Q;
}

std::string format_point(const Vector3& point) {
  return "(" + format_number(point.x()) + ", " + format_number(point.y()) + ", " + format_number(point.z()) + ")";
}

/// A loop joint row's name in the user's joint frame: rows are written on the
/// canonical frames (joint axis turned to z), whose axes are Q's columns in the user's
/// joint frame, so a revolute about y reports its blocked rotations about x and z, not
/// the canonical x and y.
std::string describe_in_joint_frame(const ConstraintRow& row, const Matrix3& Q) {
  const bool translation = row.kind == ConstraintRowKind::along;
  // along: the axis it blocks translation along; perpendicular a_A . b_B: the third axis.
  const int canonical_axis = translation ? row.axis_a : 3 - row.axis_a - row.axis_b;
  const Vector3 axis = Q.col(canonical_axis);
  std::string name = format_point(axis);
  static const char* axis_names[3] = {"x", "y", "z"};
  for (int k = 0; k < 3; ++k)
    if ((axis.cwiseAbs() - Vector3::Unit(k)).cwiseAbs().maxCoeff() <= 1e-12) name = axis_names[k];
  return (translation ? "translation along " : "rotation about ") + name;
}

/// The row's name for describe_constraint_row: what the driver measures, in the user's
/// bodies and points ("x of block's point (0, 0, 0)").
std::string frame_driver_description(const DriverDefinition& def) {
  const std::string point_b = def.body_b + "'s point " + format_point(def.X_body_b_frame.translation());
  switch (def.kind) {
    case DriverKind::absolute: {
      static const char* axes[3] = {"x", "y", "z"};
      for (int axis = 0; axis < 3; ++axis)
        if (def.direction.normalized() == Vector3::Unit(axis)) return std::string(axes[axis]) + " of " + point_b;
      return "component along " + format_point(def.direction) + " of " + point_b;
    }
    case DriverKind::distance:
      return "distance from " + def.body_a + "'s point " + format_point(def.X_body_a_frame.translation()) + " to " +
             point_b;
    case DriverKind::angle:
      return "angle of " + def.body_b + "'s frame_b x axis about " + def.body_a + "'s frame_a z axis";
    case DriverKind::joint: break;
  }
  return "prescribed coordinate";
}

/// An absolute, distance or angle driver: frames A and B on their links and the one row
/// whose measured coordinate f(t) prescribes (constraint.hpp).
template <class LinkOf>
Constraint frame_driver(const Model& model, Constraint constraint, const DriverDefinition& def, const LinkOf& link_of) {
  const bool absolute = def.kind == DriverKind::absolute;
  constraint.link_a = absolute ? 0 : link_of(def.name, "body_a", def.body_a);
  constraint.link_b = link_of(def.name, absolute ? "body" : "body_b", def.body_b);
  if (constraint.link_a == constraint.link_b)
    throw constraint_error(def.name, absolute ? "body" : "body_b",
                           absolute ? "'ground', which does not move" : "body '" + def.body_a + "' on both ends",
                           absolute ? "a body" : "two different bodies");
  constraint.X_linkB_frame = model.links[constraint.link_b].X_link_body * def.X_body_b_frame;
  ConstraintRow row;
  row.description = frame_driver_description(def);
  switch (def.kind) {
    case DriverKind::absolute: {
      const double length = def.direction.norm();
      if (!(std::abs(length - 1.0) <= 1e-6))
        throw constraint_error(def.name, "direction", "a direction of length " + format_number(length),
                               "a unit vector (world frame)");
      const Vector3 direction = def.direction / length;
      // Frame A: the ground frame turned so that its x is the direction (an `along` row on x).
      constraint.X_linkA_frame = Transform::from_rotation(
          Eigen::Quaterniond::FromTwoVectors(Vector3::UnitX(), direction).toRotationMatrix());
      constraint.kind = AbsoluteDriverConstraint{direction, def.motion};
      row.kind = ConstraintRowKind::along;
      break;
    }
    case DriverKind::distance:
      constraint.X_linkA_frame = model.links[constraint.link_a].X_link_body * def.X_body_a_frame;
      constraint.kind = DistanceDriverConstraint{def.motion};
      row.kind = ConstraintRowKind::length;
      break;
    case DriverKind::angle:
      constraint.X_linkA_frame = model.links[constraint.link_a].X_link_body * def.X_body_a_frame;
      constraint.kind = AngleDriverConstraint{def.motion};
      row.kind = ConstraintRowKind::angle;
      break;
    case DriverKind::joint: break;
  }
  constraint.rows = {row};
  return constraint;
}

}  // namespace

void ModelBuilder::add_constraints(Model& model) const {
  std::map<std::string, int> names;
  // A new constraint of this type under a name no joint or constraint uses yet.
  auto start = [&](const std::string& name, ConstraintKind kind) {
    if (model.joint_index(name) > 0 || !names.emplace(name, 0).second)
      throw constraint_error(name, "name", "'" + name + "' a second time (joints and constraints share names)",
                             "a unique name");
    Constraint constraint;
    constraint.name = name;
    constraint.kind = std::move(kind);
    return constraint;
  };
  auto link_of = [&](const std::string& constraint, const std::string& field, const std::string& body) {
    const int link = model.link_index(body);
    if (link < 0)
      throw constraint_error(constraint, field, "'" + body + "', which is not a body", "'ground' or the name of a body");
    return link;
  };
  auto add = [&](Constraint constraint) {
    constraint.first_row = model.num_constraint_rows;
    model.num_constraint_rows += static_cast<int>(constraint.rows.size());
    model.constraints.push_back(std::move(constraint));
  };

  for (const LoopJointDefinition& def : loop_joints_) {
    Constraint constraint = start(def.name, LoopJointConstraint{def.kind});
    constraint.link_a = link_of(def.name, "parent", def.parent);
    constraint.link_b = link_of(def.name, "child", def.child);
    if (constraint.link_a == constraint.link_b)
      throw constraint_error(def.name, "child", "the parent body '" + def.parent + "' again",
                             "two different bodies to connect");
    if (def.kind == JointKind::free)
      throw constraint_error(def.name, "type", "a free joint, which constrains nothing", "another joint type");
    const Matrix3 Q = canonical_axes(def, ModelError::ItemKind::constraint);
    const Transform rotate = Transform::from_rotation(Q);
    constraint.X_linkA_frame = model.links[constraint.link_a].X_link_body * def.X_parent_joint * rotate;
    constraint.X_linkB_frame = model.links[constraint.link_b].X_link_body * def.X_child_joint * rotate;
    constraint.R_joint_frame = Q;
    constraint.rows = loop_joint_rows(def.kind);
    for (ConstraintRow& row : constraint.rows) row.description = describe_in_joint_frame(row, Q);
    add(std::move(constraint));
  }
  for (const DistanceConstraintDefinition& def : distances_) {
    Constraint constraint = start(def.name, DistanceConstraint{def.distance});
    constraint.link_a = link_of(def.name, "body_a", def.body_a);
    constraint.link_b = link_of(def.name, "body_b", def.body_b);
    if (constraint.link_a == constraint.link_b)
      throw constraint_error(def.name, "body_b", "body '" + def.body_a + "' on both ends", "two different bodies");
    if (!(def.distance > 0.0) || !std::isfinite(def.distance))
      throw constraint_error(def.name, "distance", format_number(def.distance),
                             "a positive distance in m (use a spherical loop joint for coincident points)");
    constraint.X_linkA_frame = model.links[constraint.link_a].X_link_body * Transform::from_translation(def.point_a);
    constraint.X_linkB_frame = model.links[constraint.link_b].X_link_body * Transform::from_translation(def.point_b);
    constraint.rows = {{ConstraintRowKind::distance, 0, 0, "distance"}};
    add(std::move(constraint));
  }
  for (const CouplerDefinition& def : couplers_) {
    Constraint constraint = start(def.name, CouplerConstraint{});
    auto& coupler = std::get<CouplerConstraint>(constraint.kind);
    for (const auto& [field, joint_name, joint_index] :
         {std::tuple{"joint_a", def.joint_a, &coupler.joint_a}, std::tuple{"joint_b", def.joint_b, &coupler.joint_b}}) {
      const int index = model.joint_index(joint_name);
      if (index < 0)
        throw constraint_error(def.name, field, "'" + joint_name + "', which is not a joint", "the name of a joint");
      const Joint& joint = model.joints[index];
      if (joint.nv != 1 || !joint_has_scalar_coordinates(joint.type))
        throw constraint_error(def.name, field, "a " + joint_type_name(joint.type) + " joint",
                               "a revolute or prismatic joint");
      *joint_index = index;
    }
    if (coupler.joint_a == coupler.joint_b)
      throw constraint_error(def.name, "joint_b", "joint '" + def.joint_a + "' on both ends", "two different joints");
    if (!std::isfinite(def.ratio) || !std::isfinite(def.offset))
      throw constraint_error(def.name, "ratio", "a non-finite ratio or offset", "finite numbers");
    coupler.ratio = def.ratio;
    coupler.offset = def.offset;
    constraint.rows = {{ConstraintRowKind::coupler, 0, 0, "coupled coordinates"}};
    add(std::move(constraint));
  }
  for (const DriverDefinition& def : drivers_) {
    if (!def.motion) throw constraint_error(def.name, "motion", "no motion", "a function of time");
    if (def.kind != DriverKind::joint) {
      add(frame_driver(model, start(def.name, DriverConstraint{}), def, link_of));
      continue;
    }
    Constraint constraint = start(def.name, DriverConstraint{});
    const int index = model.joint_index(def.joint);
    if (index < 0)
      throw constraint_error(def.name, "joint", "'" + def.joint + "', which is not a joint", "the name of a joint");
    const Joint& joint = model.joints[index];
    if (joint.nv == 0 || !joint_has_scalar_coordinates(joint.type))
      throw constraint_error(def.name, "joint", "a " + joint_type_name(joint.type) + " joint",
                             "a revolute, prismatic, cylindrical or universal joint");
    if (def.coordinate < 0 || def.coordinate >= joint.nv)
      throw constraint_error(def.name, "coordinate", std::to_string(def.coordinate),
                             "0 to " + std::to_string(joint.nv - 1) + " (the coordinates of joint '" + def.joint + "')");
    for (const Constraint& other : model.constraints)
      if (const auto* driver = std::get_if<DriverConstraint>(&other.kind);
          driver && driver->joint == index && driver->coordinate == def.coordinate)
        throw constraint_error(def.name, "joint", "coordinate " + std::to_string(def.coordinate) + " of joint '" +
                                                      def.joint + "', already driven by '" + other.name + "'",
                               "at most one driver per coordinate");
    constraint.kind = DriverConstraint{index, def.coordinate, def.motion};
    constraint.rows = {{ConstraintRowKind::driver, 0, 0, "prescribed coordinate"}};
    add(std::move(constraint));
  }
  for (const ExpressionConstraintDefinition& def : expressions_) {
    Constraint constraint = start(def.name, ExpressionConstraint{});
    auto& expression = std::get<ExpressionConstraint>(constraint.kind);
    const int count = static_cast<int>(def.variables.size());
    if (count < 1 || count > ExpressionConstraint::max_variables)
      throw constraint_error(def.name, "variables", std::to_string(count) + " variables",
                             "1 to " + std::to_string(ExpressionConstraint::max_variables) + " joint coordinates");
    const int function_size = def.function ? def.function->size() : 0;
    if (function_size != count)
      throw constraint_error(def.name, "expression", "a function of " + std::to_string(function_size) + " coordinates",
                             "a function of its " + std::to_string(count) + " variables");
    for (const ExpressionVariable& variable : def.variables) {
      const std::string field = "variables." + variable.name;
      const int index = model.joint_index(variable.joint);
      if (index < 0)
        throw constraint_error(def.name, field, "'" + variable.joint + "', which is not a joint of the tree",
                               "the name of a revolute, prismatic, cylindrical or universal joint");
      const Joint& joint = model.joints[index];
      // Quaternion coordinates (spherical, free) are not the integrals of their rates: a
      // function of them would need the q -> v map in its Jacobian. Refused.
      if (joint.nv == 0 || !joint_has_scalar_coordinates(joint.type))
        throw constraint_error(def.name, field, "joint '" + variable.joint + "', a " + joint_type_name(joint.type) +
                                                    " joint",
                               "a revolute, prismatic, cylindrical or universal joint (scalar coordinates)");
      if (!variable.coordinate && joint.nv != 1)
        throw constraint_error(def.name, field,
                               "joint '" + variable.joint + "', a " + joint_type_name(joint.type) + " joint with " +
                                   std::to_string(joint.nv) + " coordinates, without a coordinate",
                               "{joint: " + variable.joint + ", coordinate: 0 to " + std::to_string(joint.nv - 1) +
                                   "}");
      const int coordinate = variable.coordinate.value_or(0);
      if (coordinate < 0 || coordinate >= joint.nv)
        throw constraint_error(def.name, field + ".coordinate", std::to_string(coordinate),
                               "0 to " + std::to_string(joint.nv - 1) + " (the coordinates of joint '" +
                                   variable.joint + "')");
      expression.q_index.push_back(joint.q_index + coordinate);
      expression.v_index.push_back(joint.v_index + coordinate);
    }
    expression.function = def.function;
    constraint.rows = {{ConstraintRowKind::expression, 0, 0, "expression"}};
    add(std::move(constraint));
  }
  for (const JointStopConstraintDefinition& def : stops_) {
    Constraint constraint = start(def.name, JointStopConstraint{});
    const int index = model.joint_index(def.joint);
    if (index < 0)
      throw constraint_error(def.name, "joint", "'" + def.joint + "', which is not a joint", "the name of a joint");
    const Joint& joint = model.joints[index];
    if (joint.nv != 1 || joint.nq != 1)
      throw constraint_error(def.name, "joint", "a " + joint_type_name(joint.type) + " joint",
                             "a revolute or prismatic joint");
    if (!std::isfinite(def.bound)) throw constraint_error(def.name, "bound", format_number(def.bound), "a finite bound");
    if (!(def.restitution >= 0.0 && def.restitution <= 1.0))
      throw constraint_error(def.name, "restitution", format_number(def.restitution), "0 <= e <= 1");
    constraint.kind = JointStopConstraint{index, def.bound, def.lower ? 1.0 : -1.0, def.restitution};
    constraint.rows = {{ConstraintRowKind::stop, 0, 0,
                        std::string(def.lower ? "coordinate >= " : "coordinate <= ") + format_number(def.bound)}};
    add(std::move(constraint));
  }
}

Model ModelBuilder::build() const {
  // Hash maps: the build is O(n) in the number of bodies (docs/performance.md, "Set-up").
  std::unordered_map<std::string, int> body_index;
  for (int b = 0; b < static_cast<int>(bodies_.size()); ++b) {
    const BodyDefinition& body = bodies_[b];
    if (body.name == ground_name) throw body_error(body.name, "name", "'ground'", "a name other than 'ground'");
    if (!body_index.emplace(body.name, b).second)
      throw body_error(body.name, "name", "'" + body.name + "' twice", "unique body names");
    check_body(body);
  }

  std::unordered_map<std::string, int> joint_of_child;
  std::unordered_map<std::string, std::vector<int>> joints_of_parent;
  std::unordered_map<std::string, int> joint_names;
  for (int j = 0; j < static_cast<int>(joints_.size()); ++j) {
    const JointDefinition& joint = joints_[j];
    if (!joint_names.emplace(joint.name, j).second)
      throw joint_error(joint.name, "name", "'" + joint.name + "' twice", "unique joint names");
    if (joint.parent != ground_name && !body_index.count(joint.parent))
      throw joint_error(joint.name, "parent", "'" + joint.parent + "', which is not a body",
                        "'ground' or the name of a body");
    if (!body_index.count(joint.child))
      throw joint_error(joint.name, "child", "'" + joint.child + "', which is not a body", "the name of a body");
    if (joint.parent == joint.child)
      throw joint_error(joint.name, "child", "the parent body '" + joint.parent + "' again",
                        "a child different from the parent");
    if (!joint_of_child.emplace(joint.child, j).second)
      throw joint_error(joint.name, "child",
                        "body '" + joint.child + "', already the child of joint '" +
                            joints_[joint_of_child[joint.child]].name + "'",
                        "each body the child of one joint (close kinematic loops with a loop joint)");
    joints_of_parent[joint.parent].push_back(j);
  }
  for (const BodyDefinition& body : bodies_)
    if (!joint_of_child.count(body.name))
      throw body_error(body.name, "name", "a body that no joint attaches",
                       "a joint with child '" + body.name + "' (use a free joint for a floating body)");
  for (const BodyDefinition& body : bodies_)
    if (body.inertia.mass() == 0.0 && !joints_of_parent.count(body.name))
      throw body_error(body.name, "mass", "0 on a body that carries nothing (its motion would have no inertia)",
                       "a positive mass, or other bodies attached to this massless connector");

  Model model;
  model.gravity = gravity_;
  model.links.reserve(bodies_.size() + 1);
  model.joints.reserve(bodies_.size() + 1);
  Link ground;
  ground.name = ground_name;
  model.links.push_back(ground);
  model.joints.push_back(Joint{});
  model.joints[0].name = ground_name;

  // Depth-first order from the ground; bodies never reached sit on a cycle.
  std::function<void(const std::string&, int)> visit = [&](const std::string& parent_body, int parent_link) {
    auto it = joints_of_parent.find(parent_body);
    if (it == joints_of_parent.end()) return;
    for (int j : it->second) {
      const JointDefinition& def = joints_[j];
      const BodyDefinition& body = bodies_[body_index.at(def.child)];
      const int link_id = model.num_links();
      const Matrix3 Q = canonical_axes(def, ModelError::ItemKind::joint);
      Joint joint;
      joint.name = def.name;
      joint.type = canonical_joint_type(def.kind);
      joint.parent = parent_link;
      // X_parentlink_joint = X_parentlink_parentbody X_parentbody_joint Q.
      joint.placement = model.links[parent_link].X_link_body * def.X_parent_joint * Transform::from_rotation(Q);
      joint.R_joint_link = Q;
      joint.nq = joint_nq(joint.type);
      joint.nv = joint_nv(joint.type);
      joint.q_index = model.nq;
      joint.v_index = model.nv;
      joint.spring = def.spring;
      joint.limits = def.limits;
      model.nq += joint.nq;
      model.nv += joint.nv;
      if (joint.spring && (joint.spring->stiffness.size() != joint.nv || joint.spring->damping.size() != joint.nv ||
                           joint.spring->rest.size() != joint.nq))
        throw joint_error(def.name, "spring", "data sizes that do not match the joint",
                          std::to_string(joint.nv) + " stiffness/damping and " + std::to_string(joint.nq) +
                              " rest values");
      if (joint.limits && joint.nv != 1)
        throw joint_error(def.name, "limits", "limits on a " + std::to_string(joint.nv) + "-DoF joint",
                          "limits on 1-DoF joints only");

      Link link;
      link.name = body.name;
      // Link frame = child-side canonical joint frame: body data move by (X_child_joint Q)^-1.
      link.X_link_body = (def.X_child_joint * Transform::from_rotation(Q)).inverse();
      link.inertia = body.inertia.transformed(link.X_link_body);
      if (body.added_inertia) link.added_inertia = transform_spatial_inertia(link.X_link_body, *body.added_inertia);
      model.links.push_back(link);
      model.joints.push_back(joint);
      model.links[parent_link].children.push_back(link_id);
      visit(body.name, link_id);
    }
  };
  visit(ground_name, 0);

  if (model.num_links() != static_cast<int>(bodies_.size()) + 1) {
    for (const BodyDefinition& body : bodies_)
      if (model.link_index(body.name) < 0) {
        const JointDefinition& joint = joints_[joint_of_child.at(body.name)];
        throw joint_error(joint.name, "parent", "a chain of joints that leads back to '" + body.name + "' (a cycle)",
                          "a tree rooted at ground (close kinematic loops with a loop joint)");
      }
  }
  add_constraints(model);
  for (int i = model.num_links() - 1; i >= 0; --i) {
    model.links[i].subtree_end = i + 1;
    for (int c : model.links[i].children)
      model.links[i].subtree_end = std::max(model.links[i].subtree_end, model.links[c].subtree_end);
  }
  model.velocity_coordinate_parent.assign(model.nv, -1);
  for (int i = 1; i < model.num_links(); ++i) {
    const Joint& joint = model.joints[i];
    if (joint.nv == 0) continue;
    int ancestor = joint.parent;
    while (ancestor > 0 && model.joints[ancestor].nv == 0) ancestor = model.joints[ancestor].parent;
    model.velocity_coordinate_parent[joint.v_index] =
        ancestor > 0 ? model.joints[ancestor].v_index + model.joints[ancestor].nv - 1 : -1;
    for (int c = joint.v_index + 1; c < joint.v_index + joint.nv; ++c) model.velocity_coordinate_parent[c] = c - 1;
  }
  model.revolute_coordinates.clear();
  for (int i = 1; i < model.num_links(); ++i)
    if (std::holds_alternative<RevoluteJoint>(model.joints[i].type)) model.revolute_coordinates.push_back(model.joints[i].q_index);
  return model;
}

}  // namespace heavesim
