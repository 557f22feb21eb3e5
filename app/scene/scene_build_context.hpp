#pragma once
// What a force kind's build step (app/forces/) gets from the scene: the case, the model,
// the system it adds its element to, the handles the run summary reads, the assembled
// initial state, and the scene's name resolution and error mapping.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "app/case/case_definition.hpp"
#include "app/forces/compensator_stroke.hpp"
#include "app/scene/element_handles.hpp"
#include "kernel/elements/body_point.hpp"
#include "kernel/model/model_builder.hpp"
#include "kernel/system/multibody_system.hpp"

namespace heavesim {

struct HydroData;  // app/scene/hydro_scene.hpp

struct SceneBuildContext {
  SceneBuildContext(const CaseDefinition& definition, const Model& model, MultibodySystem& system,
                    SummarisedElements& summarised, const HydroData& hydro_data)
      : definition(definition), model(model), system(system), summarised(summarised), hydro_data(hydro_data) {}

  const CaseDefinition& definition;
  const Model& model;
  MultibodySystem& system;
  SummarisedElements& summarised;
  /// The hydro elements' data files and the sea, read before the model was built.
  const HydroData& hydro_data;
  double t_start = 0.0;  // s, the start of the run

  /// The assembled initial configuration q0 (set by the scene before BuildStage::on_assembled).
  const VectorX& initial_configuration() const { return *initial_configuration_; }
  void set_initial_configuration(const VectorX& q0) { initial_configuration_ = &q0; }

  /// The model at rest at q0 (positions and zero speeds in `data`; M(q0) in
  /// *mass_matrix, a reference into `data`), built at first use, shared by the
  /// compensators' static-balance analysis (control/analysis/static_balance.hpp).
  struct InitialState {
    explicit InitialState(const Model& model) : data(model) {}
    Data data;
    const MatrixX* mass_matrix = nullptr;
  };
  InitialState& initial_state();

  /// Every compensator built so far, with its stroke (the closed-loop analysis).
  std::vector<CompensatorOnStroke> compensators_on_strokes;
  /// Checks that need every element built (run by the scene after the last stage, in the
  /// order they were added).
  std::vector<std::function<void()>> after_build;

  /// An InputError at forces[name].<field>, at that key's position when known.
  InputError error(const std::string& name, const std::string& field, const std::string& found,
                   const std::string& expected) const {
    return definition.item_error(name, field, found, expected);
  }
  /// `point` [m] on `body` (body frame; "ground": world frame); an InputError at
  /// forces[name].<field> when `body` is not a body.
  BodyPoint body_point(const std::string& name, const std::string& field, const std::string& body,
                       const Vector3& point) const {
    if (body == ModelBuilder::ground_name) return {0, point};
    if (model.link_index(body) < 0)
      throw error(name, field, "'" + body + "', which is not a body", "'ground' or the name of a body");
    return BodyPoint::on_body(model, body, point);
  }

 private:
  const VectorX* initial_configuration_ = nullptr;
  std::optional<InitialState> initial_state_;
};

}  // namespace heavesim
