#pragma once
// The validation set (docs/validation.md): each check compares heavesim with something
// it did not compute itself and reports max error against a stated tolerance.
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "app/run/kinematic_run.hpp"
#include "app/run/simulation_run.hpp"

namespace heavesim::validation {

/// Gravity in every validation case and sample model [m/s^2].
inline constexpr double g = 9.81;
/// The gas spring of cases/validation/c1_passive_compensator.yaml and c3_gas_spring.yaml:
/// piston area A [m^2], gas volume at mid-stroke V0 [m^3], polytropic exponent n,
/// atmospheric pressure p_atm [Pa].
namespace default_gas_spring {
inline constexpr double A = 0.1735, V0 = 60.0, n = 1.4, p_atm = 101325.0;
}

/// |value - reference| / |reference|.
inline double relative(double value, double reference) { return std::abs(value - reference) / std::abs(reference); }

struct ValidationRow {
  std::string check;     // e.g. "K1"
  std::string subject;   // e.g. "double pendulum, 1000 random states"
  std::string quantity;  // e.g. "qdd (ABA), relative"
  double max_error = 0.0;
  double tolerance = 0.0;
  bool passed() const { return max_error <= tolerance; }
};

struct ValidationCheck {
  std::string id;
  std::string title;
  std::function<std::vector<ValidationRow>()> run;
};

/// Every check of the suite, in order.
const std::vector<ValidationCheck>& validation_checks();

/// Absolute path of a file shipped with the project (e.g. "cases/validation/two_link.yaml"),
/// looked up from the working directory upwards, then in the source tree heavesim was built from.
std::string project_file(const std::string& relative_path);

/// Loads and runs a case; after each output time the full pipeline (with joint
/// reactions) has been evaluated and `sample(t, system)` is called.
RunOutcome run_case(const std::string& relative_path, const std::vector<std::string>& overrides,
                    const std::function<void(double t, const MultibodySystem& system)>& sample);

/// run_case, with a NumericalError reported as an incomplete outcome (completed =
/// false, time_reached = the failure's time), for checks that score a run that
/// stops as an infinite error.
RunOutcome run_case_to_failure(const std::string& relative_path, const std::vector<std::string>& overrides,
                               const std::function<void(double t, const MultibodySystem& system)>& sample);

/// The two "structure at assembly" rows of an over-constrained case: its redundant
/// rows and its mobility nv - rank against their exact values.
std::vector<ValidationRow> assembly_structure_rows(const std::string& id, const std::string& label,
                                                   const std::string& relative_path, int expected_redundant,
                                                   int expected_mobility);

/// Loads a case and runs its kinematic analysis (app/run/kinematic_run.hpp, reactions
/// included); `sample(t, system)` after each time point's evaluation.
KinematicOutcome run_kinematic_case(const std::string& relative_path, const std::vector<std::string>& overrides,
                                    const std::function<void(double t, const MultibodySystem& system)>& sample);

/// Kinetic plus gravitational energy at the system's last evaluation [J].
double mechanical_energy(const MultibodySystem& system);

// The checks (one file each).
std::vector<ValidationRow> check_k1_double_pendulum();
std::vector<ValidationRow> check_k2_planar_chains();
std::vector<ValidationRow> check_k3_pendulum_runs();
std::vector<ValidationRow> check_k5_free_body();
std::vector<ValidationRow> check_k6_algorithm_cross_checks();
std::vector<ValidationRow> check_l1_slider_crank();
std::vector<ValidationRow> check_l2_four_bar();
std::vector<ValidationRow> check_l4_constraint_drift();
std::vector<ValidationRow> check_a03_andrews();
std::vector<ValidationRow> check_l5_overconstrained_four_bar();
std::vector<ValidationRow> check_a01_simple_pendulum();
std::vector<ValidationRow> check_a02_n_four_bar();
std::vector<ValidationRow> check_a04_bricard();
std::vector<ValidationRow> check_a05_flyball_governor();
std::vector<ValidationRow> check_c1_passive_compensator();
std::vector<ValidationRow> check_c2_static_rig();
std::vector<ValidationRow> check_c3_gas_spring_energy();
std::vector<ValidationRow> check_h1_box_hydrostatics();
std::vector<ValidationRow> check_h2_semisub_hydrostatics();
std::vector<ValidationRow> check_h3_heave_decay();
std::vector<ValidationRow> check_h4_regular_wave_rao();
std::vector<ValidationRow> check_h5_radiation_memory();
std::vector<ValidationRow> check_h6_irregular_sea();
std::vector<ValidationRow> check_h7_bem_readers();
std::vector<ValidationRow> check_l3_mksim_slider_crank();
std::vector<ValidationRow> check_l6_grashof_four_bar();
std::vector<ValidationRow> check_l7_redundant_four_bar();
std::vector<ValidationRow> check_l8_driving_torque();
std::vector<ValidationRow> check_s1_spring_crane();
std::vector<ValidationRow> check_s2_rig_statics();
std::vector<ValidationRow> check_p1_lcp_textbook();
std::vector<ValidationRow> check_p2_lcp_random();
std::vector<ValidationRow> check_p3_block_on_incline();
std::vector<ValidationRow> check_p4_box_stacks();
std::vector<ValidationRow> check_m1_mksim_import();

}  // namespace heavesim::validation
