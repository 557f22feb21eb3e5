#include "app/scene/scene.hpp"

namespace heavesim {

Scene build_scene(const CaseDefinition& definition) {
  ModelBuilder builder;
  builder.set_gravity(definition.gravity);
  for (const BodyDefinition& body : definition.bodies) builder.add_body(body);
  for (const JointDefinition& joint : definition.joints) builder.add_joint(joint);

  Scene scene;
  try {
    scene.model = std::make_shared<const Model>(builder.build());
  } catch (const ModelError& error) {
    throw to_input_error(definition, error);
  }
  const Model& model = *scene.model;
  SystemSettings settings;
  settings.method = definition.solver.dynamics;
  scene.system = std::make_unique<MultibodySystem>(scene.model, settings);

  VectorX q0 = model.neutral_configuration();
  VectorX v0 = VectorX::Zero(model.nv);
  for (int i = 1; i < model.num_links(); ++i) {
    const Joint& joint = model.joints[i];
    auto it = definition.initial_states.find(joint.name);
    if (it == definition.initial_states.end()) continue;
    q0.segment(joint.q_index, joint.nq) = it->second.q;
    v0.segment(joint.v_index, joint.nv) = it->second.v;
  }
  scene.initial_state = scene.system->initial_state(q0, v0);
  return scene;
}

}  // namespace heavesim
