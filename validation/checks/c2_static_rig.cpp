// C2: static equilibrium of the rig. H0 (rigid and 4-segment elastic string) and H0b
// (cases/rig) with the passive compensator, gas pressure from static balance, the
// platform held still; over 100 s
// every joint must carry exactly the weight hanging below it (docs/physics/drilling-rig.md §6:
// 1.62 MN at the top-drive/string joint, 2.06 MN at the travelling-block/top-drive
// joint, 2.60 MN on the compensator), computed here from the masses and the string's
// buoyancy, and the stroke must not drift.
#include <cmath>

#include <fmt/format.h>

#include "kernel/algorithms/joint_reactions.hpp"
#include "validation/checks/validation_suite.hpp"

namespace heavesim::validation {
namespace {

// cases/rig/parameters.yaml
constexpr double m_crown = 30000, m_tb = 25000, m_td = 45000, m_string = 190000;
constexpr double buoyancy = 1025.0 / 7850.0 * m_string * g;

struct Expected {
  std::string joint;
  double vertical_force;  // N, parent on child
};

void check_rig(const std::string& case_path, const std::vector<Expected>& expected, const std::string& stroke_joint,
               std::vector<ValidationRow>& rows) {
  double reaction_error = 0.0, drift = 0.0, stroke0 = 0.0;
  bool first = true;
  run_case(case_path, {}, [&](double, const MultibodySystem& system) {
    const Model& model = system.model();
    for (const Expected& e : expected) {
      const JointReaction r = joint_reaction(model, system.data(), model.joint_index(e.joint));
      const Vector3 expected_force(0.0, 0.0, e.vertical_force);
      reaction_error = std::max(reaction_error, (r.force_world - expected_force).norm() / e.vertical_force);
    }
    const Joint& stroke = model.joints[model.joint_index(stroke_joint)];
    const double s = system.configuration()[stroke.q_index];
    if (first) stroke0 = s, first = false;
    drift = std::max(drift, std::abs(s - stroke0));
  });
  std::string joints;
  for (const Expected& e : expected) joints += (joints.empty() ? "" : ", ") + e.joint;
  rows.push_back({"C2", case_path.substr(case_path.rfind('/') + 1) + ", 100 s (" + joints + ")",
                  "joint reactions vs hanging weights, relative", reaction_error, 1e-6});
  rows.push_back({"C2", case_path.substr(case_path.rfind('/') + 1) + ", 100 s", "stroke drift [m]", drift, 1e-3});
}

}  // namespace

std::vector<ValidationRow> check_c2_static_rig() {
  const double string_load = m_string * g - buoyancy;
  const double td_load = string_load + m_td * g;
  const double total = td_load + (m_tb + m_crown) * g;
  std::vector<ValidationRow> rows;
  check_rig("cases/validation/c2_static_h0.yaml",
            {{"td_string", string_load}, {"tb_td", td_load}, {"crown_tb", td_load + m_tb * g}, {"compensator", total}},
            "compensator", rows);
  // H0b: the drilling line carries the travelling block; the compensator the crown and the line tension.
  check_rig("cases/validation/c2_static_h0b.yaml", {{"td_string", string_load}, {"tb_td", td_load}, {"compensator", total}},
            "compensator", rows);
  // Elastic string: segment joint k carries the (5 - k) quarters below it.
  check_rig("cases/validation/c2_static_h0_elastic.yaml",
            {{"seg1", string_load}, {"seg2", 0.75 * string_load}, {"seg3", 0.5 * string_load},
             {"seg4", 0.25 * string_load}, {"tb_td", td_load}, {"compensator", total}},
            "compensator", rows);
  return rows;
}

}  // namespace heavesim::validation
