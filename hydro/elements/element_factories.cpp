#include "hydro/elements/element_factories.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <deque>
#include <mutex>

#include "hydro/elements/radiation_convolution.hpp"
#include "hydro/elements/radiation_memory.hpp"
#include "kernel/math/two_thread_loop.hpp"
#include "kernel/parameter_error.hpp"

namespace heavesim::hydro {

std::vector<std::pair<int, int>> realised_mode_pairs(const RetardationKernel& kernel, const ModeSet& modes) {
  Matrix6 largest = Matrix6::Zero();
  for (const Matrix6& K : kernel.values) largest = largest.cwiseMax(K.cwiseAbs());
  std::vector<std::pair<int, int>> pairs;
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j)
      if (modes[i] && modes[j] && largest(i, j) > 0.0 &&
          largest(i, j) > 1e-3 * std::sqrt(largest(i, i) * largest(j, j)))
        pairs.emplace_back(i, j);
  return pairs;
}

void keep_modes(RetardationKernel& kernel, const ModeSet& modes) {
  for (Matrix6& K : kernel.values)
    for (int i = 0; i < 6; ++i)
      for (int j = 0; j < 6; ++j)
        if (!modes[i] || !modes[j]) K(i, j) = 0.0;
}

namespace {

// The last realisations this process made, with what they were made from. `heavesim run`
// builds its scene twice from the same files (the second for the samples' evaluation,
// Recorder::why_samples_in_line): the second build takes the first's realisations instead
// of solving their eigenproblems again (~200 M instructions for the MSS semi's ten pairs).
// A realisation is a function of the kernel's samples, the modes and the order only,
// which are compared exactly. Four are kept (a case has one memory per floating body),
// each with a copy of its kernel (~0.35 MB for 60 s at 0.05 s). The store is made under
// the mutex and never freed, as signal/hann_segment.cpp's plans: no thread can lose it
// during the program's exit.
struct Realised {
  double time_step = 0.0;
  ModeSet modes{};
  int order = 0;
  std::vector<Matrix6> samples;
  std::vector<ModePairStateSpace> systems;
};
constexpr std::size_t realisations_kept = 4;
std::mutex realised_mutex;
std::deque<Realised>* realised = nullptr;  // the newest first

bool made_from(const Realised& kept, const RetardationKernel& kernel, const ModeSet& modes, int order) {
  return kept.time_step == kernel.time_step && kept.modes == modes && kept.order == order &&
         std::equal(kept.samples.begin(), kept.samples.end(), kernel.values.begin(), kernel.values.end(),
                    [](const Matrix6& a, const Matrix6& b) { return a == b; });
}

}  // namespace

std::vector<ModePairStateSpace> realize_memory(const RetardationKernel& kernel, const ModeSet& modes, int order) {
  {
    const std::lock_guard lock(realised_mutex);
    if (realised != nullptr)
      for (const Realised& kept : *realised)
        if (made_from(kept, kernel, modes, order)) return kept.systems;
  }
  // The pairs are independent (each a symmetric eigenproblem of the Hankel matrix, up to
  // 150 x 150, ~16 M instructions): two at a time where the process may use two cores, each
  // the same numbers on either thread. (A sweep's runs side by side then share their cores
  // for the ~0.1 s of a scene build.)
  const auto pairs = realised_mode_pairs(kernel, modes);
  std::vector<ModePairStateSpace> systems(pairs.size());
  for_each_index(pairs.size(), usable_cores() >= 2 ? 2 : 1, [&](std::size_t k) {
    systems[k] = realize_kernel_entry(kernel, pairs[k].first, pairs[k].second, order);
  });
  for (const ModePairStateSpace& realised : systems)
    if (!realised.stable)
      throw ParameterError("state_space_order",
                           fmt::format("an unstable realisation of K_{}{} at order {} (R^2 = {:.4f})",
                                       realised.force_mode + 1, realised.velocity_mode + 1, order, realised.r_squared),
                           "an order whose realisation is stable (try a lower or higher order, or fewer modes)");
  const std::lock_guard lock(realised_mutex);
  if (realised == nullptr) realised = new std::deque<Realised>;
  realised->push_front({kernel.time_step, modes, order, kernel.values, systems});
  if (realised->size() > realisations_kept) realised->pop_back();
  return systems;
}

std::unique_ptr<ForceElement> radiation_memory(std::string name, int link, const RadiationData& radiation,
                                               const RadiationMemorySettings& settings) {
  check_state_space_order(settings.state_space_order);  // also when the memory is a convolution
  RetardationKernel kernel = retardation_kernel(radiation, settings.kernel_duration, settings.kernel_step);
  if (settings.convolution) {
    keep_modes(kernel, settings.modes);
    return std::make_unique<RadiationConvolution>(std::move(name), link, std::move(kernel));
  }
  return std::make_unique<RadiationMemory>(std::move(name), link,
                                           realize_memory(kernel, settings.modes, settings.state_space_order));
}

Matrix6 restoring_stiffness(const LinearHydrostaticsSettings& s) {
  if (!s.stiffness_includes_gravity) return s.stiffness;
  return s.stiffness - wamit_gravitational_stiffness(s.body_mass, s.center_of_mass, s.gravity);
}

Vector6 buoyancy_load(const LinearHydrostaticsSettings& s) {
  Vector6 load = Vector6::Zero();
  load[2] = s.displaced_volume ? s.water_density * s.gravity * *s.displaced_volume : s.body_mass * s.gravity;
  return load;
}

std::unique_ptr<LinearRestoring> linear_hydrostatics(std::string name, int link,
                                                     const LinearHydrostaticsSettings& settings) {
  return std::make_unique<LinearRestoring>(std::move(name), link, restoring_stiffness(settings),
                                           buoyancy_load(settings), Transform::Identity());
}

}  // namespace heavesim::hydro
