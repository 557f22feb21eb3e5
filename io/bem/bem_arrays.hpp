#pragma once
// What the HDF5-based BEM readers (BEMIO, Capytaine) share: the case's fluid, arrays
// read through named axes whatever order the file stores them in, and the checks on
// the coefficients (finite values, symmetric added mass, ascending frequencies).
#include <initializer_list>
#include <string>
#include <vector>

#include "io/bem/wamit_reader.hpp"  // bem_symmetry_tolerance, symmetric_part
#include "io/hdf5/hdf5_reader.hpp"
#include "hydro/bem/bem_data.hpp"

namespace heavesim::bem {

/// The case's water and gravity, which dimensionalise the coefficients (as for WAMIT).
struct CaseFluid {
  double density = 1025.0;  // rho [kg/m^3]
  double gravity = 9.81;    // g [m/s^2]
};

/// A stored array indexed in a logical axis order: at({i, j, k}) with the indices in
/// the order of `logical_to_stored` (logical axis a is stored axis logical_to_stored[a]).
class AxisArray {
 public:
  AxisArray(hdf5::Array array, const std::vector<int>& logical_to_stored);
  double at(std::initializer_list<std::size_t> logical_index) const;

 private:
  hdf5::Array array_;
  std::vector<std::size_t> strides_;  // per logical axis
};

/// Fails with the dataset named unless `value` is finite; `what` says which entry.
void check_finite(const hdf5::Reader& file, const std::string& dataset, double value, const std::string& what);

/// `factor * stored`: a stored value made dimensional for the case's fluid (or converted,
/// deg to rad). Fails with the dataset named unless both are finite: a stored value near
/// the largest double times rho g overflows to inf, which no later check would catch.
double dimensional(const hdf5::Reader& file, const std::string& dataset, double stored, double factor,
                   const std::string& what);

/// Checks |M_ij - M_ji| <= tol sqrt(|M_ii M_jj|) (tol = bem::bem_symmetry_tolerance, as
/// for WAMIT files) and symmetrises M; `at` says where (e.g. "at w = 0.5 rad/s").
void symmetrise_checked(const hdf5::Reader& file, const std::string& dataset, hydro::Matrix6& M, const char* what,
                        const std::string& at);

/// Orders the finite-frequency entries by ascending frequency and fails (naming
/// `dataset`) when there is none (only w = 0 or w = inf entries) or a frequency repeats.
void sort_by_frequency(const hdf5::Reader& file, const std::string& dataset, hydro::RadiationData& data);
void sort_by_frequency_and_heading(const hdf5::Reader& file, const std::string& dataset, hydro::ExcitationData& data);

}  // namespace heavesim::bem
