#include "app/case/contact_reader.hpp"

#include <algorithm>
#include <set>

#include "app/case/frame_reader.hpp"

namespace heavesim {
namespace {

/// `key`'s text if it is one of `names`; else a failure there naming the closest.
std::string one_of(const NodeReader& item, const std::string& key, const std::vector<std::string>& names,
                   const std::string& what) {
  const NodeReader reader = item[key];
  const std::string name = reader.text();
  for (const std::string& candidate : names)
    if (candidate == name) return name;
  const std::string suggestion = closest_match(name, names);
  reader.fail("'" + name + "', which is not " + what,
              suggestion.empty() ? what : "'" + suggestion + "' (did you mean it?), or " + what);
}

std::string unique_name(const NodeReader& item, std::set<std::string>& names, const std::string& fallback) {
  const std::string name = item.optional("name") ? item["name"].text() : fallback;
  if (!names.insert(name).second)
    (item.optional("name") ? item["name"] : item).fail("a second item named '" + name + "'", "unique names");
  return name;
}

}  // namespace

void read_contacts(const NodeReader& section, CaseDefinition& definition) {
  section.expect_section("contacts");
  ContactDefinition& contacts = definition.contacts;
  if (auto margin = section.optional("margin")) contacts.margin = margin->non_negative_number(length_range);
  std::vector<std::string> bodies = {ModelBuilder::ground_name}, joints, geometry_names;
  for (const BodyDefinition& body : definition.bodies) bodies.push_back(body.name);
  for (const JointDefinition& joint : definition.joints) joints.push_back(joint.name);
  std::set<std::string> geometry_set, pair_set, stop_set, line_set;  // names unique within each list
  if (auto geometries = section.optional("geometries"))
    for (const NodeReader& item : geometries->items()) {
      item.expect_section("contact_geometry");
      ContactGeometryDefinition geometry;
      geometry.name = unique_name(item, geometry_set, item["name"].text());
      geometry.body = one_of(item, "body", bodies, "a body or 'ground'");
      geometry.X_body_shape = read_frame(item.optional("frame"));
      const std::string shape = item["shape"].choice({"sphere", "box", "cylinder", "plane"});
      // Sizes are taken as given; their rules (> 0, the shape's own keys) are the
      // kernel's check, reported at these keys by the scene.
      geometry.shape.kind = shape == "sphere" ? ContactShapeKind::sphere
                            : shape == "box"  ? ContactShapeKind::box
                            : shape == "cylinder" ? ContactShapeKind::cylinder
                                                  : ContactShapeKind::plane;
      if (auto radius = item.optional("radius")) geometry.shape.radius = radius->number_in(length_range);
      if (auto half = item.optional("half_length")) geometry.shape.half_length = half->number_in(length_range);
      if (auto half = item.optional("half_extents")) geometry.shape.half_extents = half->vector3_in(length_range);
      // A shape's size keys are required (the missing-key error names them).
      if (shape == "sphere" || shape == "cylinder") item["radius"];
      if (shape == "cylinder") item["half_length"];
      if (shape == "box") item["half_extents"];
      contacts.geometries.push_back(geometry);
      geometry_names.push_back(geometry.name);
    }
  if (auto pairs = section.optional("pairs"))
    for (const NodeReader& item : pairs->items()) {
      item.expect_section("contact_pair");
      ContactPairDefinition pair;
      pair.geometry_a = one_of(item, "a", geometry_names, "a contact geometry");
      pair.geometry_b = one_of(item, "b", geometry_names, "a contact geometry");
      pair.name = unique_name(item, pair_set, pair.geometry_a + "_on_" + pair.geometry_b);
      pair.friction_coefficient = item.number_or("friction_coefficient", 0.0);
      pair.restitution = item.number_or("restitution", 0.0);
      if (auto torsion = item.optional("torsional_friction")) pair.torsional_friction = torsion->number_in(length_range);
      if (auto directions = item.optional("friction_directions"))
        pair.friction_directions = static_cast<int>(std::clamp(directions->integer(), -1L, 1000L));  // the kernel checks 2..16
      contacts.pairs.push_back(pair);
    }
  if (auto stops = section.optional("joint_stops"))
    for (const NodeReader& item : stops->items()) {
      item.expect_section("joint_stop");
      JointStopDefinition stop;
      stop.joint = one_of(item, "joint", joints, "a joint of the tree");
      stop.name = unique_name(item, stop_set, stop.joint + "_stop");
      if (auto lower = item.optional("lower")) stop.lower = lower->number();
      if (auto upper = item.optional("upper")) stop.upper = upper->number();
      if (!item.has("lower") && !item.has("upper")) item["lower"];  // at least one bound
      stop.restitution = item.number_or("restitution", 0.0);
      contacts.joint_stops.push_back(stop);
    }
  if (auto lines = section.optional("lines"))
    for (const NodeReader& item : lines->items()) {
      item.expect_section("tension_line");
      TensionLineDefinition line;
      line.body_a = one_of(item, "body_a", bodies, "a body or 'ground'");
      line.body_b = one_of(item, "body_b", bodies, "a body or 'ground'");
      line.name = unique_name(item, line_set, line.body_a + "_to_" + line.body_b);
      if (auto point = item.optional("point_a")) line.point_a = point->vector3_in(length_range);
      if (auto point = item.optional("point_b")) line.point_b = point->vector3_in(length_range);
      line.length = item["length"].number_in(length_range);  // > 0: the kernel's check, at this key
      line.restitution = item.number_or("restitution", 0.0);
      contacts.lines.push_back(line);
    }
}

}  // namespace heavesim
