#include "app/case/force_kinds.hpp"

#include <stdexcept>

#include "app/case/control_reader.hpp"
#include "app/case/element_reader.hpp"
#include "app/case/hydro_reader.hpp"

namespace heavesim {
namespace {

constexpr ForceKind kinds[] = {
    {"spring_damper", read_kernel_force},
    {"point_force", read_kernel_force},
    {"ground_contact", read_kernel_force},
    {"pneumatic_compensator", read_compensator},
    {"active_compensator", read_compensator},
    {"added_mass", read_hydro_force},
    {"hydrostatics", read_hydro_force},
    {"radiation", read_hydro_force},
    {"wave_excitation", read_hydro_force},
    {"linear_damping", read_hydro_force},
    {"quadratic_damping", read_hydro_force},
    {"mooring", read_hydro_force},
};

}  // namespace

std::span<const ForceKind> force_kinds() { return kinds; }

std::vector<std::string_view> force_kind_names() {
  std::vector<std::string_view> names;
  for (const ForceKind& kind : kinds) names.push_back(kind.type);
  return names;
}

const ForceKind& force_kind(std::string_view type) {
  for (const ForceKind& kind : kinds)
    if (kind.type == type) return kind;
  throw std::out_of_range("no force kind '" + std::string(type) + "'");
}

}  // namespace heavesim
