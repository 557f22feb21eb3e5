#pragma once
// Contact points between the shapes of a ContactModel at the current position stage:
// for every pair, the points where the two convex shapes touch or come within the
// margin, each with a unit normal, two unit tangents and the signed gap (negative:
// overlap). Narrow phase by shape pair (docs/physics/contact.md, "Geometry"):
//   sphere-plane, sphere-sphere, sphere-box        one point (closest points)
//   box-plane                                      the box corners within the margin
//   cylinder-plane                                 the lowest rim point of each end
//                                                  (4 rim points per end when upright)
//   box-box                                        corners of either box against the
//                                                  faces of the other (vertex-face;
//                                                  edge-edge contact is not generated)
// A pair of kinds not listed (plane-plane, cylinder with anything but a plane) is
// refused by check_contact_model before a run.
#include <span>

#include "kernel/contact/contact_model.hpp"
#include "kernel/model/data.hpp"

namespace heavesim {

struct ContactPoint {
  int pair = 0;                              ///< index into ContactModel::pairs
  int link_a = 0, link_b = 0;                ///< links of the pair's geometries a and b
  Vector3 point_world = Vector3::Zero();     ///< m: midway between the two surfaces
  Vector3 normal_world = Vector3::UnitZ();   ///< unit, from b towards a (a is pushed along +n)
  Vector3 tangent1_world = Vector3::UnitX(); ///< unit, normal x tangent1 = tangent2
  Vector3 tangent2_world = Vector3::UnitY();
  double gap = 0.0;                          ///< m: signed distance of the surfaces along n
};

/// The most points the narrow phase can produce for all pairs of `contacts` at once
/// (per pair: 1 with a sphere; 8 for a box or a cylinder on a plane; 16 for two boxes).
int max_contact_points(const ContactModel& contacts);

/// Writes the contact points of every pair with gap < contacts.margin into `out`
/// (positions from `data`'s position stage) and returns how many; stops at out.size()
/// and returns out.size() + 1 if more were found (the caller sized it too small).
/// Allocation-free.
int detect_contacts(const Model& model, const Data& data, const ContactModel& contacts, std::span<ContactPoint> out);

}  // namespace heavesim
