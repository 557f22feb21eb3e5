#include "app/rao/frequency_domain_reference.hpp"

#include <algorithm>

#include "app/scene/hydro_scene.hpp"
#include "hydro/elements/linear_body_loads.hpp"
#include "hydro/excitation/excitation_interpolation.hpp"
#include "hydro/radiation/added_mass.hpp"

namespace heavesim {
namespace {

/// A(w), B(w) linear in w between the BEM frequencies, held beyond them.
std::pair<hydro::Matrix6, hydro::Matrix6> radiation_at(const hydro::RadiationData& r, double w) {
  const std::vector<double>& f = r.angular_frequencies;
  if (w <= f.front()) return {r.added_mass.front(), r.damping.front()};
  if (w >= f.back()) return {r.added_mass.back(), r.damping.back()};
  const std::size_t n = static_cast<std::size_t>(std::upper_bound(f.begin(), f.end(), w) - f.begin());
  const double s = (w - f[n - 1]) / (f[n] - f[n - 1]);
  return {(1 - s) * r.added_mass[n - 1] + s * r.added_mass[n], (1 - s) * r.damping[n - 1] + s * r.damping[n]};
}

}  // namespace

std::pair<std::string, std::string> wave_excitation_element(const CaseDefinition& definition) {
  for (const ForceDefinition& force : definition.forces)
    if (const auto* excitation = std::get_if<WaveExcitationDefinition>(&force.kind)) return {force.name, excitation->body};
  throw definition.error_at("forces", "no wave_excitation element",
                            "a wave_excitation force on the floating body: its recorded wave_elevation (the incident "
                            "wave at the body's reference point) is the RAO's input");
}

std::optional<FrequencyDomainReference> FrequencyDomainReference::of_case(const CaseDefinition& definition,
                                                                          std::string& reason) {
  const std::pair<std::string, std::string> element = wave_excitation_element(definition);
  const std::string &excitation_name = element.first, &platform = element.second;
  std::string radiation_name, hydrostatics_name;
  const HydrostaticsDefinition* hydrostatics = nullptr;
  FrequencyDomainReference reference;
  reference.heading_ = definition.waves.heading;
  for (const ForceDefinition& force : definition.forces) {
    if (const auto* r = std::get_if<RadiationDefinition>(&force.kind); r && r->body == platform) radiation_name = force.name;
    if (const auto* h = std::get_if<HydrostaticsDefinition>(&force.kind); h && h->body == platform && !h->nonlinear) {
      hydrostatics_name = force.name;
      hydrostatics = h;
    }
    if (const auto* d = std::get_if<LinearDampingDefinition>(&force.kind); d && d->body == platform)
      reference.settings_.external_damping += d->damping;
    if (const auto* m = std::get_if<MooringDefinition>(&force.kind); m && m->body == platform)
      reference.settings_.external_stiffness += m->stiffness;
  }
  for (const ForceDefinition& force : definition.forces)
    if (force.name == excitation_name && std::get<WaveExcitationDefinition>(force.kind).heave_estimate) {
      reason = "its wave_excitation is the heave estimate, not BEM data";
      return std::nullopt;
    }
  if (radiation_name.empty() || hydrostatics_name.empty()) {
    reason = "the platform '" + platform + "' has no " + (radiation_name.empty() ? "radiation" : "linear hydrostatics") +
             " element";
    return std::nullopt;
  }
  const HydroData data = read_hydro_data(definition);
  const BodyDefinition& body = *std::find_if(definition.bodies.begin(), definition.bodies.end(),
                                             [&](const BodyDefinition& b) { return b.name == platform; });
  // The kernel's [angular; linear] spatial inertia about the body frame origin, in WAMIT order.
  reference.settings_.mass = hydro::swap_linear_angular(body.inertia.matrix());
  reference.bem_.radiation = data.radiation.at(radiation_name);
  reference.bem_.excitation = data.excitation.at(excitation_name);
  const double g = definition.gravity.norm();
  reference.bem_.hydrostatic_stiffness = data.stiffness.at(hydrostatics_name);
  if (!hydrostatics->hst_includes_gravity)
    reference.bem_.hydrostatic_stiffness += hydro::wamit_gravitational_stiffness(body.inertia.mass(), body.inertia.com(), g);
  return reference;
}

hydro::ComplexVector6 FrequencyDomainReference::rao(double w) const {
  // One frequency's BEM data, interpolated as the run's elements interpolate them.
  hydro::BemData at_w;
  const auto [added_mass, damping] = radiation_at(bem_.radiation, w);
  at_w.radiation.angular_frequencies = {w};
  at_w.radiation.added_mass = {added_mass};
  at_w.radiation.damping = {damping};
  at_w.excitation.angular_frequencies = {w};
  at_w.excitation.headings = {heading_};
  at_w.excitation.force = {{hydro::interpolate_excitation(bem_.excitation, w, heading_)}};
  at_w.hydrostatic_stiffness = bem_.hydrostatic_stiffness;
  return hydro::frequency_domain_rao(at_w, settings_, 0, 0);
}

}  // namespace heavesim
