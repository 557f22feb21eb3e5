#include "kernel/contact/contact_model.hpp"

#include <cmath>
#include <sstream>

#include "kernel/model/model.hpp"
#include "kernel/parameter_error.hpp"

namespace heavesim {

const char* to_string(ContactShapeKind kind) {
  switch (kind) {
    case ContactShapeKind::sphere: return "sphere";
    case ContactShapeKind::box: return "box";
    case ContactShapeKind::cylinder: return "cylinder";
    case ContactShapeKind::plane: return "plane";
  }
  return "?";
}

namespace {

bool positive(double x) { return std::isfinite(x) && x > 0.0; }

std::string number(double x) {
  std::ostringstream text;
  text << x;
  return text.str();
}

void check_shape(const ContactShape& shape, const std::string& field) {
  const auto require_positive = [&](double value, const char* name) {
    if (!positive(value)) throw ParameterError(field + "." + name, number(value), "a length > 0 m");
  };
  switch (shape.kind) {
    case ContactShapeKind::sphere: require_positive(shape.radius, "radius"); return;
    case ContactShapeKind::cylinder:
      require_positive(shape.radius, "radius");
      require_positive(shape.half_length, "half_length");
      return;
    case ContactShapeKind::box:
      for (int k = 0; k < 3; ++k)
        if (!positive(shape.half_extents[k]))
          throw ParameterError(field + ".half_extents[" + std::to_string(k) + "]", number(shape.half_extents[k]),
                               "a length > 0 m");
      return;
    case ContactShapeKind::plane: return;
  }
}

/// The pairs the narrow phase (contact_detection.cpp) has a routine for.
bool supported(ContactShapeKind a, ContactShapeKind b) {
  using K = ContactShapeKind;
  if (a == K::plane) std::swap(a, b);
  if (b == K::plane) return a != K::plane;
  if (a == K::cylinder || b == K::cylinder) return false;
  return true;  // sphere-sphere, sphere-box, box-box
}

}  // namespace

void check_contact_model(const Model& model, const ContactModel& contacts) {
  const int geometries = static_cast<int>(contacts.geometries.size());
  for (int g = 0; g < geometries; ++g) {
    const ContactGeometry& geometry = contacts.geometries[g];
    const std::string field = "geometries[" + std::to_string(g) + "]";
    if (geometry.link < 0 || geometry.link >= model.num_links())
      throw ParameterError(field + ".link", std::to_string(geometry.link) + " (geometry '" + geometry.name + "')",
                           "a link index 0.." + std::to_string(model.num_links() - 1));
    check_shape(geometry.shape, field);
  }
  for (int p = 0; p < static_cast<int>(contacts.pairs.size()); ++p) {
    const ContactPair& pair = contacts.pairs[p];
    const std::string field = "pairs[" + std::to_string(p) + "]";
    for (const int index : {pair.geometry_a, pair.geometry_b})
      if (index < 0 || index >= geometries)
        throw ParameterError(field + ".geometry", std::to_string(index),
                             "a geometry index 0.." + std::to_string(geometries - 1));
    const ContactGeometry& a = contacts.geometries[pair.geometry_a];
    const ContactGeometry& b = contacts.geometries[pair.geometry_b];
    const std::string named = " (pair '" + a.name + "' with '" + b.name + "')";
    if (a.link == b.link)
      throw ParameterError(field, "both geometries on one link" + named, "geometries on two different links");
    if (!supported(a.shape.kind, b.shape.kind))
      throw ParameterError(field, std::string(to_string(a.shape.kind)) + " with " + to_string(b.shape.kind) + named,
                           "a pair with a contact routine: sphere, box or cylinder with a plane; sphere or box "
                           "with sphere or box");
    if (!(std::isfinite(pair.friction_coefficient) && pair.friction_coefficient >= 0.0))
      throw ParameterError(field + ".friction_coefficient", number(pair.friction_coefficient) + named,
                           "a finite number >= 0");
    if (!(pair.restitution >= 0.0 && pair.restitution <= 1.0))
      throw ParameterError(field + ".restitution", number(pair.restitution) + named, "0 <= e <= 1");
    if (!(std::isfinite(pair.torsional_friction) && pair.torsional_friction >= 0.0))
      throw ParameterError(field + ".torsional_friction", number(pair.torsional_friction) + named,
                           "a finite length >= 0 m");
    if (pair.friction_directions < 2 || pair.friction_directions > ContactPair::max_friction_directions)
      throw ParameterError(field + ".friction_directions", std::to_string(pair.friction_directions) + named,
                           "2.." + std::to_string(ContactPair::max_friction_directions) +
                               " tangent directions (a friction polygon of 4..32 faces)");
  }
  for (int s = 0; s < static_cast<int>(contacts.joint_stops.size()); ++s) {
    const JointStop& stop = contacts.joint_stops[s];
    const std::string field = "joint_stops[" + std::to_string(s) + "]";
    if (stop.joint < 1 || stop.joint >= static_cast<int>(model.joints.size()))
      throw ParameterError(field + ".joint", std::to_string(stop.joint),
                           "a joint index 1.." + std::to_string(model.joints.size() - 1));
    const Joint& joint = model.joints[stop.joint];
    if (joint.nv != 1 || joint.nq != 1)
      throw ParameterError(field + ".joint",
                           "'" + joint.name + "' with " + std::to_string(joint.nv) + " velocity coordinates",
                           "a 1-DoF joint (revolute or prismatic)");
    if (std::isnan(stop.lower) || std::isnan(stop.upper) || !(stop.lower < stop.upper))
      throw ParameterError(field, "bounds [" + number(stop.lower) + ", " + number(stop.upper) + "] on '" +
                                      joint.name + "'",
                           "lower < upper");
    if (!(stop.restitution >= 0.0 && stop.restitution <= 1.0))
      throw ParameterError(field + ".restitution", number(stop.restitution), "0 <= e <= 1");
  }
  for (int l = 0; l < static_cast<int>(contacts.lines.size()); ++l) {
    const TensionLine& line = contacts.lines[l];
    const std::string field = "lines[" + std::to_string(l) + "]";
    for (const int link : {line.link_a, line.link_b})
      if (link < 0 || link >= model.num_links())
        throw ParameterError(field + ".link", std::to_string(link) + " (line '" + line.name + "')",
                             "a link index 0.." + std::to_string(model.num_links() - 1));
    if (line.link_a == line.link_b)
      throw ParameterError(field, "both ends of line '" + line.name + "' on one link", "ends on two different links");
    if (!line.point_a.allFinite() || !line.point_b.allFinite())
      throw ParameterError(field + (line.point_a.allFinite() ? ".point_b" : ".point_a"), "a point that is not finite",
                           "finite coordinates in m");
    if (!positive(line.length)) throw ParameterError(field + ".length", number(line.length), "a length > 0 m");
    if (!(line.restitution >= 0.0 && line.restitution <= 1.0))
      throw ParameterError(field + ".restitution", number(line.restitution), "0 <= e <= 1");
  }
  if (!(std::isfinite(contacts.margin) && contacts.margin >= 0.0))
    throw ParameterError("margin", number(contacts.margin), "a finite length >= 0 m");
}

}  // namespace heavesim
