// Reads drivers[i] (docs/case-format.md, "drivers[i]" and the absolute, distance and
// angle driver sections).
#include "app/case/driver_reader.hpp"

#include <fmt/format.h>

#include "app/case/frame_reader.hpp"
#include "app/case/motion_reader.hpp"

namespace heavesim {
namespace {

/// The name of a body (or ground) at `key`; another name is refused there with the
/// closest body name as a did-you-mean. The bodies are read before the drivers.
std::string body_name(const NodeReader& item, const std::string& key, const CaseDefinition& definition) {
  const NodeReader reader = item[key];
  const std::string name = reader.text();
  std::vector<std::string> candidates = {ModelBuilder::ground_name};
  for (const BodyDefinition& body : definition.bodies) {
    if (body.name == name) return name;
    candidates.push_back(body.name);
  }
  if (name == ModelBuilder::ground_name) return name;
  const std::string suggestion = closest_match(name, candidates);
  reader.fail("'" + name + "', which is not a body",
              suggestion.empty() ? "'ground' or the name of a body"
                                 : "'" + suggestion + "' (did you mean it?), 'ground' or the name of a body");
}

/// A point on a body [m, body frame] as a frame with that origin; the origin when absent.
Transform point_frame(const NodeReader& item, const std::string& key) {
  const std::optional<NodeReader> point = item.optional(key);
  return Transform::from_translation(point ? point->vector3_in(length_range) : Vector3::Zero());
}

/// The key that gives a driver's motion (`position`, or a tabulated motion's `table`).
NodeReader motion_key(const NodeReader& item) {
  for (const char* key : {"position", "table"})
    if (item.has(key)) return item[key];
  return item;
}

}  // namespace

void read_driver(const NodeReader& item, const std::string& name, CaseDefinition& definition,
                 const ExpressionContext& expressions) {
  const std::string type =
      item.optional("type") ? item["type"].choice({"joint", "absolute", "distance", "angle"}) : "joint";
  DriverDefinition def;
  def.name = name;
  if (type == "joint") {
    item.expect_section("drivers[i]");
    def.joint = item["joint"].text();
    def.coordinate = static_cast<int>(item.optional("coordinate") ? item["coordinate"].integer() : 0);
  } else if (type == "absolute") {
    item.expect_section("absolute_driver");
    def.kind = DriverKind::absolute;
    def.body_b = body_name(item, "body", definition);
    def.X_body_b_frame = point_frame(item, "point");
    def.direction = item["direction"].vector3();  // its length is the model's check (ModelError at the key)
  } else if (type == "distance") {
    item.expect_section("distance_driver");
    def.kind = DriverKind::distance;
    def.body_a = body_name(item, "body_a", definition);
    def.X_body_a_frame = point_frame(item, "point_a");
    def.body_b = body_name(item, "body_b", definition);
    def.X_body_b_frame = point_frame(item, "point_b");
  } else {
    item.expect_section("angle_driver");
    def.kind = DriverKind::angle;
    def.body_a = body_name(item, "body_a", definition);
    def.X_body_a_frame = read_frame(item.optional("frame_a"));
    def.body_b = body_name(item, "body_b", definition);
    def.X_body_b_frame = read_frame(item.optional("frame_b"));
  }
  const std::shared_ptr<const TimeFunction> function = read_motion(item, name, expressions);
  def.motion = [function](double t) { return (*function)(t); };
  definition.drivers.push_back(std::move(def));
}

void check_distance_drivers_over_run(const CaseDefinition& definition, const std::optional<NodeReader>& drivers) {
  if (!drivers) return;
  const std::vector<NodeReader> items = drivers->items();
  const long intervals = output_interval_count(definition.solver, definition.output.interval);
  const double t0 = definition.solver.t_start, t1 = definition.solver.t_end;
  for (std::size_t d = 0; d < definition.drivers.size(); ++d) {
    const DriverDefinition& driver = definition.drivers[d];
    if (driver.kind != DriverKind::distance) continue;
    for (long k = 0; k <= intervals; ++k) {
      const double t = k == intervals ? t1 : t0 + (t1 - t0) * static_cast<double>(k) / static_cast<double>(intervals);
      const double length = driver.motion(t).position;
      if (!(length > 0.0))
        motion_key(items[d]).fail(fmt::format("a distance of {:g} m at t = {:g} s", length, t),
                                  "a distance > 0 at every output time of the run (points that meet have no "
                                  "direction between them: use a spherical loop joint)");
    }
  }
}

}  // namespace heavesim
