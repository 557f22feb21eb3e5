#include "app/forces/compensator_stroke.hpp"

#include <tuple>

#include <fmt/format.h>

#include "app/scene/scene_build_context.hpp"

namespace heavesim {
namespace {

constexpr KeySpec stroke_table[] = {
    {"joint", "text", "–", "one of joint, base and moving", "joint form: a prismatic joint"},
    {"base", "map", "–", "one of joint, base and moving", "bodies form: `{body, point}` of the base"},
    {"moving", "map", "–", "required with base", "bodies form: `{body, point}` of the moving side"},
    {"axis", "vector", "–", "`[0, 0, 1]`", "bodies form: unit axis, base body frame"},
    {"mid_stroke", "number", "m", "0", "q or axial distance at s = 0"},
};

constexpr KeySpec body_point_table[] = {
    {"body", "text", "–", "required", "body name or `ground`"},
    {"point", "vector", "m", "`[0, 0, 0]`", "point in the body frame"},
};

constexpr KeySpec seal_friction_table[] = {
    {"coulomb", "number", "N", "0", "F_c"},
    {"viscous", "number", "N·s/m", "0", "c_v"},
    {"smoothing_speed", "number", "m/s", "0.01", "v_s"},
};

}  // namespace

std::span<const KeySpec> stroke_keys() { return stroke_table; }
std::span<const KeySpec> body_point_keys() { return body_point_table; }
std::span<const KeySpec> seal_friction_keys() { return seal_friction_table; }

bool StrokeDefinition::same_as(const StrokeDefinition& other) const {
  return joint_form() ? joint == other.joint
                      : !other.joint_form() && base_body == other.base_body && moving_body == other.moving_body;
}

double positive_or(const NodeReader& item, const std::string& key, double default_value) {
  auto node = item.optional(key);
  return node ? node->positive_number() : default_value;
}

double non_negative_or(const NodeReader& item, const std::string& key, double default_value) {
  auto node = item.optional(key);
  return node ? node->non_negative_number() : default_value;
}

double absolute_pressure(const NodeReader& node, double atmospheric, const std::string& what) {
  const double value = node.number();
  if (!(value >= atmospheric))
    node.fail(fmt::format("{} = {:g} Pa, below atmospheric pressure ({:g} Pa)", what, value, atmospheric),
              "an absolute pressure >= the atmospheric pressure");
  return value;
}

std::pair<std::string, Vector3> read_body_point(const NodeReader& reader) {
  reader.expect_section("body_point");
  return {reader["body"].text(), reader.optional("point") ? reader["point"].vector3_in(length_range) : Vector3::Zero()};
}

StrokeDefinition read_stroke(const NodeReader& reader) {
  reader.expect_section("stroke");
  StrokeDefinition stroke;
  stroke.mid_stroke = reader.number_or("mid_stroke", 0.0);
  if (reader.has("joint")) {
    for (const char* key : {"base", "moving", "axis"})
      if (reader.has(key))
        reader[key].fail(fmt::format("'{}' together with 'joint'", key),
                         "either {joint} (a prismatic joint) or {base, moving, axis} (two body points)");
    stroke.joint = reader["joint"].text();
    return stroke;
  }
  if (!reader.has("base") && !reader.has("moving"))
    reader.fail("{joint: <prismatic joint>} or {base: {body, point}, moving: {body, point}, axis: [x, y, z]}");
  std::tie(stroke.base_body, stroke.base_point) = read_body_point(reader["base"]);
  std::tie(stroke.moving_body, stroke.moving_point) = read_body_point(reader["moving"]);
  stroke.axis = reader.optional("axis") ? reader["axis"].unit_vector3() : Vector3::UnitZ();
  return stroke;
}

SealFriction read_friction(const NodeReader& reader) {
  reader.expect_section("seal_friction");
  return {non_negative_or(reader, "coulomb", 0.0), non_negative_or(reader, "viscous", 0.0),
          positive_or(reader, "smoothing_speed", 0.01)};
}

StrokeAxis resolve_stroke(const SceneBuildContext& context, const std::string& name, const StrokeDefinition& stroke) {
  const Model& model = context.model;
  if (stroke.joint_form()) {
    const int joint = model.joint_index(stroke.joint);
    if (joint < 1)
      throw context.error(name, "stroke.joint", "'" + stroke.joint + "', which is not a joint",
                          "the name of a prismatic joint (the stroke is its coordinate)");
    return StrokeAxis::on_joint(model, joint, stroke.mid_stroke);  // ParameterError("joint") unless prismatic
  }
  const BodyPoint base = context.body_point(name, "stroke.base", stroke.base_body, stroke.base_point);
  const BodyPoint moving = context.body_point(name, "stroke.moving", stroke.moving_body, stroke.moving_point);
  if (base.link == moving.link)
    throw context.error(name, "stroke.moving", "the same body as the base", "a body that moves relative to the base");
  return StrokeAxis::between(model, base, moving, stroke.axis, stroke.mid_stroke);
}

const std::map<std::string, std::string>& compensator_keys() {
  static const std::map<std::string, std::string> keys{
      {"joint", "stroke.joint"},
      {"acceleration_feedforward", "controller.acceleration_feedforward"},
      {"max_rate", "actuator.max_rate"}};
  return keys;
}

}  // namespace heavesim
