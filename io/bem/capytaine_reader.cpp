#include "io/bem/capytaine_reader.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include <fmt/format.h>

namespace heavesim::bem {
namespace {

constexpr std::array<const char*, 6> dof_names = {"Surge", "Sway", "Heave", "Roll", "Pitch", "Yaw"};

std::string quoted_list(const std::vector<std::string>& names) {
  std::string text;
  for (const std::string& name : names) text += (text.empty() ? "'" : ", '") + name + "'";
  return "(" + text + ")";
}

class CapytaineFile {
 public:
  explicit CapytaineFile(const std::string& path) : file(path, "a Capytaine NetCDF4 file (HDF5-based; netCDF3 classic files are not read)") {}

  /// The variable `name` read through the axes `dimensions` (dimension names, in that
  /// logical order), each axis's length checked against its coordinate's.
  AxisArray variable(const std::string& name, const std::vector<std::string>& dimensions) const {
    const std::string path = "/" + name;
    const std::vector<std::string> stored = file.dimension_names(path);
    hdf5::Array array = file.read(path);
    std::vector<int> axes;
    for (const std::string& dimension : dimensions) {
      const auto it = std::find(stored.begin(), stored.end(), dimension);
      if (it != stored.end()) axes.push_back(static_cast<int>(it - stored.begin()));
    }
    if (stored.size() != dimensions.size() || axes.size() != dimensions.size())
      file.fail(path, "dimensions " + quoted_list(stored), "the dimensions " + quoted_list(dimensions) + " in any order");
    for (std::size_t axis = 0; axis < stored.size(); ++axis) {
      if (file.shape("/" + stored[axis]) != std::vector<hsize_t>{array.shape[axis]}) {
        std::vector<hsize_t> lengths;
        for (const std::string& dimension : stored) {
          const std::vector<hsize_t> shape = file.shape("/" + dimension);
          lengths.push_back(shape.empty() ? 1 : shape[0]);
        }
        file.fail(path, fmt::format("shape {} with dimensions {}", hdf5::shape_text(array.shape), quoted_list(stored)),
                  fmt::format("shape {}, the lengths of those dimensions' coordinates", hdf5::shape_text(lengths)));
      }
    }
    return AxisArray(std::move(array), axes);
  }

  /// omega [rad/s], entries 0 <= omega <= inf.
  std::vector<double> frequencies() const {
    file.check_units("/omega", {"rad/s"});
    const std::vector<double> omega = file.read("/omega").values;
    for (std::size_t k = 0; k < omega.size(); ++k)
      if (!(omega[k] >= 0.0))
        file.fail("/omega", fmt::format("omega = {} rad/s (entry {})", omega[k], k + 1), "frequencies 0 <= omega <= inf");
    return omega;
  }

  /// The WAMIT mode (0-based) of each entry of a dof coordinate.
  std::vector<int> modes(const std::string& dimension) const {
    const std::string path = "/" + dimension;
    const std::vector<std::string> names = file.read_strings(path);
    std::vector<int> modes;
    for (std::size_t k = 0; k < names.size(); ++k) {
      const auto it = std::find(dof_names.begin(), dof_names.end(), names[k]);
      if (it == dof_names.end())
        file.fail(path, fmt::format("the dof '{}' (entry {})", names[k], k + 1),
                  "rigid-body dofs of one body: Surge, Sway, Heave, Roll, Pitch, Yaw (modes 1-6)");
      const int mode = static_cast<int>(it - dof_names.begin());
      if (std::find(modes.begin(), modes.end(), mode) != modes.end())
        file.fail(path, fmt::format("the dof '{}' twice", names[k]), "each dof once");
      modes.push_back(mode);
    }
    return modes;
  }

  /// The positive scalar variable `name` (rho, g).
  double positive(const std::string& name) const {
    const double value = file.read_scalar("/" + name);
    if (!(value > 0.0 && std::isfinite(value)))
      file.fail("/" + name, fmt::format("{} = {}", name, value), "a positive number");
    return value;
  }

  /// M(i, j) = factor value(a, b) for influenced dof a (mode influenced[a]) and radiating
  /// dof b (mode radiating[b]), every value finite; `at` names the other indices for errors.
  template <class Value>
  hydro::Matrix6 dof_matrix(const std::vector<int>& influenced, const std::vector<int>& radiating,
                            const std::string& variable, double factor, const std::string& at, Value value) const {
    hydro::Matrix6 M = hydro::Matrix6::Zero();
    for (std::size_t a = 0; a < influenced.size(); ++a)
      for (std::size_t b = 0; b < radiating.size(); ++b) {
        M(influenced[a], radiating[b]) =
            dimensional(file, variable, value(a, b), factor,
                        fmt::format("the entry {}influenced_dof = {}, radiating_dof = {}", at,
                                    dof_names[influenced[a]], dof_names[radiating[b]]));
      }
    return M;
  }

