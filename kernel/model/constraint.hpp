#pragma once
// Constraints that close kinematic loops or tie coordinates together, as stored in
// the Model. Each is a set of scalar rows of Haug's basic kinds (E. J. Haug,
// Computer-Aided Kinematics and Dynamics of Mechanical Systems, 1989, ch. 3), written
// on frames A (on link_a) and B (on link_b):
//
//   along          d_A . (p_B - p_A) = 0        blocks translation along d (an axis of A)
//   perpendicular  a_A . b_B = 0                keeps an axis of A perpendicular to one of B
//   distance       (|p_B - p_A|^2 - L^2) / 2 = 0
//   coupler        q_a - ratio q_b - offset = 0 (coordinates of two 1-DoF joints)
//   driver         q_a,k - f(t) = 0            (prescribed motion of one joint coordinate)
//   length         |p_B - p_A|                 (a distance driver's measured coordinate, m)
//   angle          atan2(y_A . x_B, x_A . x_B) (an angle driver's: x_B's angle about z_A, rad)
//   expression     f(x, t) = 0                 (a user function of scalar joint coordinates x)
//   stop           side (q_j - bound) = 0      (a joint stop while it holds: one-sided)
//
// Drivers on frames (absolute: an `along` row on a world-fixed frame A; distance: a
// `length` row; angle: an `angle` row) subtract f(t) from their row, so that every
// driver reads "measured coordinate - f(t) = 0" and its multiplier is the actuator's
// force (N) or torque (N m) along the increasing coordinate (docs/physics/drivers.md).
//
// For every spatial row d(phi)/dt = G_B . (v_B - v_A) exactly, with G_B a world spatial
// force direction on B (and -G_B on A): this gives J, -dJ/dt v and the constraint's
// reaction wrench without finite differences (constraint_equations.hpp).
#include <functional>
#include <memory>
#include <string>
#include <variant>
#include <vector>

#include "kernel/joints/joint.hpp"
#include "kernel/model/constraint_function.hpp"
#include "kernel/spatial/transform.hpp"

