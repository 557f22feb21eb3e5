#pragma once
// Headline numbers of the compensators in a run, gathered at every output sample:
// stroke usage, end-stop contacts (EndStopMonitor: counted at the output rate),
// gas pressure and temperature ranges; for active compensators the largest force,
// control error and hydraulic power. Written as /summary attributes and printed by
// `heavesim run`.
#include <string>
#include <vector>

#include "app/output/result_file.hpp"
#include "control/active/active_compensator.hpp"
#include "control/pneumatic/pneumatic_compensator.hpp"
#include "kernel/system/multibody_system.hpp"

namespace heavesim {

class CompensatorSummary {
 public:
  explicit CompensatorSummary(const MultibodySystem& system);
  /// After system.evaluate(t, y): takes one sample.
  void observe(double t, const VectorX& y);
  void write(ResultFile& file) const;
  /// One line per compensator.
  std::vector<std::string> headlines() const;

 private:
  struct Passive {
    const PneumaticCompensator* element;
    int offset;
    EndStopMonitor monitor;
    double max_stroke = -1e300, min_stroke = 1e300, max_pressure = -1e300, min_pressure = 1e300;
    double max_temperature = -1e300, min_temperature = 1e300;
  };
  struct Active {
    const ActiveCompensator* element;
    int offset;
    double max_force = 0.0, max_error = 0.0, max_supply_power = 0.0, supply_energy = 0.0;
    double first_time = 0.0, last_time = 0.0;
    double last_supply_power = 0.0;
    long samples = 0;
  };
  const MultibodySystem& system_;
  std::vector<Passive> passive_;
  std::vector<Active> active_;
};

}  // namespace heavesim
