#pragma once
// Headline numbers of the compensators in a run, gathered at every output sample:
// stroke usage, end-stop contacts (EndStopMonitor: counted at the output rate),
// gas pressure and temperature ranges; for active compensators the largest force,
// control error and hydraulic power; and the compensation efficiency
//   eta = 1 - sigma(z_load) / sigma(z_base)
// over the evaluation window (output.evaluate_after to the end): z_base the world height
// [m] of the stroke's base (the derrick top), z_load that of the moving side (the crown
// block, rigidly carrying the string on H0), sigma the standard deviation over the
// window's samples. For a steady sinusoid sigma ratio = amplitude ratio, so this is the
// regular-wave definition of docs/physics/drilling-rig.md §6 too (eta = 1 - Z_ds / Z_dt).
// Ground contacts (the bit on the formation): the contact force (WOB) over the same
// window -- mean, standard deviation, range, and the samples off the ground.
// Written as /summary attributes and printed by `heavesim run`.
#include <string>
#include <vector>

#include "app/output/result_file.hpp"
#include "app/output/running_statistics.hpp"
#include "app/scene/element_handles.hpp"
#include "kernel/system/multibody_system.hpp"

namespace heavesim {

class CompensatorSummary {
 public:
  /// `elements`: the compensators and ground contacts of `system` (Scene::summarised);
  /// `evaluate_after` [s]: start of the efficiency window.
  CompensatorSummary(const MultibodySystem& system, const SummarisedElements& elements, double evaluate_after);
  /// Start of the evaluation window [s], and whether a sample at t [s] falls in it (the
  /// recorder's per-joint load statistics use the same window).
  double evaluate_after() const { return evaluate_after_; }
  bool in_window(double t) const { return t >= evaluate_after_ - 1e-9; }
  /// How many values measure() writes for one sample.
  int measured_values() const { return measured_values_; }
  /// After `system.evaluate(t, y)`: what observe() takes of that sample (each passive
  /// compensator's stroke [m], gas pressure [Pa] and temperature [K], base and load heights
  /// [m] in the evaluation window, NaN before it; each ground contact's force [N]; each
  /// active compensator's force [N], control error [m] and supply power [W]) into `values`
  /// (measured_values()). `system` is the
  /// summary's or another build of the same case (its elements at the same places): the
  /// recorder evaluates its samples on two scenes at once. Reads nothing of the summary's
  /// running state, so any thread may measure while another observes.
  void measure(const MultibodySystem& system, double t, const VectorX& y, double* values) const;
  /// Takes one sample's measured values, in sample order.
  void observe(double t, const double* values);
  void write(ResultFile& file) const;
  /// 1 - sigma(z_load) / sigma(z_base) of passive compensator k over the window; NaN if
  /// the base did not move (nothing to compensate) or the window holds < 2 samples.
  double efficiency(std::size_t k) const;
  /// One line per compensator.
  std::vector<std::string> headlines() const;

 private:
  struct Passive {
    const PneumaticCompensator* element;
    std::size_t index;  // in MultibodySystem::force_elements()
    int offset;
    EndStopMonitor monitor;
    double max_stroke = -1e300, min_stroke = 1e300, max_pressure = -1e300, min_pressure = 1e300;
    double max_temperature = -1e300, min_temperature = 1e300;
    RunningStatistics base_height{}, load_height{};  // m, over the evaluation window
  };
  struct Active {
    const ActiveCompensator* element;
    std::size_t index;
    int offset;
    double max_force = 0.0, max_error = 0.0, max_supply_power = 0.0, supply_energy = 0.0;
    double first_time = 0.0, last_time = 0.0;
    double last_supply_power = 0.0;
    long samples = 0;
  };
  struct Contact {
    const GroundContact* element;
    std::size_t index;
    RunningStatistics force{};  // N, over the evaluation window
    long lifted_samples = 0;    // samples in the window with no contact force
  };
  /// The element at `index` of `system`, of the type the summary's has there.
  template <class Element>
  static const Element& element_of(const MultibodySystem& system, std::size_t index) {
    return static_cast<const Element&>(*system.force_elements()[index]);
  }
  double evaluate_after_;
  int measured_values_ = 0;
  std::vector<Passive> passive_;
  std::vector<Active> active_;
  std::vector<Contact> contacts_;
};

}  // namespace heavesim
