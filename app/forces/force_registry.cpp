#include "app/forces/force_registry.hpp"

#include <array>
#include <stdexcept>
#include <utility>

#include "app/case/case_definition.hpp"
#include "app/forces/force_kinds.hpp"

namespace heavesim {
namespace {

/// Reads alternative I of ForceKindDefinition and appends it to the case's forces.
template <std::size_t I>
void read_kind(const NodeReader& item, const std::string&, const std::string& name, CaseDefinition& definition) {
  using Kind = std::variant_alternative_t<I, ForceKindDefinition>;
  definition.forces.push_back({name, ForceKindDefinition(std::in_place_index<I>, Kind::read(item, definition))});
  definition.item_paths[name] = item.path();
}

template <std::size_t... I>
constexpr auto registered_kinds(std::index_sequence<I...>) {
  return std::array<ForceKind, sizeof...(I)>{
      ForceKind{std::variant_alternative_t<I, ForceKindDefinition>::type,
                &std::variant_alternative_t<I, ForceKindDefinition>::keys,
                &std::variant_alternative_t<I, ForceKindDefinition>::sub_sections, &read_kind<I>}...};
}

constexpr auto kinds = registered_kinds(std::make_index_sequence<std::variant_size_v<ForceKindDefinition>>{});

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
