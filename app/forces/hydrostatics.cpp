#include "app/forces/hydrostatics.hpp"

#include "app/scene/hydro_scene.hpp"
#include "app/scene/scene_build_context.hpp"
#include "hydro/elements/nonlinear_hydrostatics.hpp"

namespace heavesim {
namespace {

constexpr KeySpec hydrostatics_keys[] = {
    {"name", "text", "–", "required", "unique"},
    {"type", "choice", "–", "required", "hydrostatics"},
    {"body", "text", "–", "required", "the floating body"},
    {"hst", "text", "–", "one of hst, mesh, stiffness", "WAMIT .hst, BEMIO .h5 or Capytaine .nc file"},
    {"mesh", "text", "–", "one of hst, mesh, stiffness", ".gdf or .stl hull (nonlinear)"},
    {"stiffness", "matrix", "N/m, N, N m/rad", "one of hst, mesh, stiffness", "C given directly"},
    {"displaced_volume", "number", "m³", "buoyancy = weight", "V for f0 = rho g V"},
    {"hst_includes_gravity", "boolean", "–", "`false`", "the .hst holds WAMIT's gravity terms"},
    {"length_scale", "number", "m", "1", "WAMIT ULEN"},
    {"description", "text", "–", "–", "free text"},
};

const BodyDefinition* find_body(const CaseDefinition& definition, const std::string& body) {
  for (const BodyDefinition& b : definition.bodies)
    if (b.name == body) return &b;
  return nullptr;
}

}  // namespace

std::span<const KeySpec> HydrostaticsDefinition::keys() { return hydrostatics_keys; }

HydrostaticsDefinition HydrostaticsDefinition::read(const NodeReader& item, const CaseDefinition&) {
  HydrostaticsDefinition def;
  item.expect_section("hydrostatics");
  if (item.has("hst") + item.has("mesh") + item.has("stiffness") != 1)
    item.fail("exactly one of 'hst' (linear: a WAMIT .hst, BEMIO .h5 or Capytaine .nc file), 'stiffness' (linear, a "
              "6 x 6 matrix) and 'mesh' (nonlinear, a .gdf or .stl hull)");
  std::string file_key;
  if (item.has("stiffness")) {
    // Linear hydrostatics given directly (e.g. from the hull's A_wp, V and waterplane
    // inertias): the buoyancy's restoring only; gravity acts on the bodies' masses.
    def.stiffness = read_matrix6(item["stiffness"]);
    check_symmetric_positive(item["stiffness"], def.stiffness, "stiffness");
  } else {
    file_key = item.has("hst") ? "hst" : "mesh";
  }
  def.nonlinear = file_key == "mesh";
  if (auto volume = item.optional("displaced_volume")) {
    if (def.nonlinear)
      volume->fail("'displaced_volume' with a mesh", "no 'displaced_volume' (the mesh gives the volume)");
    def.displaced_volume = volume->positive_number();
  }
  if (auto gravity = item.optional("hst_includes_gravity")) {
    if (!item.has("hst"))
      gravity->fail("'hst_includes_gravity' without 'hst'", "no 'hst_includes_gravity' (it says what a WAMIT .hst holds)");
    def.hst_includes_gravity = gravity->boolean();
  }
  def.body = item["body"].text();
  def.file = read_data_file(item, file_key, def.nonlinear);
  return def;
}

void HydrostaticsDefinition::read_data(const std::string& name, const CaseDefinition& definition,
                                       HydroData& data) const {
  if (file.key.empty()) {
    data.stiffness[name] = stiffness;
  } else if (!nonlinear) {
    data.stiffness[name] = read_checked(definition, name, file, [&] {
      return bem::read_hydrostatic_stiffness_file(file.path, wamit_scaling(definition, file.length_scale));
    });
  } else {
    const std::string& path = file.path;
    const bool stl = path.size() > 4 && (path.substr(path.size() - 4) == ".stl" || path.substr(path.size() - 4) == ".STL");
    data.meshes[name] = read_checked(definition, name, file, [&] { return stl ? hydro::read_stl(path) : hydro::read_gdf(path); });
  }
}

void HydrostaticsDefinition::build(const std::string& name, SceneBuildContext& context) const {
  const CaseDefinition& definition = context.definition;
  const double g = definition.gravity.norm(), rho = definition.water.density;
  add_hydro_element(context, name, body, [&](int link) -> std::unique_ptr<ForceElement> {
    if (nonlinear)
      return std::make_unique<hydro::NonlinearHydrostatics>(name, link, context.hydro_data.meshes.at(name), rho, g);
    const BodyDefinition& floating = *find_body(definition, body);  // the model has it
    hydro::LinearHydrostaticsSettings settings;
    settings.stiffness = context.hydro_data.stiffness.at(name);
    settings.stiffness_includes_gravity = hst_includes_gravity;
    settings.displaced_volume = displaced_volume;
    settings.body_mass = floating.inertia.mass();
    settings.center_of_mass = floating.inertia.com();
    settings.water_density = rho;
    settings.gravity = g;
    return hydro::linear_hydrostatics(name, link, settings);
  });
}

}  // namespace heavesim
