#pragma once
// Where a compensator acts: along a stroke axis between a base (the derrick top, part
// of the platform) and a moving side (rods, crown block). Two forms:
//
//  * joint form: the coordinate q of a prismatic joint. The force enters as a
//    generalized force on that coordinate, so the joint itself transmits it (its
//    reaction's axial component is the compensator force, docs/result-file.md).
//  * body form: two body points and an axis fixed in the base body. The force acts
//    as an equal and opposite pair at the moving point, on the moving body and on the
//    base body, along the axis (crown-block rigs where the stroke is not one joint).
//
// Stroke s [m] = displacement along the axis from mid-stroke, positive when the
// moving side moves away from the base along +axis (the rods extend);
// a positive compensator force pushes the moving side along +axis.
#include "kernel/elements/body_point.hpp"
#include "kernel/elements/force_element.hpp"

namespace heavesim {

struct StrokeAxis {
  int joint = -1;                              // model joint index (joint form), -1 for the body form
  BodyPoint base;                              // body form: base point (ground allowed)
  BodyPoint moving;                            // body form: moving point
  Vector3 axis_base_link = Vector3::UnitZ();   // body form: unit axis, base link frame
  double mid_stroke = 0.0;                     // m: q (joint form) or axial distance (body form) at s = 0

  /// Joint form on the prismatic joint `joint_index`.
  static StrokeAxis on_joint(const Model& model, int joint_index, double mid_stroke);
  /// Body form; `axis_base_body` is a unit vector in the base body's (user) frame.
  static StrokeAxis between(const Model& model, const BodyPoint& base, const BodyPoint& moving,
                            const Vector3& axis_base_body, double mid_stroke);
  bool joint_form() const { return joint >= 0; }
};

/// Stroke s [m] and its rate ds/dt [m/s] on the current position and velocity stages.
struct StrokeMotion {
  double stroke = 0.0;
  double rate = 0.0;
};
StrokeMotion stroke_motion(const StrokeAxis& axis, const Model& model, const Data& data);

/// Adds a force [N] along the stroke (positive extends it). Its power is force * ds/dt.
void apply_stroke_force(const StrokeAxis& axis, const Model& model, const Data& data, double force,
                        AppliedForces& forces);

/// Origin [m, world] of the base side: the prismatic joint's parent-side frame (joint
/// form) or the base point (body form), and its velocity [m/s, world]; this is where a
/// motion reference unit at the derrick measures.
struct BaseMotion {
  Vector3 position_world;
  Vector3 velocity_world;
  Vector3 axis_world;  // unit stroke axis, world frame
};
BaseMotion base_motion(const StrokeAxis& axis, const Model& model, const Data& data);

}  // namespace heavesim
