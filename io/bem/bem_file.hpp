#pragma once
// The BEM data file of a case's radiation, wave_excitation or linear hydrostatics
// element, read by its format: WAMIT (.1, .3, .hst and any other extension), BEMIO
// HDF5 (.h5, .hdf5) or Capytaine NetCDF4 (.nc). Every format gives hydro's dimensional
// types in WAMIT's conventions (hydro/bem/bem_data.hpp); only the file an element
// declares is read. Bad data is a hydro::DataError naming the file and the line (WAMIT)
// or the dataset (HDF5).
#include <string>

#include "hydro/bem/bem_data.hpp"
#include "io/bem/wamit_reader.hpp"

namespace heavesim::bem {

enum class BemFileFormat { wamit, bemio, capytaine };

/// By extension (case-insensitive): .h5/.hdf5 BEMIO, .nc Capytaine, anything else WAMIT.
BemFileFormat bem_file_format(const std::string& path);

/// rho and g of `scaling` dimensionalise every format; its length_scale (ULEN) only
/// WAMIT's files (the HDF5 formats are not scaled by a length).
hydro::RadiationData read_radiation_file(const std::string& path, const bem::WamitScaling& scaling);
hydro::ExcitationData read_excitation_file(const std::string& path, const bem::WamitScaling& scaling);
hydro::Matrix6 read_hydrostatic_stiffness_file(const std::string& path, const bem::WamitScaling& scaling);

}  // namespace heavesim::bem
