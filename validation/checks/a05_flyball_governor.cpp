// A05: IFToMM benchmark A05, the stiff flyball governor
// (cases/validation/iftomm_a05_flyball_governor.yaml: a free spinning shaft, two arms
// with 5 kg balls, a slider, and stiff, heavily damped spring-dampers in place of the
// coupler rods), through the whole application, against the governor reduced to its
// symmetric motion (arm angle, slider height, and the spin from conserved angular
// momentum) written from Lagrange's equations and integrated by ARKODE Fehlberg 8(7)
// (oracles/flyball_governor). The benchmark's output is the slider coordinate s.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "validation/checks/validation_suite.hpp"
#include "validation/oracles/flyball_governor.hpp"

namespace heavesim::validation {

std::vector<ValidationRow> check_a05_flyball_governor() {
  std::vector<ValidationRow> rows;
  for (const auto& [label, overrides] :
       {std::pair<std::string, std::vector<std::string>>{"IDA, rtol = atol = 1e-10", {}},
        {"HHT, h = 0.05 ms", {"solver.integrator=hht", "solver.step=5e-5"}}}) {
    std::vector<double> times;
    std::vector<double> arm_a, arm_b, slider, spin;
    run_case("cases/validation/iftomm_a05_flyball_governor.yaml", overrides,
             [&](double t, const MultibodySystem& system) {
               const Model& model = system.model();
               const VectorX& q = system.configuration();
               const VectorX& v = system.velocity();
               times.push_back(t);
               arm_a.push_back(q[model.joints[model.joint_index("arm_a")].q_index]);
               arm_b.push_back(q[model.joints[model.joint_index("arm_b")].q_index]);
               slider.push_back(q[model.joints[model.joint_index("slide")].q_index]);
               spin.push_back(v[model.joints[model.joint_index("spin")].v_index]);
             });
    const std::vector<double> later(times.begin() + 1, times.end());
    const std::vector<oracle::FlyballGovernorState> exact =
        oracle::flyball_governor_states(oracle::FlyballGovernorParameters{}, later, 1e-12);
    double arm_error = 0.0, slider_error = 0.0, spin_error = 0.0, slider_travel = 0.0;
    for (std::size_t k = 0; k < later.size(); ++k) {
      arm_error = std::max(
          {arm_error, std::abs(arm_a[k + 1] - exact[k].arm_angle), std::abs(arm_b[k + 1] - exact[k].arm_angle)});
      slider_error = std::max(slider_error, std::abs(slider[k + 1] - exact[k].slider_height));
      spin_error = std::max(spin_error, std::abs(spin[k + 1] - exact[k].spin_rate));
      slider_travel = std::max(slider_travel, std::abs(slider[k + 1] - slider.front()));
    }
    const std::string subject = fmt::format("A05 governor 10 s, {} (s moves {:.3f} m, spin {:.2f} -> {:.2f} rad/s)",
                                            label, slider_travel, spin.front(), spin.back());
    rows.push_back({"A05", subject, "arm angles vs reduced Lagrange model [rad]", arm_error, 1e-6});
    rows.push_back({"A05", subject, "slider s vs reduced model [m] (IFToMM output)", slider_error, 1e-6});
    rows.push_back({"A05", subject, "shaft spin rate vs p / J(theta) [rad/s]", spin_error, 1e-6});
  }
  return rows;
}

}  // namespace heavesim::validation
