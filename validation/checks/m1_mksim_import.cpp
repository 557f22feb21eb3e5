// M1: the MKSim paper's slider-crank written in MKSim's language
// (cases/kinematics/mksim_slider_crank.mks), imported (app/mksim/) and analysed by the
// kinematic sweep. MKSim's count (28 coordinates, 27 equations, DOF 1) and heavesim's DOF
// report (one free direction: the rod's spin between its spherical joints); the block on
// its driver x = 8 + 3 sin t; the crank against the closed form cos(theta) = (x^2 + r^2 -
// l^2) / (2 r x) with the paper's r = 6 m, l = 10 m; the rod's spin held at zero by the
// minimum-kinetic-energy motion.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

#include <unistd.h>

#include "app/mksim/mksim_reader.hpp"
#include "app/mksim/mksim_to_case.hpp"
#include "app/run/kinematic_run.hpp"
#include "validation/checks/validation_suite.hpp"
#include "validation/oracles/mechanism_kinematics.hpp"

namespace heavesim::validation {

std::vector<ValidationRow> check_m1_mksim_import() {
  const mksim::Model model = mksim::read_model_file(project_file("cases/kinematics/mksim_slider_crank.mks"));
  const mksim::Count count = mksim::count(model);
  const std::filesystem::path case_path =
      std::filesystem::temp_directory_path() / fmt::format("heavesim_m1_{}.yaml", ::getpid());
  std::ofstream(case_path) << mksim::to_case_yaml(model);
  const CaseDefinition definition = load_case(case_path.string());
  std::filesystem::remove(case_path);
  Scene scene = build_scene(definition);
  const int free_directions = scene.model->nv - scene.assembly.rank.rank;

  const double r = 6.0, l = 10.0;
  double block = 0.0, crank = 0.0, spin = 0.0;
  const KinematicOutcome outcome = run_kinematics(scene, definition, false, [&](double t, const VectorX&,
                                                                               const KinematicPoint&) {
    const MultibodySystem& system = *scene.system;
    const Model& kinematic_model = system.model();
    const Data& data = system.data();
    const auto placement = [&](const char* body) {
      const int link = kinematic_model.link_index(body);
      return data.X_world_link[link] * kinematic_model.links[link].X_link_body;
    };
    const Vector3 block_position = placement("block").translation();
    block = std::max({block, std::abs(block_position.x() - (8 + 3 * std::sin(t))), std::abs(block_position.y()),
                      std::abs(block_position.z())});
    const oracle::Motion3 x{8 + 3 * std::sin(t), 3 * std::cos(t), -3 * std::sin(t)};
    const double theta = oracle::slider_crank_crank_angle(r, l, x).position;
    const Vector3 crank_axis = placement("pend1").rotation().col(0);  // the crank along its body x
    crank = std::max(crank, std::abs(std::remainder(std::atan2(crank_axis.y(), crank_axis.x()) - theta, 2 * M_PI)));
    const int rod = kinematic_model.link_index("pend2");
    const Vector3 rod_axis = placement("pend2").rotation().col(0);
    spin = std::max(spin, std::abs(data.velocity_world[rod].angular().dot(rod_axis)));
    return true;
  });
  const std::string subject =
      outcome.completed ? fmt::format("M1 MKSim slider-crank imported (r = 6, l = 10, x = 8 + 3 sin t), {} points",
                                      outcome.points)
                        : "M1 MKSim slider-crank imported: stopped";
  const double failed = outcome.completed ? 0.0 : INFINITY;
  return {{"M1", count.summary(), "MKSim count: |coordinates - 28| + |equations - 27| (exact)",
           static_cast<double>(std::abs(count.coordinates - 28) + std::abs(count.equations() - 27)), 0.0},
          {"M1", fmt::format("heavesim DOF report: {} joint speeds, rank {}", scene.model->nv, scene.assembly.rank.rank),
           "free directions - 1 (the rod's spin; exact)", static_cast<double>(std::abs(free_directions - 1)), 0.0},
          {"M1", subject, "block position vs 8 + 3 sin t [m]", block + failed, 1e-12},
          {"M1", subject, "crank angle vs acos((x^2 + r^2 - l^2)/(2 r x)) [rad]", crank + failed, 1e-12},
          {"M1", subject, "rod spin about its axis (minimum-energy motion) [rad/s]", spin + failed, 1e-12}};
}

}  // namespace heavesim::validation
