#include "app/case/hydro_reader.hpp"

#include <algorithm>
#include <climits>
#include <cmath>
#include <filesystem>

#include <fmt/format.h>

#include "io/bem/bem_file.hpp"

namespace heavesim {
namespace {

hydro::Ramp read_ramp(const NodeReader& reader) {
  // ramp: a duration [s] (cosine ramp), or {kind: cosine | tanh | none, duration: ..}
  hydro::Ramp ramp;
  if (reader.node().is_scalar()) {
    ramp.kind = hydro::RampKind::cosine;
    ramp.duration = reader.non_negative_number();
    return ramp;
  }
  reader.expect_section("ramp");
  const std::string kind = reader["kind"].choice({"cosine", "tanh", "none"});
  ramp.kind = kind == "cosine" ? hydro::RampKind::cosine
              : kind == "tanh" ? hydro::RampKind::hyperbolic_tangent
                               : hydro::RampKind::none;
  if (ramp.kind != hydro::RampKind::none) ramp.duration = reader["duration"].positive_number();
  return ramp;
}

/// A 6 x 6 matrix in WAMIT order: 6 rows of 6 numbers, or 6 numbers (its diagonal).
hydro::Matrix6 read_matrix6(const NodeReader& reader) {
  const char* expected = "6 rows of 6 numbers, or 6 numbers (the diagonal), WAMIT order [surge, sway, heave, roll, "
                         "pitch, yaw]";
  if (!reader.node().is_sequence()) reader.fail(expected);
  const std::vector<NodeReader> items = reader.items();
  if (items.size() != 6) reader.fail(fmt::format("{} entries", items.size()), expected);
  hydro::Matrix6 matrix = hydro::Matrix6::Zero();
  if (items[0].node().is_scalar()) {
    for (int i = 0; i < 6; ++i) matrix(i, i) = items[i].number();
    return matrix;
  }
  for (int i = 0; i < 6; ++i) {
    const std::vector<double> row = items[i].node().is_sequence() ? items[i].numbers() : std::vector<double>{};
    if (row.size() != 6) items[i].fail("a row of 6 numbers");
    for (int j = 0; j < 6; ++j) matrix(i, j) = row[j];
  }
  return matrix;
}

hydro::Vector6 read_vector6(const NodeReader& reader) {
  const std::vector<double> values = reader.node().is_sequence() ? reader.numbers() : std::vector<double>{};
  if (values.size() != 6) reader.fail("6 numbers in WAMIT order [surge, sway, heave, roll, pitch, yaw]");
  return Eigen::Map<const hydro::Vector6>(values.data());
}

/// A data file next to the case: relative paths are taken from the directory of the file
/// that holds the key (an included file's own directory); the file must exist.
std::string read_data_file(const NodeReader& reader) {
  const std::string text = reader.text();
  std::filesystem::path path(text);
  if (path.is_relative()) path = std::filesystem::path(reader.location().file).parent_path() / path;
  if (!std::filesystem::is_regular_file(path))
    reader.fail(fmt::format("'{}', which is not a readable file ({})", text, path.string()),
                "a path to an existing data file, relative to the case file");
  return path.lexically_normal().string();
}

void check_symmetric_positive(const NodeReader& reader, const hydro::Matrix6& matrix, const std::string& what) {
  if (!matrix.isApprox(matrix.transpose(), 1e-9) && !matrix.isZero())
    reader.fail("a matrix that is not symmetric", "a symmetric " + what + " matrix");
  if ((matrix.diagonal().array() < 0.0).any())
    reader.fail("a negative diagonal entry", "a " + what + " matrix with diagonal entries >= 0");
}

}  // namespace

void read_waves(const NodeReader& reader, CaseDefinition& definition) {
  WaveDefinition& waves = definition.waves;
  const std::string type = reader["type"].choice({"regular", "jonswap", "pierson_moskowitz", "none"});
  if (type == "none") {
    reader.expect_section("waves", "none");
    return;
  }
  if (type == "regular") {
    reader.expect_section("waves", "regular");
    waves.type = WaveDefinition::Type::regular;
    waves.amplitude = reader["amplitude"].non_negative_number();
    waves.period = reader["period"].positive_number();
    waves.phase = reader.number_or("phase", 0.0);
  } else {
    reader.expect_section("waves", "irregular");
    waves.type = type == "jonswap" ? WaveDefinition::Type::jonswap : WaveDefinition::Type::pierson_moskowitz;
    waves.significant_height = reader["hs"].positive_number();
    waves.peak_period = reader["tp"].positive_number();
    if (auto gamma = reader.optional("gamma")) {
      if (waves.type != WaveDefinition::Type::jonswap)
        gamma->fail("'gamma' on a Pierson-Moskowitz sea", "no 'gamma' (type: jonswap has a peak enhancement)");
      waves.peak_enhancement = gamma->number();  // its range is hydro::Jonswap's rule
    }
    hydro::IrregularSeaSettings& sea = waves.irregular;
    sea.num_components = 200;
    // The number of components and the band are hydro::irregular_sea's rules, checked
    // when the scene builds the sea.
    if (auto components = reader.optional("components"))
      sea.num_components = static_cast<int>(std::clamp<long>(components->integer(), INT_MIN, INT_MAX));
    if (auto seed = reader.optional("seed")) {
      const long s = seed->integer();
      if (s < 0) seed->fail(fmt::format("{}", s), "a seed >= 0");
      sea.seed = static_cast<unsigned long long>(s);
    }
    if (auto discretization = reader.optional("discretization"))
      sea.discretization = discretization->choice({"equal_energy", "equal_spacing"}) == "equal_energy"
                               ? hydro::FrequencyDiscretization::equal_energy
                               : hydro::FrequencyDiscretization::equal_spacing;
    sea.min_frequency = reader.optional("min_frequency") ? reader["min_frequency"].positive_number() : 0.1;
    sea.max_frequency = reader.optional("max_frequency") ? reader["max_frequency"].positive_number() : 3.0;
  }
  waves.heading = reader.number_or("heading", 0.0);
  if (auto ramp = reader.optional("ramp")) waves.ramp = read_ramp(*ramp);
}

void read_hydro_force(const NodeReader& item, const std::string& type, const std::string& name,
                      CaseDefinition& definition) {
  HydroForceDefinition def;
  def.name = name;
  if (type == "hydrostatics") {
    item.expect_section("hydrostatics");
    def.type = HydroForceDefinition::Type::hydrostatics;
    if (item.has("hst") + item.has("mesh") + item.has("stiffness") != 1)
      item.fail("exactly one of 'hst' (linear: a WAMIT .hst, BEMIO .h5 or Capytaine .nc file), 'stiffness' (linear, a "
                "6 x 6 matrix) and 'mesh' (nonlinear, a .gdf or .stl hull)");
    if (item.has("stiffness")) {
      // Linear hydrostatics given directly (e.g. from the hull's A_wp, V and waterplane
      // inertias): the buoyancy's restoring only; gravity acts on the bodies' masses.
      def.stiffness = read_matrix6(item["stiffness"]);
      check_symmetric_positive(item["stiffness"], def.stiffness, "stiffness");
    } else {
      def.file_key = item.has("hst") ? "hst" : "mesh";
    }
    def.nonlinear = def.file_key == "mesh";
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
  } else if (type == "radiation") {
    item.expect_section("radiation");
    def.type = HydroForceDefinition::Type::radiation;
    def.file_key = "file";
    hydro::RadiationMemorySettings& memory = def.memory;
    if (auto kind = item.optional("memory"))
      memory.convolution = kind->choice({"state_space", "convolution"}) == "convolution";
    // The order's range and the kernel's sampling are hydro's rules (state_space.hpp,
    // retardation_kernel.hpp), checked when the scene builds the element.
    if (auto order = item.optional("state_space_order"))
      memory.state_space_order = static_cast<int>(std::clamp<long>(order->integer(), INT_MIN, INT_MAX));
    if (auto duration = item.optional("kernel_duration")) memory.kernel_duration = duration->positive_number();
    if (auto step = item.optional("kernel_step")) memory.kernel_step = step->positive_number();
    if (auto modes = item.optional("modes")) {
      memory.modes.fill(false);
      for (const NodeReader& mode : modes->items()) {
        const long m = mode.integer();
        if (m < 1 || m > 6) mode.fail(fmt::format("{}", m), "a WAMIT mode 1..6 (surge, sway, heave, roll, pitch, yaw)");
        memory.modes[m - 1] = true;
      }
    }
  } else if (type == "wave_excitation") {
    item.expect_section("wave_excitation");
    def.type = HydroForceDefinition::Type::wave_excitation;
    if (item.has("file") == item.has("heave_estimate"))
      item.fail("exactly one of 'file' (a WAMIT .3, BEMIO .h5 or Capytaine .nc file) and 'heave_estimate' (the semi-submersible hand estimate)");
    if (auto estimate = item.optional("heave_estimate")) {
      estimate->expect_section("heave_estimate");
      hydro::SemisubmersibleHeaveEstimate e;
      e.pontoon_bottom_area = (*estimate)["pontoon_bottom_area"].positive_number();
      e.waterplane_area = (*estimate)["waterplane_area"].positive_number();
      e.keel_depth = (*estimate)["keel_depth"].positive_number();
      e.pontoon_top_depth = (*estimate)["pontoon_top_depth"].positive_number();
      e.added_mass = (*estimate)["added_mass"].non_negative_number();
      e.added_mass_depth = (*estimate)["added_mass_depth"].positive_number();
      if (!(e.pontoon_top_depth < e.keel_depth))
        (*estimate)["pontoon_top_depth"].fail(
            fmt::format("{:g} m, not above the keel at {:g} m", e.pontoon_top_depth, e.keel_depth),
            "pontoon_top_depth < keel_depth (both depths below the still-water level)");
      if (!(e.waterplane_area <= e.pontoon_bottom_area))
        (*estimate)["waterplane_area"].fail(
            fmt::format("{:g} m^2, more than the pontoon bottoms' {:g} m^2", e.waterplane_area, e.pontoon_bottom_area),
            "waterplane_area <= pontoon_bottom_area (the columns stand on the pontoons)");
      def.heave_estimate = e;
    } else {
      def.file_key = "file";
    }
    if (!definition.waves.declared())
      item["type"].fail("wave_excitation without a sea", "a top-level 'waves:' block (declared before use)");
  } else if (type == "linear_damping") {
    item.expect_section("linear_damping");
    def.type = HydroForceDefinition::Type::linear_damping;
    def.damping = read_matrix6(item["damping"]);
    check_symmetric_positive(item["damping"], def.damping, "damping");
  } else if (type == "quadratic_damping") {
    item.expect_section("quadratic_damping");
    def.type = HydroForceDefinition::Type::quadratic_damping;
    def.quadratic_coefficients = read_vector6(item["coefficients"]);
    if ((def.quadratic_coefficients.array() < 0.0).any()) item["coefficients"].fail("a negative coefficient", "coefficients >= 0");
  } else if (type == "added_mass") {
    // Constant added mass (e.g. the fallback A of docs/physics/drilling-rig.md §4) put into the
    // body's inertia like a radiation element's A(inf); no force of its own.
    item.expect_section("added_mass");
    def.type = HydroForceDefinition::Type::added_mass;
    def.added_mass = read_matrix6(item["matrix"]);
    check_symmetric_positive(item["matrix"], def.added_mass, "mass");
  } else {
    item.expect_section("mooring");
    def.type = HydroForceDefinition::Type::mooring;
    def.stiffness = read_matrix6(item["stiffness"]);
    check_symmetric_positive(item["stiffness"], def.stiffness, "stiffness");
    if (auto pretension = item.optional("pretension")) def.pretension = read_vector6(*pretension);
  }
  def.body = item["body"].text();
  if (!def.file_key.empty()) {
    def.file = read_data_file(item[def.file_key]);
  }
  if (auto scale = item.optional("length_scale")) {
    // ULEN nondimensionalises WAMIT's files only; BEMIO and Capytaine store SI values.
    if (!def.nonlinear && bem::bem_file_format(def.file) != bem::BemFileFormat::wamit)
      scale->fail("'length_scale' with a BEMIO (.h5) or Capytaine (.nc) file",
                  "no 'length_scale' (only WAMIT files are nondimensional in ULEN)");
    def.length_scale = scale->positive_number();
  }
  definition.item_paths[name] = item.path();
  definition.hydro_forces.push_back(std::move(def));
}

}  // namespace heavesim
