// A04: IFToMM benchmark A04, Bricard's mechanism (cases/validation/iftomm_a04_bricard.yaml):
// five rods, six revolute joints, one a loop joint. Grubler's count gives 0 degrees of
// freedom; the axes' arrangement leaves one of the loop joint's five rows dependent on the
// others and the mechanism moves with one. References: the rank of the constraint
// Jacobian found at assembly (exactly one redundant row, mobility nv - rank = 1), and
// conservation of energy (no dissipation: kinetic + gravitational energy constant) over
// the benchmark's 10 s, with IDA (index-2, independent rows only) and HHT (index 3); and
// P3, the benchmark's output point (the corner B between rods 2 and 3), against an
// independent formulation of the same mechanism (oracles/bricard_mechanism: rotation
// matrices, body Jacobians, an SVD null space, ARKODE Fehlberg 8(7)).
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "kernel/elements/body_point.hpp"
#include "validation/checks/validation_suite.hpp"
#include "validation/oracles/bricard_mechanism.hpp"
#include "validation/oracles/iftomm_accuracy.hpp"

namespace heavesim::validation {
namespace {

constexpr const char* bricard_case = "cases/validation/iftomm_a04_bricard.yaml";

struct BricardRun {
  double energy_drift = 0.0;        // relative to m g L summed over the rods (5 x 9.81 J)
  double p3_largest_motion = 0.0;   // m, max |P3(t) - P3(0)|
  std::vector<double> times;        // s, the output samples
  std::vector<Eigen::Vector3d> p3;  // m, world
};

BricardRun run_bricard(const std::vector<std::string>& overrides) {
  std::vector<double> energies;
  Vector3 p3_start = Vector3::Zero();
  BricardRun result;
  run_case(bricard_case, overrides, [&](double t, const MultibodySystem& system) {
    // rod3's frame sits on B = P3.
    const Vector3 p3 = BodyPoint::on_body(system.model(), "rod3", Vector3::Zero()).position_world(system.data());
    if (energies.empty()) p3_start = p3;
    result.times.push_back(t);
    result.p3.push_back(p3);
    result.p3_largest_motion = std::max(result.p3_largest_motion, (p3 - p3_start).norm());
    energies.push_back(mechanical_energy(system));
  });
  const double energy_scale = 5.0 * 1.0 * g * 1.0;
  for (double energy : energies)
    result.energy_drift = std::max(result.energy_drift, std::abs(energy - energies.front()) / energy_scale);
  return result;
}

}  // namespace

std::vector<ValidationRow> check_a04_bricard() {
  std::vector<ValidationRow> rows = assembly_structure_rows("A04", "A04 Bricard", bricard_case, 1, 1);
  std::vector<Eigen::Vector3d> reference;  // P3 by the independent formulation, at the runs' samples
  for (const auto& [label, overrides] :
       {std::pair<std::string, std::vector<std::string>>{"IDA GGL, rtol = atol = 1e-10", {}},
        {"HHT index-3, h = 1 ms", {"solver.integrator=hht", "solver.step=1e-3"}}}) {
    const BricardRun run = run_bricard(overrides);
    const std::string subject = fmt::format("A04 Bricard 10 s, {} (P3 moves {:.2f} m)", label, run.p3_largest_motion);
    rows.push_back({"A04", subject, "energy drift / (5 m g L)", run.energy_drift, 1e-6});
    if (reference.empty()) {
      const std::vector<double> later(run.times.begin() + 1, run.times.end());
      reference.push_back(run.p3.front());  // t = 0: the assembled start, at rest
      for (const oracle::BricardSample& sample : oracle::bricard_samples(later, 1e-12)) reference.push_back(sample.p3);
    }
    rows.push_back({"A04", subject, "P3 x, y, z vs independent formulation, max [m]",
                    oracle::iftomm_max_error(run.p3, reference), 1e-6});
  }
  return rows;
}

}  // namespace heavesim::validation
