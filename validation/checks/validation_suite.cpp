#include "validation/checks/validation_suite.hpp"

#include <filesystem>
#include <stdexcept>

#include <cmath>

#include <fmt/format.h>

#include "app/scene/scene.hpp"
#include "app/version.hpp"
#include "kernel/algorithms/energy.hpp"

namespace heavesim::validation {

const std::vector<ValidationCheck>& validation_checks() {
  static const std::vector<ValidationCheck> checks = {
      {"K1", "double pendulum vs closed-form Lagrange equations and pin reactions", check_k1_double_pendulum},
      {"K2", "planar n-link rods (n = 2, 3, 5) vs the n-link oracle", check_k2_planar_chains},
      {"K3", "2- and 3-link pendulum runs (V1-V4) vs the oracle integrated independently", check_k3_pendulum_runs},
      {"K5", "free rigid body: momentum and energy conservation, symmetric-top closed form", check_k5_free_body},
      {"K6", "algorithm cross-checks: CRBA vs RNEA, ABA vs CRBA, reactions vs subtree Newton-Euler",
       check_k6_algorithm_cross_checks},
      {"L1", "slider-crank of SUNDIALS' idaSlCrank_dns (loop joint, spring-damper, push) vs a minimal-coordinate "
             "oracle and the example's printout",
       check_l1_slider_crank},
      {"L2", "IFToMM A02 N-four-bar (N = 1, 2) through every singular pass vs the exact parallelogram motion",
       check_l2_four_bar},
      {"L4", "constraint drift of the 3-hour H1 rig with a loop (IDA at the case's 1e-4)", check_l4_constraint_drift},
      {"A03", "IFToMM A03 Andrews' squeezing mechanism (SI and mm-g-s) vs the Test Set for IVP Solvers reference, in mescd",
       check_a03_andrews},
      {"L5", "over-constrained parallelogram (3-D loop joints, a third parallel crank): 7 redundant rows, exact motion",
       check_l5_overconstrained_four_bar},
      {"A01", "IFToMM A01 simple pendulum vs the exact elliptic-function motion (10 s and 2000 s)",
       check_a01_simple_pendulum},
      {"A02", "IFToMM A02 N-four-bar at the benchmark's size (N = 10, 40; 20 s) vs the exact parallelogram motion",
       check_a02_n_four_bar},
      {"A04", "IFToMM A04 Bricard mechanism: one redundant row, mobility 1, energy conservation", check_a04_bricard},
      {"A05", "IFToMM A05 stiff flyball governor vs a reduced two-coordinate Lagrange model",
       check_a05_flyball_governor},
      {"C1", "passive compensator under prescribed platform heave vs the linear transmissibility k / (k - M w^2)",
       check_c1_passive_compensator},
      {"C2", "static equilibrium of the H0 (rigid and elastic string) and H0b rigs (platform held): joint reactions vs "
             "hanging weights",
       check_c2_static_rig},
      {"C3", "gas-spring energy: integral F ds vs the polytropic work (p V) / (n - 1) change", check_c3_gas_spring_energy},
      {"L3", "MKSim slider-crank (kinematic analysis, block driven x = 8 + 3 sin t) vs the closed-form crank angle "
             "and its exact derivatives",
       check_l3_mksim_slider_crank},
      {"L6", "Grashof crank-rocker four-bar through a full crank turn (kinematic analysis) vs loop closure",
       check_l6_grashof_four_bar},
      {"L7", "planar four-bar of 3-D revolute joints: 3 redundant equations, named in the loop joint's frame",
       check_l7_redundant_four_bar},
      {"L8", "driving torque of a slider-crank's crank along a prescribed motion vs Lagrange's equation",
       check_l8_driving_torque},
      {"M1", "MKSim slider-crank in MKSim's language, imported: 28 - 27 = 1, block on x = 8 + 3 sin t, crank vs "
             "closed form, rod spin held at zero",
       check_m1_mksim_import},
      {"H1", "hydrostatics of a box hull by clipping vs analytic V, B, C33, C44, C55", check_h1_box_hydrostatics},
      {"H2", "hydrostatics of the MSS semi mesh vs WAMIT semisub.out", check_h2_semisub_hydrostatics},
      {"H3", "heave free decay through the kernel vs 2 pi sqrt((m + A33)/C33) and the damped closed form",
       check_h3_heave_decay},
      {"H4", "regular-wave heave RAO from time-domain runs vs the frequency-domain RAO", check_h4_regular_wave_rao},
      {"H5", "radiation memory: B(w) from K(t), convolution vs state space", check_h5_radiation_memory},
      {"H6", "irregular sea generation: H_m0 of a 3-hour record vs the target", check_h6_irregular_sea},
      {"H7", "WAMIT readers vs the MSS semi numbers, WAMIT's RAO file and the Hulme table", check_h7_bem_readers},
      {"S1", "static equilibrium of a spring-loaded crane vs the hand moment and force balance", check_s1_spring_crane},
      {"S2", "static equilibrium of the drilling rig: heave offset, stroke, gas pressure, hook loads vs hand formulas",
       check_s2_rig_statics},
      {"P1", "LCP textbook problems: the source document's Lemke tableau example (pivot sequence, answer) and "
             "Murty's problem (2^n pivots)",
       check_p1_lcp_textbook},
      {"P2", "random SPD and P-matrix LCPs (n = 10..500, answer chosen first): Lemke and Dantzig residuals",
       check_p2_lcp_random},
      {"P3", "box on an incline with Coulomb friction (contact stepping): slides with g (sin - mu cos) below "
             "tan(slope), sticks above",
       check_p3_block_on_incline},
      {"P4", "20-cube stacks at rest, uniform and 1:100 masses, 10 s: face loads vs the weights above, no drift",
       check_p4_box_stacks},
  };
  return checks;
}

std::string project_file(const std::string& relative_path) {
  for (std::filesystem::path directory = std::filesystem::current_path(); !directory.empty();
       directory = directory.parent_path()) {
    if (std::filesystem::exists(directory / relative_path)) return (directory / relative_path).string();
    if (directory == directory.parent_path()) break;
  }
  const std::filesystem::path source = std::filesystem::path(heavesim_source_dir) / relative_path;
  if (std::filesystem::exists(source)) return source.string();
  throw std::runtime_error("validation file '" + relative_path + "' not found (run from the project directory)");
}

RunOutcome run_case(const std::string& relative_path, const std::vector<std::string>& overrides,
                    const std::function<void(double t, const MultibodySystem& system)>& sample) {
  const CaseDefinition definition = load_case(project_file(relative_path), overrides);
  Scene scene = build_scene(definition);
  std::unique_ptr<Integrator> integrator = make_integrator(definition.solver.integrator, *scene.system);
  return run_simulation(scene, definition.solver, definition.output.interval, *integrator,
                        [&](double t, const VectorX& y) {
                          scene.system->evaluate(t, y, true);
                          sample(t, *scene.system);
                          return true;
                        });
}

RunOutcome run_case_to_failure(const std::string& relative_path, const std::vector<std::string>& overrides,
                               const std::function<void(double t, const MultibodySystem& system)>& sample) {
  try {
    return run_case(relative_path, overrides, sample);
  } catch (const NumericalError& error) {
    RunOutcome outcome;
    outcome.completed = false;
    outcome.time_reached = error.time();
    return outcome;
  }
}

std::vector<ValidationRow> assembly_structure_rows(const std::string& id, const std::string& label,
                                                   const std::string& relative_path, int expected_redundant,
                                                   int expected_mobility) {
  const Scene scene = build_scene(load_case(project_file(relative_path)));
  const ConstraintRank& rank = scene.assembly.rank;
  const int redundant = static_cast<int>(rank.redundant_rows.size());
  const int mobility = scene.model->nv - rank.rank;
  const std::string subject = fmt::format("{} at assembly: {} rows, rank {}, {} redundant, mobility {}", label,
                                          rank.rows, rank.rank, redundant, mobility);
  return {{id, subject, fmt::format("redundant rows - {} (exact)", expected_redundant),
           std::abs(redundant - static_cast<double>(expected_redundant)), 0.0},
          {id, subject, fmt::format("mobility nv - rank - {} (exact)", expected_mobility),
           std::abs(mobility - static_cast<double>(expected_mobility)), 0.0}};
}

double mechanical_energy(const MultibodySystem& system) {
  return kinetic_energy(system.model(), system.data()) + gravity_potential_energy(system.model(), system.data());
}

}  // namespace heavesim::validation
