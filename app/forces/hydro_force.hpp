#pragma once
// What the hydrodynamic force kinds share (hydrostatics, radiation, wave_excitation,
// linear_damping, quadratic_damping, added_mass, mooring): each acts on one floating
// body's reference point (its body frame origin), in WAMIT order [surge, sway, heave,
// roll, pitch, yaw], world axes. Their data files (BEM results, hull meshes) are read
// before the model is built (`read_data`, app/scene/hydro_scene.hpp), because a
// radiation element's A(inf) is its body's added inertia.
#include <functional>
#include <memory>
#include <string>

#include "app/forces/force_kind.hpp"
#include "hydro/data_error.hpp"
#include "hydro/elements/element_factories.hpp"
#include "hydro/waves/wave_train.hpp"
#include "io/bem/bem_file.hpp"

namespace heavesim {

struct CaseDefinition;
struct HydroData;

/// A hydro element's data file.
struct HydroDataFile {
  std::string path;           // resolved against the directory of the case file that holds the key
  std::string key;            // the key it came from ("hst", "mesh", "file"), for errors; empty: no file
  double length_scale = 1.0;  // WAMIT ULEN [m]
};

/// A 6 x 6 matrix in WAMIT order: 6 rows of 6 numbers, or 6 numbers (its diagonal).
hydro::Matrix6 read_matrix6(const NodeReader& reader);
/// 6 numbers in WAMIT order.
hydro::Vector6 read_vector6(const NodeReader& reader);
void check_symmetric_positive(const NodeReader& reader, const hydro::Matrix6& matrix, const std::string& what);
/// Reads the data file at `file_key` (none when empty; relative paths from the directory
/// of the file that holds the key; the file must exist), then `length_scale` (WAMIT
/// files only, unless `mesh`).
HydroDataFile read_data_file(const NodeReader& item, const std::string& file_key, bool mesh);

/// WAMIT's dimensional scaling of the case (rho, g, ULEN).
bem::WamitScaling wamit_scaling(const CaseDefinition& definition, double length_scale);
/// An InputError at forces[name].<file key> for a data file's error, naming the data
/// file's line (or, for an HDF5 file, its dataset: the DataError's file is then
/// "<path>:<dataset>").
[[noreturn]] void throw_data_error(const CaseDefinition& definition, const std::string& name, const std::string& key,
                                   const hydro::DataError& error);
/// Reads one data file through `read`, mapping a hydro::DataError (throw_data_error).
template <class Read>
auto read_checked(const CaseDefinition& definition, const std::string& name, const HydroDataFile& file, Read read) {
  try {
    return read();
  } catch (const hydro::DataError& error) {
    throw_data_error(definition, name, file.key, error);
  }
}

/// Adds the element `make(link)` makes on `body` (an InputError at forces[name].body
/// unless it is a floating body; a ParameterError of `make` becomes an InputError at its
/// key), recording its load on the body reference point under /forces/<name>/
/// (app/scene/recorded_load.hpp), and `recorded_waves`' elevation there when given.
void add_hydro_element(SceneBuildContext& context, const std::string& name, const std::string& body,
                       const std::function<std::unique_ptr<ForceElement>(int link)>& make,
                       std::shared_ptr<const hydro::WaveTrain> recorded_waves = nullptr);
/// The link of `body`; an InputError at forces[name].body unless it is a floating body.
int floating_body_link(const SceneBuildContext& context, const std::string& name, const std::string& body);

}  // namespace heavesim
