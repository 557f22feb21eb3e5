#pragma once
// Force kind `hydrostatics`: linear restoring from a WAMIT .hst, BEMIO .h5 or Capytaine
// .nc file or a matrix given directly, or nonlinear buoyancy on a panel mesh clipped at
// the instantaneous free surface (hydro/elements/nonlinear_hydrostatics.hpp).
#include <optional>

#include "app/forces/hydro_force.hpp"

namespace heavesim {

struct HydrostaticsDefinition {
  static constexpr std::string_view type = "hydrostatics";
  static constexpr BuildStage stage = BuildStage::hydro;
  static std::span<const KeySpec> keys();
  static std::span<const SchemaSection> sub_sections() { return {}; }
  static HydrostaticsDefinition read(const NodeReader& item, const CaseDefinition& definition);
  /// Reads the .hst or the mesh (or takes the given C).
  void read_data(const std::string& name, const CaseDefinition& definition, HydroData& data) const;
  void build(const std::string& name, SceneBuildContext& context) const;

  std::string body;
  /// The .hst (linear) or .gdf / .stl (nonlinear, `nonlinear`) file; no file when the
  /// stiffness is given directly.
  HydroDataFile file;
  bool nonlinear = false;  // from a panel mesh, clipped every evaluation
  /// C given directly [N/m, N, N m/rad], reference point, WAMIT order (no file): the
  /// buoyancy's restoring only; gravity acts on the bodies' masses.
  hydro::Matrix6 stiffness = hydro::Matrix6::Zero();
  /// Linear: buoyancy rho g V at the reference pose; when absent, equal to the body's
  /// weight (the reference pose is then the static equilibrium).
  std::optional<double> displaced_volume;  // V [m^3]
  /// Linear: the .hst is WAMIT's "hydrostatic and gravitational" matrix of a run given
  /// the CG (MSS semisub.hst); its gravitational part is taken out because the kernel
  /// applies the weight at the centre of mass itself (docs/physics/hydrodynamics.md §7).
  bool hst_includes_gravity = false;
};

}  // namespace heavesim
