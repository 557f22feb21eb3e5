#pragma once
// What every force kind of `forces:` provides (docs/architecture.md, "Adding a force
// kind"). A kind is one definition struct, in its own file of app/forces/, with
//   static constexpr std::string_view type;   // its `type` value and key-table section
//   static constexpr BuildStage stage;        // when the scene builds it (below)
//   static std::span<const KeySpec> keys();   // its keys (docs/case-format.md table)
//   static std::span<const SchemaSection> sub_sections();  // its nested sections
//                                             // (e.g. a compensator's `stroke`), maybe none
//   static Kind read(const NodeReader& item, const CaseDefinition& definition);
//                                             // forces[i], its name already read;
//                                             // `definition`: the case read so far
//   void build(const std::string& name, SceneBuildContext& context) const;
// optionally (the hydro kinds, whose data files are read before the model is built)
//   void read_data(const std::string& name, const CaseDefinition& definition, HydroData& data) const;
// and one line in app/forces/force_kinds.hpp; the registry (force_registry.hpp) and the
// scene derive everything else from that list.
#include <span>
#include <string>
#include <string_view>

#include "app/case/case_schema.hpp"
#include "app/case/node_reader.hpp"

namespace heavesim {

struct CaseDefinition;     // app/case/case_definition.hpp
struct SceneBuildContext;  // app/scene/scene_build_context.hpp

/// When the scene builds a kind. Within a stage the elements are added in the order the
/// case declares them; the stages run in this order, which fixes each element's index
/// and state offset in the system (and so the order of outputs and summaries).
enum class BuildStage {
  on_model,       // as soon as the model exists (the kernel's spring-dampers, point forces)
  hydro,          // then the hydrodynamic elements
  on_assembled,   // after the initial state is assembled onto the loops (ground contacts)
  compensators,   // last: a compensator's static balance counts every other element
};

}  // namespace heavesim
