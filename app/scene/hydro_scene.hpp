#pragma once
// The data of the case's hydrodynamic force elements (hydro/) and its sea, read before
// the model is built; the elements themselves are built by their kinds (app/forces/).
// Only what the case declares is read.
#include <map>
#include <memory>
#include <set>
#include <string>

#include "app/case/case_definition.hpp"
#include "hydro/bem/bem_data.hpp"
#include "hydro/hydrostatics/hull_mesh.hpp"
#include "kernel/system/multibody_system.hpp"

namespace heavesim {

/// The data files of the hydro elements, read once before the model is built (A(inf)
/// enters the body inertia). hydro::DataError becomes an InputError at the element's
/// file key whose text names the data file and its line.
struct HydroData {
  std::map<std::string, hydro::RadiationData> radiation;    // by element name
  std::map<std::string, hydro::ExcitationData> excitation;  // by element name
  std::map<std::string, hydro::Matrix6> stiffness;          // linear hydrostatics C, by element name
  std::map<std::string, hydro::HullMesh> meshes;            // nonlinear hydrostatics, by element name
  /// A(inf) of every body with a radiation element, as added inertia about the body
  /// frame origin, body axes, [angular; linear] (added_mass.hpp), by body name.
  std::map<std::string, Matrix6> added_inertia;
  /// The incident sea (no components when none is declared), one per scene, shared by
  /// the elements that record it.
  std::shared_ptr<const hydro::WaveTrain> waves;
  std::set<std::string> radiating_bodies;  // one radiation element per body

  /// Adds `added` [angular; linear, body frame origin, body axes] to the body's added
  /// inertia: several elements add up.
  void add_inertia(const std::string& body, const Matrix6& added) {
    added_inertia.try_emplace(body, Matrix6::Zero()).first->second += added;
  }
};
/// Builds the sea, so that hydro's rules on it (wave_spectrum.hpp, wave_train.hpp,
/// dispersion.hpp) are checked for every case that declares one, then each force kind's
/// data (its `read_data`, app/forces/), in declaration order.
HydroData read_hydro_data(const CaseDefinition& definition);

/// The incident sea of the case (empty when none is declared). A hydro ParameterError
/// becomes an InputError at its `waves:` or `environment:` key.
hydro::WaveTrain wave_train(const CaseDefinition& definition);

}  // namespace heavesim