  hdf5::Reader file;
};

}  // namespace

hydro::RadiationData read_capytaine_radiation(const std::string& path, const CaseFluid& fluid) {
  CapytaineFile capytaine(path);
  const hdf5::Reader& file = capytaine.file;
  const std::vector<std::string> dimensions = {"omega", "influenced_dof", "radiating_dof"};
  const AxisArray A = capytaine.variable("added_mass", dimensions);
  const AxisArray B = capytaine.variable("radiation_damping", dimensions);
  const std::vector<double> omega = capytaine.frequencies();
  const std::vector<int> influenced = capytaine.modes("influenced_dof"), radiating = capytaine.modes("radiating_dof");
  const double factor = fluid.density / capytaine.positive("rho");
  auto matrix = [&](const AxisArray& array, const std::string& variable, std::size_t k) {
    return capytaine.dof_matrix(influenced, radiating, variable, factor, fmt::format("omega = {:g}, ", omega[k]),
                                [&](std::size_t a, std::size_t b) { return array.at({k, a, b}); });
  };
  hydro::RadiationData data;
  bool has_infinite = false;
  for (std::size_t k = 0; k < omega.size(); ++k) {
    hydro::Matrix6 added_mass = matrix(A, "/added_mass", k);
    symmetrise_checked(file, "/added_mass", added_mass, "A",
                       fmt::format("at omega = {:g} rad/s (entry {} of {})", omega[k], k + 1, omega.size()));
    if (std::isinf(omega[k])) {
      data.added_mass_infinite = added_mass;
      has_infinite = true;
    } else if (omega[k] == 0.0) {
      data.added_mass_zero = added_mass;
      data.has_added_mass_zero = true;
    } else {
      // B is symmetrised unchecked, as for WAMIT files.
      const hydro::Matrix6 damping = matrix(B, "/radiation_damping", k);
      data.angular_frequencies.push_back(omega[k]);
      data.added_mass.push_back(added_mass);
      data.damping.push_back(symmetric_part(damping));
    }
  }
  if (!has_infinite)
    file.fail("/omega",
              fmt::format("no omega = inf entry (omega from {:g} to {:g} rad/s)",
                          *std::min_element(omega.begin(), omega.end()), *std::max_element(omega.begin(), omega.end())),
              "an omega = inf entry: the time-domain model needs the infinite-frequency added mass A(inf) (solve "
              "the radiation problems at omega = inf too)");
  sort_by_frequency(file, "/omega", data);
  return data;
}

hydro::ExcitationData read_capytaine_excitation(const std::string& path, const CaseFluid& fluid) {
  const CapytaineFile capytaine(path);
  const hdf5::Reader& file = capytaine.file;
  const std::vector<std::string> dimensions = {"omega", "wave_direction", "influenced_dof", "complex"};
  const AxisArray diffraction = capytaine.variable("diffraction_force", dimensions);
  const AxisArray froude_krylov = capytaine.variable("Froude_Krylov_force", dimensions);
  const std::vector<double> omega = capytaine.frequencies();
  const std::vector<int> influenced = capytaine.modes("influenced_dof");
  file.check_units("/wave_direction", {"rad"});
  const std::vector<double> headings = file.read("/wave_direction").values;
  const std::vector<std::string> parts = file.read_strings("/complex");
  const auto re = std::find(parts.begin(), parts.end(), "re"), im = std::find(parts.begin(), parts.end(), "im");
  if (parts.size() != 2 || re == parts.end() || im == parts.end())
    file.fail("/complex", "the labels " + quoted_list(parts), "the labels ('re', 'im')");
  const std::size_t real = re - parts.begin(), imaginary = im - parts.begin();
  const double factor = fluid.density * fluid.gravity / (capytaine.positive("rho") * capytaine.positive("g"));
  hydro::ExcitationData data;
  data.force.assign(headings.size(), {});
  for (std::size_t h = 0; h < headings.size(); ++h) {
    check_finite(file, "/wave_direction", headings[h], fmt::format("entry {}", h + 1));
    data.headings.push_back(headings[h]);
  }
  for (std::size_t k = 0; k < omega.size(); ++k) {
    if (omega[k] == 0.0 || std::isinf(omega[k])) continue;  // no diffraction problem there
    data.angular_frequencies.push_back(omega[k]);
    for (std::size_t h = 0; h < headings.size(); ++h) {
      hydro::ComplexVector6 X = hydro::ComplexVector6::Zero();
      for (std::size_t a = 0; a < influenced.size(); ++a) {
        const std::string at = fmt::format("the entry omega = {:g}, wave_direction = {:g}, influenced_dof = {}",
                                           omega[k], headings[h], dof_names[influenced[a]]);
        std::complex<double> total;
        for (const auto& [variable, array] : {std::pair{"/diffraction_force", &diffraction},
                                              std::pair{"/Froude_Krylov_force", &froude_krylov}}) {
          const double x = array->at({k, h, a, real}), y = array->at({k, h, a, imaginary});
          check_finite(file, variable, x, at + ", re");
          check_finite(file, variable, y, at + ", im");
          total += std::complex<double>(x, y);
        }
        // Capytaine's e^{-i w t} to WAMIT's e^{+i w t}: the complex conjugate. The sum of
        // the two forces, then its scaling, may each overflow.
        const std::string sum = "/diffraction_force + /Froude_Krylov_force";
        X[influenced[a]] = {dimensional(file, sum, total.real(), factor, at + ", re of the sum"),
                            dimensional(file, sum, -total.imag(), factor, at + ", im of the sum")};
      }
      data.force[h].push_back(X);
    }
  }
  sort_by_frequency_and_heading(file, "/omega", data);
  return data;
}

hydro::Matrix6 read_capytaine_hydrostatic_stiffness(const std::string& path, const CaseFluid& fluid) {
  CapytaineFile capytaine(path);
  const AxisArray stiffness = capytaine.variable("hydrostatic_stiffness", {"influenced_dof", "radiating_dof"});
  const std::vector<int> influenced = capytaine.modes("influenced_dof"), radiating = capytaine.modes("radiating_dof");
  const double factor = fluid.density * fluid.gravity / (capytaine.positive("rho") * capytaine.positive("g"));
  return capytaine.dof_matrix(influenced, radiating, "/hydrostatic_stiffness", factor, "",
                              [&](std::size_t a, std::size_t b) { return stiffness.at({a, b}); });
}

}  // namespace heavesim::bem
