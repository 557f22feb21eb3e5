#pragma once
// Immutable multibody model: a rooted tree of links connected by joints.
//
// Link 0 is the ground (the world frame: Z up, origin on the mean free surface).
// Link i >= 1 is the child of joint i; links are in depth-first order, so a parent
// always precedes its children and every subtree occupies the contiguous index
// range [i, subtree_end[i]).
// Link frame i is the child-side frame of joint i (origin at the joint point), turned
// so that the joint axis is its z axis; the user's body frame is placed in it by
// X_link_body and the user's joint frame by Joint::R_joint_link (outputs only).
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "kernel/model/constraint.hpp"
#include "kernel/joints/joint.hpp"
#include "kernel/spatial/inertia.hpp"

namespace heavesim {

/// Small per-joint vector (at most 7 entries), never on the heap.
using JointVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 7, 1>;

/// Linear spring-damper along every velocity coordinate of a joint:
///   tau = -stiffness .* (q minus rest) - damping .* v,
/// with "q minus rest" the joint's difference() (a rotation vector for spherical joints).
/// Units per coordinate: N/m and N s/m (translations), N m/rad and N m s/rad (rotations).
struct JointSpringDamper {
  JointVector stiffness;  // size nv
  JointVector damping;    // size nv
  JointVector rest;       // size nq
};

/// Soft limits of a 1-DoF joint: a one-sided penalty spring-damper acting only
/// beyond [lower, upper] (and the damper only while penetrating).
struct JointLimits {
  double lower = -std::numeric_limits<double>::infinity();
  double upper = std::numeric_limits<double>::infinity();
  double stiffness = 0.0;  // N/m or N m/rad
  double damping = 0.0;    // N s/m or N m s/rad
};

struct Joint {
  std::string name;
  JointType type;         // canonical: axis on the joint frame's z (universal: x then y)
  int parent = -1;        // parent link index
  Transform placement;    // X_parentlink_joint: parent-side (canonical) joint frame in the parent link frame
  Matrix3 R_joint_link = Matrix3::Identity();  // link (canonical joint) axes in the user's joint frame
  int q_index = 0, v_index = 0, nq = 0, nv = 0;
  std::optional<JointSpringDamper> spring;
  std::optional<JointLimits> limits;
};

struct Link {
  std::string name;                     // the body's name
  Inertia inertia;                      // rigid-body inertia about the link frame, link axes
  std::optional<Matrix6> added_inertia; // e.g. hydrodynamic A(inf), link frame, [angular; linear]
  Transform X_link_body;                // the user's body frame in the link frame
  std::vector<int> children;
  int subtree_end = 0;                  // one past the last link of this link's subtree
};

struct Model {
  std::vector<Link> links;    // links[0] is the ground
  std::vector<Joint> joints;  // joints[i] moves links[i]; joints[0] is a placeholder
  std::vector<Constraint> constraints;  // loop joints, distances, couplers (closed loops)
  int num_constraint_rows = 0;          // m: scalar constraint equations in all constraints
  // For every velocity coordinate c: the coordinate before it on the path to the root
  // (the previous coordinate of the same joint, else the last coordinate of the nearest
  // ancestor joint that has any), -1 at a root; always < c. M's nonzero entries lie on
  // these paths (CRBA, the tree-sparse L^T L). Derived topology, like subtree_end: set
  // by ModelBuilder.
  std::vector<int> velocity_coordinate_parent;
  // The configuration coordinates of the revolute joints, in link order: the position
  // stage takes their cos and sin two at a time (update_positions). Set by ModelBuilder.
  std::vector<int> revolute_coordinates;
  Vector3 gravity = Vector3(0.0, 0.0, -9.81);  // m/s^2, world frame
  int nq = 0;
  int nv = 0;

  int num_links() const { return static_cast<int>(links.size()); }
  /// Index of the link carrying this body name, -1 if none. "ground" is link 0.
  int link_index(const std::string& body_name) const;
  /// Index of the joint with this name, -1 if none.
  int joint_index(const std::string& joint_name) const;
  bool has_constraints() const { return num_constraint_rows > 0; }
  bool has_added_inertia() const;
  /// Total mass of all links [kg].
  double total_mass() const;
  /// Configuration with every joint at its neutral value (unit quaternions, zeros).
  VectorX neutral_configuration() const;
};

}  // namespace heavesim
