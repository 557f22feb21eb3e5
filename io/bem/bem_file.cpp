#include "io/bem/bem_file.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "io/bem/bemio_reader.hpp"
#include "io/bem/capytaine_reader.hpp"

namespace heavesim::bem {
namespace {

CaseFluid fluid(const bem::WamitScaling& scaling) { return {scaling.density, scaling.gravity}; }

/// The reader of `path`'s format, called with the scaling it takes.
template <class Wamit, class Bemio, class Capytaine>
auto read_by_format(const std::string& path, const bem::WamitScaling& scaling, Wamit wamit, Bemio bemio,
                    Capytaine capytaine) {
  switch (bem_file_format(path)) {
    case BemFileFormat::bemio:
      return bemio(path, fluid(scaling));
    case BemFileFormat::capytaine:
      return capytaine(path, fluid(scaling));
    case BemFileFormat::wamit:
      break;
  }
  return wamit(path, scaling);
}

}  // namespace

BemFileFormat bem_file_format(const std::string& path) {
  std::string extension = std::filesystem::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (extension == ".h5" || extension == ".hdf5") return BemFileFormat::bemio;
  if (extension == ".nc") return BemFileFormat::capytaine;
  return BemFileFormat::wamit;
}

hydro::RadiationData read_radiation_file(const std::string& path, const bem::WamitScaling& scaling) {
  return read_by_format(path, scaling, bem::read_wamit_1, read_bemio_radiation, read_capytaine_radiation);
}

hydro::ExcitationData read_excitation_file(const std::string& path, const bem::WamitScaling& scaling) {
  return read_by_format(path, scaling, bem::read_wamit_3, read_bemio_excitation, read_capytaine_excitation);
}

hydro::Matrix6 read_hydrostatic_stiffness_file(const std::string& path, const bem::WamitScaling& scaling) {
  return read_by_format(path, scaling, bem::read_wamit_hst, read_bemio_hydrostatic_stiffness,
                        read_capytaine_hydrostatic_stiffness);
}

}  // namespace heavesim::bem
