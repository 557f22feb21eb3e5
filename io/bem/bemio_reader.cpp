#include "io/bem/bemio_reader.hpp"

#include <cmath>
#include <numeric>
#include <optional>

#include <fmt/format.h>

namespace heavesim::bem {
namespace {

const std::string parameters = "/simulation_parameters/";
const std::string coefficients = "/body1/hydro_coeffs/";

/// The file with its frequencies and the factors that make its coefficients
/// dimensional for the case's fluid.
class BemioFile {
 public:
  BemioFile(const std::string& path, const CaseFluid& fluid) : file(path, "a BEMIO HDF5 file") {
    const std::string flag = parameters + "scaled";
    const char* flag_meaning =
        "0 (stored nondimensional: A/rho, B/(rho w), X/(rho g), C/(rho g)) or 1 (stored dimensional)";
    if (!file.has(flag)) file.fail(flag, "no such dataset", std::string("the flag scaled: ") + flag_meaning);
    const double scaled = file.read_scalar(flag);
    if (scaled != 0.0 && scaled != 1.0) file.fail(flag, fmt::format("scaled = {:g}", scaled), flag_meaning);
    nondimensional = scaled == 0.0;
    radiation_factor = fluid.density;
    excitation_factor = fluid.density * fluid.gravity;
    if (!nondimensional) {  // dimensional for the file's fluid: rescale to the case's
      const double rho = positive(parameters + "rho", "kg/m^3"), g = positive(parameters + "g", "m/s^2");
      radiation_factor /= rho;
      excitation_factor /= rho * g;
    }
    const std::string w = parameters + "w";
    file.check_units(w, {"rad/s"});
    const hdf5::Array stored = file.read(w);
    if (stored.shape.size() != 1 || stored.values.empty())
      file.fail(w, "shape " + hdf5::shape_text(stored.shape), "a list of the Nf wave frequencies [rad/s]");
    frequencies = stored.values;
    for (std::size_t k = 0; k < frequencies.size(); ++k)
      if (!(frequencies[k] >= 0.0 && std::isfinite(frequencies[k])))
        file.fail(w, fmt::format("w = {} rad/s (entry {})", frequencies[k], k + 1), "frequencies 0 <= w < inf");
    check_periods();
  }

  /// The array `dataset`, expected with shape `expected` (0: 6 Nb, a multiple of 6) as
  /// docs/physics/hydrodynamics.md §10 lists it, or with its dimensions reversed.
  AxisArray oriented(const std::string& dataset, const std::vector<hsize_t>& expected, const char* layout) const {
    hdf5::Array array = file.read(dataset);
    const std::size_t rank = expected.size();
    auto matches = [&](bool reversed) {
      if (array.shape.size() != rank) return false;
      for (std::size_t k = 0; k < rank; ++k) {
        const hsize_t stored = array.shape[reversed ? rank - 1 - k : k];
        if (expected[k] ? stored != expected[k] : (stored == 0 || stored % 6 != 0)) return false;
      }
      return true;
    };
    std::vector<int> axes(rank);
    std::iota(axes.begin(), axes.end(), 0);
    if (!matches(false)) {
      if (!matches(true))
        file.fail(dataset, "shape " + hdf5::shape_text(array.shape),
                  fmt::format("shape {} with Nf = {} (the length of {}w), or its reverse", layout, frequencies.size(),
                              parameters));
      std::reverse(axes.begin(), axes.end());
    }
    return AxisArray(std::move(array), axes);
  }

  /// Body 1's own 6 x 6 block of `array` (frequency index `k`, if it has one), finite.
  hydro::Matrix6 block(const AxisArray& array, const std::string& dataset, std::optional<std::size_t> k,
                       double factor, const std::string& at) const {
    hydro::Matrix6 M;
    for (std::size_t i = 0; i < 6; ++i)
      for (std::size_t j = 0; j < 6; ++j) {
        const double value = k ? array.at({i, j, *k}) : array.at({i, j});
        M(i, j) = dimensional(file, dataset, value, factor, fmt::format("entry ({},{}) {}", i + 1, j + 1, at));
      }
    return M;
  }

  std::string at_frequency(std::size_t k) const {
    return fmt::format("at w = {:g} rad/s (frequency {} of {})", frequencies[k], k + 1, frequencies.size());
  }

  hdf5::Reader file;
  std::vector<double> frequencies;  // w [rad/s] in the file's order
  bool nondimensional = true;
  double radiation_factor = 1.0;   // A = factor A_stored, B = factor (w) B_stored
  double excitation_factor = 1.0;  // X = factor X_stored, C = factor C_stored

 private:
  double positive(const std::string& dataset, const char* units) const {
    file.check_units(dataset, {units});
    const double value = file.read_scalar(dataset);
    if (!(value > 0.0 && std::isfinite(value)))
      file.fail(dataset, fmt::format("{}", value), fmt::format("a positive value [{}] (scaled = 1)", units));
    return value;
  }

