#include "app/forces/mooring.hpp"

#include "app/scene/scene_build_context.hpp"

namespace heavesim {
namespace {

constexpr KeySpec mooring_keys[] = {
    {"name", "text", "–", "required", "unique"},
    {"type", "choice", "–", "required", "mooring"},
    {"body", "text", "–", "required", "the moored body"},
    {"stiffness", "matrix", "N/m, N, N m/rad", "required", "K, 6 x 6 or its diagonal"},
    {"pretension", "vector", "N, N m", "0", "f0"},
    {"description", "text", "–", "–", "free text"},
};

}  // namespace

std::span<const KeySpec> MooringDefinition::keys() { return mooring_keys; }

MooringDefinition MooringDefinition::read(const NodeReader& item, const CaseDefinition&) {
  MooringDefinition def;
  item.expect_section("mooring");
  def.stiffness = read_matrix6(item["stiffness"]);
  check_symmetric_positive(item["stiffness"], def.stiffness, "stiffness");
  if (auto tension = item.optional("pretension")) def.pretension = read_vector6(*tension);
  def.body = item["body"].text();
  return def;
}

void MooringDefinition::build(const std::string& name, SceneBuildContext& context) const {
  add_hydro_element(context, name, body, [&](int link) {
    return std::make_unique<hydro::LinearRestoring>(name, link, stiffness, pretension, Transform::Identity());
  });
}

}  // namespace heavesim
