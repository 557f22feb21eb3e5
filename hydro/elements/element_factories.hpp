#pragma once
// The hydro force elements a case declares, built from their settings: the decisions
// between the data (a BEM file, a sampled kernel) and the element -- which radiation
// mode pairs to realise, the convolution's masking, the gravitational part of a WAMIT
// .hst, the default buoyancy -- taken once here rather than by each application.
#include <array>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include "hydro/bem/bem_data.hpp"
#include "hydro/elements/linear_body_loads.hpp"
#include "hydro/radiation/state_space.hpp"

namespace heavesim::hydro {

/// WAMIT modes (0-based: surge, sway, heave, roll, pitch, yaw) an element acts in.
using ModeSet = std::array<bool, 6>;

/// How the radiation memory of a body is represented.
struct RadiationMemorySettings {
  int state_space_order = 12;  // states per realised mode pair, 2 .. max_state_space_order
  /// A direct convolution of the sampled K(t) (RadiationConvolution; for fixed-step
  /// explicit runs whose step divides kernel_step) instead of the state space.
  bool convolution = false;
  double kernel_duration = 60.0;  // s, length of the retardation kernel K(t)
  double kernel_step = 0.05;      // s, its sample step (<= kernel_duration / 10)
  /// Modes whose memory is kept: pairs (i, j) with both in the set. All six by default;
  /// a body held to fewer degrees of freedom needs only those.
  ModeSet modes = {true, true, true, true, true, true};
};

/// The mode pairs (i, j) whose memory is realised: both modes in `modes` and the kernel
/// not negligible against its own diagonal, max|K_ij| > 1e-3 sqrt(max|K_ii| max|K_jj|)
/// over the samples (dimensionally consistent, unlike a comparison across translation
/// and rotation). Row-major order.
std::vector<std::pair<int, int>> realised_mode_pairs(const RetardationKernel& kernel, const ModeSet& modes);

/// Zeroes every K_ij (all samples) with mode i or j outside `modes`.
void keep_modes(RetardationKernel& kernel, const ModeSet& modes);

/// The state-space realisation of each pair of realised_mode_pairs (two pairs at a time;
/// the process's last four kept, so a second build of a scene from the same data realises
/// nothing again). Throws ParameterError("state_space_order") when a realisation is
/// unstable (its memory would grow without bound in a run).
std::vector<ModePairStateSpace> realize_memory(const RetardationKernel& kernel, const ModeSet& modes, int order);

/// The radiation memory element of a body (link) from its BEM data: the kernel
/// K(t) = (2/pi) int B cos(w t) dw sampled as asked, then a RadiationConvolution of the
/// kept modes, or a RadiationMemory of the realised pairs. Throws ParameterError
/// ("state_space_order", "kernel_step") for settings it cannot realise.
std::unique_ptr<ForceElement> radiation_memory(std::string name, int link, const RadiationData& radiation,
                                               const RadiationMemorySettings& settings);

/// Linear hydrostatics F = f0 - C xi about the body frame origin (WAMIT order).
struct LinearHydrostaticsSettings {
  Matrix6 stiffness = Matrix6::Zero();  // C [N/m, N, N m/rad] as given (.hst or matrix)
  /// C is WAMIT's "hydrostatic and gravitational" matrix of a run given the CG: its
  /// gravitational part is taken out because the kernel applies the weight at the CoM
  /// itself (wamit_gravitational_stiffness).
  bool stiffness_includes_gravity = false;
  std::optional<double> displaced_volume;    // V [m^3]; default: buoyancy = the body's weight
  double body_mass = 0.0;                    // m [kg]
  Vector3 center_of_mass = Vector3::Zero();  // m, body frame
  double water_density = 1025.0;             // rho [kg/m^3]
  double gravity = 9.81;                     // g [m/s^2]
};

/// The restoring matrix the element uses: C, less the gravitational part when C has it.
Matrix6 restoring_stiffness(const LinearHydrostaticsSettings& settings);

/// f0 = rho g V e_heave, or m g e_heave without a displaced volume, so that the reference
/// pose (the world frame) is the static equilibrium.
Vector6 buoyancy_load(const LinearHydrostaticsSettings& settings);

/// LinearRestoring(C', f0) at the world frame as reference pose.
std::unique_ptr<LinearRestoring> linear_hydrostatics(std::string name, int link,
                                                     const LinearHydrostaticsSettings& settings);

}  // namespace heavesim::hydro
