#include "app/case/hydro_reader.hpp"

#include <algorithm>
#include <climits>

#include <fmt/format.h>

namespace heavesim {
namespace {

hydro::Ramp read_ramp(const NodeReader& reader) {
  // ramp: a duration [s] (cosine ramp), or {kind: cosine | tanh | none, duration: ..}
  hydro::Ramp ramp;
  if (reader.node().is_scalar()) {
    ramp.kind = hydro::RampKind::cosine;
    ramp.duration = reader.non_negative_number();
    return ramp;
  }
  reader.expect_section("ramp");
  const std::string kind = reader["kind"].choice({"cosine", "tanh", "none"});
  ramp.kind = kind == "cosine" ? hydro::RampKind::cosine
              : kind == "tanh" ? hydro::RampKind::hyperbolic_tangent
                               : hydro::RampKind::none;
  if (ramp.kind != hydro::RampKind::none) ramp.duration = reader["duration"].positive_number();
  return ramp;
}

}  // namespace

void read_waves(const NodeReader& reader, CaseDefinition& definition) {
  WaveDefinition& waves = definition.waves;
  const std::string type = reader["type"].choice({"regular", "jonswap", "pierson_moskowitz", "none"});
  if (type == "none") {
    reader.expect_section("waves", "none");
    return;
  }
  if (type == "regular") {
    reader.expect_section("waves", "regular");
    waves.type = WaveDefinition::Type::regular;
    waves.amplitude = reader["amplitude"].non_negative_number();
    waves.period = reader["period"].positive_number();
    waves.phase = reader.number_or("phase", 0.0);
  } else {
    reader.expect_section("waves", "irregular");
    waves.type = type == "jonswap" ? WaveDefinition::Type::jonswap : WaveDefinition::Type::pierson_moskowitz;
    waves.significant_height = reader["hs"].positive_number();
    waves.peak_period = reader["tp"].positive_number();
    if (auto gamma = reader.optional("gamma")) {
      if (waves.type != WaveDefinition::Type::jonswap)
        gamma->fail("'gamma' on a Pierson-Moskowitz sea", "no 'gamma' (type: jonswap has a peak enhancement)");
      waves.peak_enhancement = gamma->number();  // its range is hydro::Jonswap's rule
    }
    hydro::IrregularSeaSettings& sea = waves.irregular;
    sea.num_components = 200;
    // The number of components and the band are hydro::irregular_sea's rules, checked
    // when the scene builds the sea.
    if (auto components = reader.optional("components"))
      sea.num_components = static_cast<int>(std::clamp<long>(components->integer(), INT_MIN, INT_MAX));
    if (auto seed = reader.optional("seed")) {
      const long s = seed->integer();
      if (s < 0) seed->fail(fmt::format("{}", s), "a seed >= 0");
      sea.seed = static_cast<unsigned long long>(s);
    }
    if (auto discretization = reader.optional("discretization"))
      sea.discretization = discretization->choice({"equal_energy", "equal_spacing"}) == "equal_energy"
                               ? hydro::FrequencyDiscretization::equal_energy
                               : hydro::FrequencyDiscretization::equal_spacing;
    sea.min_frequency = reader.optional("min_frequency") ? reader["min_frequency"].positive_number() : 0.1;
    sea.max_frequency = reader.optional("max_frequency") ? reader["max_frequency"].positive_number() : 3.0;
  }
  waves.heading = reader.number_or("heading", 0.0);
  if (auto ramp = reader.optional("ramp")) waves.ramp = read_ramp(*ramp);
}

}  // namespace heavesim
