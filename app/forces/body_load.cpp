#include "app/forces/body_load.hpp"

#include <cmath>

#include "app/case/motion_reader.hpp"
#include "app/scene/scene_build_context.hpp"
#include "kernel/elements/body_point.hpp"
#include "kernel/elements/force_element.hpp"

namespace heavesim {
namespace {

constexpr KeySpec body_load_keys[] = {
    {"name", "text", "–", "required", "unique"},
    {"type", "choice", "–", "required", "body_load"},
    {"body", "text", "–", "required", "the loaded body"},
    {"point", "vector", "m", "`[0, 0, 0]`", "where the force acts, body frame"},
    {"frame", "choice", "–", "`body`", "`body`: components turn with the body (follower load); `world`: fixed axes"},
    {"force", "list", "N", "`[0, 0, 0]`", "three expressions of t: the force's components in `frame`"},
    {"moment", "list", "N m", "`[0, 0, 0]`", "three expressions of t: the couple's components in `frame`"},
    {"description", "text", "–", "–", "free text"},
};

constexpr const char* expected_components = "a list of three expressions of t such as [0, 0, -2e4*(1 + sin(t))]";

/// A force at a body point and a couple, each with components f(t) in the body frame or
/// the world frame. Its virtual work is F . dp + M . dtheta: the kernel takes it as the
/// world wrench (M + p x F; F) about the world origin on the body's link.
class BodyLoad : public ForceElement {
 public:
  BodyLoad(std::string name, BodyPoint point, const Matrix3& R_link_body, bool world_frame,
           BodyLoadDefinition::Components force, BodyLoadDefinition::Components moment)
      : name_(std::move(name)), point_(point), R_link_body_(R_link_body), world_frame_(world_frame),
        force_(std::move(force)), moment_(std::move(moment)) {
    for (const auto* components : {&force_, &moment_})
      for (const auto& component : *components) depends_on_time_ |= component && component->position_uses_time();
  }
  const std::string& name() const override { return name_; }
  void apply(double t, const Model&, const Data& data, Eigen::Ref<const VectorX>, AppliedForces& forces) const override {
    Vector3 force = evaluate(force_, t), moment = evaluate(moment_, t);
    if (!world_frame_) {
      const Matrix3 R_world_body = data.X_world_link[point_.link].rotation() * R_link_body_;
      force = R_world_body * force;
      moment = R_world_body * moment;
    }
    forces.add_force_at_point(point_.link, point_.position_world(data), force);
    forces.external_force_world[point_.link].angular() += moment;
  }
  /// Where the point is, and (body frame) how the body is turned.
  ElementDependencies dependencies() const override { return {depends_on_time_, true, false, false, false}; }
  /// 0: a follower or time-varying load is not conservative; its work shows as a change
  /// of the total energy (as a joint torque's does).
  double potential_energy(const Model&, const Data&, Eigen::Ref<const VectorX>) const override { return 0.0; }

 private:
  static Vector3 evaluate(const BodyLoadDefinition::Components& components, double t) {
    Vector3 value = Vector3::Zero();
    for (int k = 0; k < 3; ++k)
      if (components[k]) value[k] = components[k]->position(t);
    return value;
  }

  std::string name_;
  BodyPoint point_;
  Matrix3 R_link_body_;  // the user's body axes in the link frame
  bool world_frame_;
  BodyLoadDefinition::Components force_, moment_;
  bool depends_on_time_ = false;
};

BodyLoadDefinition::Components read_components(const NodeReader& item, const std::string& key) {
  BodyLoadDefinition::Components components;
  const std::optional<NodeReader> list = item.optional(key);
  if (!list) return components;
  const std::vector<NodeReader> entries = list->node().is_sequence() ? list->items() : std::vector<NodeReader>{};
  if (entries.size() != 3) list->fail(list->node().describe(), expected_components);
  for (int k = 0; k < 3; ++k)
    components[k] = read_time_expression(entries[k], item["name"].text(), item.expressions(), "body load",
                                         expected_components);
  return components;
}

}  // namespace

std::span<const KeySpec> BodyLoadDefinition::keys() { return body_load_keys; }

BodyLoadDefinition BodyLoadDefinition::read(const NodeReader& item, const CaseDefinition&) {
  BodyLoadDefinition def;
  item.expect_section(type);
  def.body = item["body"].text();
  if (auto point = item.optional("point")) def.point = point->vector3_in(length_range);
  if (auto frame = item.optional("frame")) def.world_frame = frame->choice({"body", "world"}) == "world";
  def.force = read_components(item, "force");
  def.moment = read_components(item, "moment");
  return def;
}

void BodyLoadDefinition::build(const std::string& name, SceneBuildContext& context) const {
  // Every component was checked finite over the run at load (check_motions_over_run).
  const BodyPoint point_on_body = context.body_point(name, "body", body, point);
  const Matrix3 R_link_body = body == ModelBuilder::ground_name
                                  ? Matrix3::Identity()
                                  : context.model.links[point_on_body.link].X_link_body.rotation();
  context.system.add_force_element(
      std::make_unique<BodyLoad>(name, point_on_body, R_link_body, world_frame, force, moment));
}

}  // namespace heavesim