  /// T, when present, must be 2 pi / w entry by entry (a mismatched or reordered list).
  void check_periods() const {
    const std::string T = parameters + "T";
    if (!file.has(T)) return;
    file.check_units(T, {"s"});
    const hdf5::Array periods = file.read(T);
    if (periods.values.size() != frequencies.size())
      file.fail(T, fmt::format("{} periods", periods.values.size()),
                fmt::format("{} periods, one per frequency of {}w", frequencies.size(), parameters));
    for (std::size_t k = 0; k < frequencies.size(); ++k)
      if (frequencies[k] > 0.0 && !(std::abs(periods.values[k] * frequencies[k] - 2 * M_PI) <= 1e-6 * 2 * M_PI))
        file.fail(T, fmt::format("T = {:g} s at entry {}, where w = {:g} rad/s", periods.values[k], k + 1, frequencies[k]),
                  "T = 2 pi / w");
  }
};

}  // namespace

hydro::RadiationData read_bemio_radiation(const std::string& path, const CaseFluid& fluid) {
  const BemioFile bemio(path, fluid);
  const hdf5::Reader& file = bemio.file;
  const std::string added = coefficients + "added_mass/all", damping = coefficients + "radiation_damping/all",
                    infinite = coefficients + "added_mass/inf_freq";
  if (!file.has(infinite))
    file.fail(infinite, "no such dataset (no infinite-frequency added mass)",
              "A(inf)/rho of shape (6, 6 Nb): the time-domain model needs A(inf) (rerun the BEM code with the "
              "infinite-frequency problem)");
  const std::size_t nf = bemio.frequencies.size();
  const AxisArray A = bemio.oriented(added, {6, 0, nf}, "(6, 6 Nb, Nf)");
  const AxisArray B = bemio.oriented(damping, {6, 0, nf}, "(6, 6 Nb, Nf)");
  const AxisArray A_infinite = bemio.oriented(infinite, {6, 0}, "(6, 6 Nb)");
  hydro::RadiationData data;
  data.added_mass_infinite = bemio.block(A_infinite, infinite, std::nullopt, bemio.radiation_factor, "(w = inf)");
  symmetrise_checked(file, infinite, data.added_mass_infinite, "A", "(w = inf)");
  for (std::size_t k = 0; k < nf; ++k) {
    const double w = bemio.frequencies[k];
    hydro::Matrix6 added_mass = bemio.block(A, added, k, bemio.radiation_factor, bemio.at_frequency(k));
    symmetrise_checked(file, added, added_mass, "A", bemio.at_frequency(k));
    if (w == 0.0) {
      data.added_mass_zero = added_mass;
      data.has_added_mass_zero = true;
      continue;
    }
    // B_bar = B / (rho w) when nondimensional. B is symmetrised unchecked, as for WAMIT
    // files (discretisation asymmetry is larger in B at short periods).
    const double factor = bemio.radiation_factor * (bemio.nondimensional ? w : 1.0);
    const hydro::Matrix6 b = bemio.block(B, damping, k, factor, bemio.at_frequency(k));
    data.angular_frequencies.push_back(w);
    data.added_mass.push_back(added_mass);
    data.damping.push_back(symmetric_part(b));
  }
  sort_by_frequency(file, parameters + "w", data);
  return data;
}

hydro::ExcitationData read_bemio_excitation(const std::string& path, const CaseFluid& fluid) {
  const BemioFile bemio(path, fluid);
  const hdf5::Reader& file = bemio.file;
  const std::string directions = parameters + "wave_dir";
  file.check_units(directions, {"deg", "degrees"});
  const hdf5::Array headings = file.read(directions);
  if (headings.shape.size() != 1 || headings.values.empty())
    file.fail(directions, "shape " + hdf5::shape_text(headings.shape), "a list of the Nh wave headings [deg]");
  const std::size_t nh = headings.values.size(), nf = bemio.frequencies.size();
  const std::string re = coefficients + "excitation/re", im = coefficients + "excitation/im";
  const AxisArray real = bemio.oriented(re, {6, nh, nf}, fmt::format("(6, Nh = {}, Nf)", nh).c_str());
  const AxisArray imaginary = bemio.oriented(im, {6, nh, nf}, fmt::format("(6, Nh = {}, Nf)", nh).c_str());
  hydro::ExcitationData data;
  for (std::size_t h = 0; h < nh; ++h) {
    data.headings.push_back(dimensional(file, directions, headings.values[h], M_PI / 180.0, fmt::format("heading {}", h + 1)));
  }
  for (std::size_t k = 0; k < nf; ++k)
    if (bemio.frequencies[k] > 0.0) data.angular_frequencies.push_back(bemio.frequencies[k]);
  data.force.assign(nh, {});
  for (std::size_t h = 0; h < nh; ++h)
    for (std::size_t k = 0; k < nf; ++k) {
      if (bemio.frequencies[k] == 0.0) continue;  // no excitation at w = 0
      hydro::ComplexVector6 X;
      for (std::size_t i = 0; i < 6; ++i) {
        const std::string at = fmt::format("entry ({},{},{}) {}", i + 1, h + 1, k + 1, bemio.at_frequency(k));
        // BEMIO keeps WAMIT's e^{+i w t} phase (WEC-Sim's readWAMIT does not conjugate).
        X[i] = {dimensional(file, re, real.at({i, h, k}), bemio.excitation_factor, at),
                dimensional(file, im, imaginary.at({i, h, k}), bemio.excitation_factor, at)};
      }
      data.force[h].push_back(X);
    }
  sort_by_frequency_and_heading(file, parameters + "w", data);
  return data;
}

hydro::Matrix6 read_bemio_hydrostatic_stiffness(const std::string& path, const CaseFluid& fluid) {
  const BemioFile bemio(path, fluid);
  const std::string stiffness = coefficients + "linear_restoring_stiffness";
  return bemio.block(bemio.oriented(stiffness, {6, 6}, "(6, 6)"), stiffness, std::nullopt, bemio.excitation_factor,
                     "");
}

}  // namespace heavesim::bem
