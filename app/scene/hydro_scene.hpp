#pragma once
// Builds the case's hydrodynamic force elements (hydro/) on the model. Only what the
// case declares is read and built.
#include <map>
#include <memory>

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
};
/// Also builds the sea, so that hydro's rules on it (wave_spectrum.hpp, wave_train.hpp,
/// dispersion.hpp) are checked for every case that declares one.
HydroData read_hydro_data(const CaseDefinition& definition);

/// The incident sea of the case (empty when none is declared). A hydro ParameterError
/// becomes an InputError at its `waves:` or `environment:` key.
hydro::WaveTrain wave_train(const CaseDefinition& definition);

/// Adds every hydro element of the case to `system`. Each one records its load on the
/// body reference point under /forces/<name>/: force_x..z [N], moment_x..z [N m]
/// (about the body frame origin, world axes), plus its own channels; wave excitation
/// also the wave elevation at the body reference point. Throws InputError.
void add_hydro_elements(const CaseDefinition& definition, const HydroData& data, const Model& model,
                        MultibodySystem& system);

}  // namespace heavesim