namespace heavesim {

enum class ConstraintRowKind { along, perpendicular, distance, coupler, driver, length, angle, expression, stop };

struct ConstraintRow {
  ConstraintRowKind kind = ConstraintRowKind::along;
  int axis_a = 0;  // along: axis of frame A (0 x, 1 y, 2 z); perpendicular: axis of A
  int axis_b = 0;  // perpendicular: axis of frame B
  std::string description;  // e.g. "translation along x"
};

/// A prescribed motion f(t) and its first two time derivatives, in the joint
/// coordinate's units (m, m/s, m/s^2 or rad, rad/s, rad/s^2).
struct DriverMotion {
  double position = 0.0;
  double velocity = 0.0;
  double acceleration = 0.0;
};
using DriverFunction = std::function<DriverMotion(double t)>;

/// The kinds of constraint, like the joint types (joint.hpp): each holds what only it
/// needs. Loop joints and distances act between frames A and B (the frame fields of
/// Constraint); couplers and drivers act on joint coordinates.
struct LoopJointConstraint {
  JointKind joint_kind = JointKind::fixed;  // the joint it stands for
};
struct DistanceConstraint {
  double distance = 0.0;  // m, between the frame origins
};
struct CouplerConstraint {
  int joint_a = 0, joint_b = 0;      // the two 1-DoF joints (model joint indices)
  double ratio = 1.0, offset = 0.0;  // q_a = ratio q_b + offset
};
struct DriverConstraint {
  int joint = 0;          // model joint index
  int coordinate = 0;     // which coordinate of the joint it prescribes
  DriverFunction motion;  // q_joint,coordinate = motion(t).position
};
/// direction . p_B - f(t) = 0: a coordinate of a body point (frame B's origin) along a
/// world direction. Frame A is the ground frame turned so that its x is the direction
/// (link_a = 0), so that the row is an `along` row on x.
struct AbsoluteDriverConstraint {
  Vector3 direction_world = Vector3::UnitX();  // unit, world frame
  DriverFunction motion;                       // m
};
/// |p_B - p_A| - f(t) = 0 between the origins of frames A and B; f > 0.
struct DistanceDriverConstraint {
  DriverFunction motion;  // m
};
/// wrap(theta - f(t)) = 0, theta = atan2(y_A . x_B, x_A . x_B): the angle of frame B's
/// x axis about frame A's z axis, measured from A's x; wrapped into (-pi, pi] so that it
/// is continuous over any number of turns.
struct AngleDriverConstraint {
  DriverFunction motion;  // rad
};
/// f(x, t) = 0 over scalar joint coordinates x_k = q[q_index[k]] (revolute, prismatic,
/// a cylindrical or universal joint's coordinate: never a quaternion's), whose rates are
/// v[v_index[k]]. Like a coupler it acts on coordinates: its Jacobian row is df/dx on
/// the v indices and its multiplier a generalized force J^T lambda on those
/// coordinates (docs/physics/expression-constraints.md). It may read t, but it is not a
/// driver: it prescribes no measured coordinate, so it has no actuator force to report.
struct ExpressionConstraint {
  static constexpr int max_variables = 16;  // x is gathered on the stack (no allocation)
  std::vector<int> q_index, v_index;
  std::shared_ptr<const ConstraintFunction> function;
};
/// A one-sided stop on the coordinate of a 1-DoF joint, met by event location
/// (kernel/system/joint_stop_events.hpp): side (q - bound) >= 0, with side = +1 at a
/// lower bound and -1 at an upper one. Its row, side (q - bound) = 0, holds only while
/// the stop is active (Data::constraint_active); then its multiplier is the stop's
/// compressive force (>= 0; generalized force side lambda on the joint). Inactive, the
/// row is zero and counts nowhere. Restitution e at impacts faster than the events'
/// threshold.
struct JointStopConstraint {
  int joint = 0;        // model joint index (nq = nv = 1)
  double bound = 0.0;   // m or rad
  double side = 1.0;    // +1: q >= bound (lower); -1: q <= bound (upper)
  double restitution = 0.0;
};
using ConstraintKind = std::variant<LoopJointConstraint, DistanceConstraint, CouplerConstraint, DriverConstraint,
                                    AbsoluteDriverConstraint, DistanceDriverConstraint, AngleDriverConstraint,
                                    ExpressionConstraint, JointStopConstraint>;

struct Constraint {
  std::string name;
  ConstraintKind kind;
  // Frame constraints (loop joints, distances): frame A on link_a (the joint's parent
  // side), B on link_b.
  int link_a = 0, link_b = 0;
  Transform X_linkA_frame, X_linkB_frame;       // canonical frames (axis on z) in their links
  Matrix3 R_joint_frame = Matrix3::Identity();  // frame B's axes in the user's joint frame
  int first_row = 0;
  std::vector<ConstraintRow> rows;

  /// Whether it acts between frames A and B (loop joint, distance, the drivers on
  /// frames) rather than on coordinates.
  bool acts_on_frames() const {
    return std::holds_alternative<LoopJointConstraint>(kind) || std::holds_alternative<DistanceConstraint>(kind) ||
           std::holds_alternative<AbsoluteDriverConstraint>(kind) ||
           std::holds_alternative<DistanceDriverConstraint>(kind) || std::holds_alternative<AngleDriverConstraint>(kind);
  }
  /// The prescribed motion f(t) of a driver of any kind; null for other constraints.
  const DriverFunction* driver_motion() const {
    return std::visit(
        [](const auto& alternative) -> const DriverFunction* {
          if constexpr (requires { alternative.motion; })
            return &alternative.motion;
          else
            return nullptr;
        },
        kind);
  }
  bool is_driver() const { return driver_motion() != nullptr; }
  /// A joint stop: a row that holds only while active (unilateral).
  bool is_unilateral() const { return std::holds_alternative<JointStopConstraint>(kind); }
  /// "loop joint", "distance constraint", "coupler", "driver", "absolute driver",
  /// "distance driver", "angle driver", "expression constraint" or "joint stop".
  const char* kind_name() const {
    static constexpr const char* names[] = {"loop joint",      "distance constraint", "coupler",     "driver",
                                            "absolute driver", "distance driver",     "angle driver",
                                            "expression constraint", "joint stop"};
    return names[kind.index()];
  }
};

/// The rows that stand for a loop joint of this kind on canonical frames (axis on z;
/// universal: x on A, y on B): the complement of the joint's free motions.
std::vector<ConstraintRow> loop_joint_rows(JointKind kind);

}  // namespace heavesim
