// heavesim import-mksim FILE.mks -o CASE.yaml: an MKSim model (docs/mksim-format.md) as
// a heavesim case. Prints MKSim's coordinate and equation count and heavesim's.
#include <fmt/format.h>

#include <fstream>

#include "app/mksim/mksim_reader.hpp"
#include "app/mksim/mksim_to_case.hpp"
#include "cli/commands/commands.hpp"

namespace heavesim {

int import_mksim_command(const std::string& model_path, const std::string& case_path) {
  const mksim::Model model = mksim::read_model_file(model_path);
  const std::string yaml = mksim::to_case_yaml(model);
  std::ofstream out(case_path, std::ios::binary | std::ios::trunc);
  out << yaml;
  out.close();
  if (!out) {
    fmt::print(stderr, "heavesim: error: cannot write the case file '{}'\n", case_path);
    return 1;
  }
  fmt::print("model {} ({} bodies, {} triads, {} joints, {} drivers) -> {}\n{}\n{}\n", model.name,
             model.bodies.size(), model.triads.size(), model.joints.size(), model.drivers.size(), case_path,
             mksim::count(model).summary(), mksim::joint_coordinate_count(model).summary());
  return 0;
}

}  // namespace heavesim
