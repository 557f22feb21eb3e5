#include "hydro/analysis/frequency_domain_rao.hpp"

#include <Eigen/LU>

namespace heavesim::hydro {

ComplexVector6 frequency_domain_rao(const BemData& bem, const RaoSettings& s, size_t n, size_t h) {
  const double w = bem.radiation.angular_frequencies.at(n);
  using ComplexMatrix6 = Eigen::Matrix<std::complex<double>, 6, 6>;
  const ComplexMatrix6 impedance =
      (-w * w * (s.mass + bem.radiation.added_mass[n]) + bem.hydrostatic_stiffness + s.external_stiffness)
          .cast<std::complex<double>>() +
      std::complex<double>(0.0, w) * (bem.radiation.damping[n] + s.external_damping).cast<std::complex<double>>();
  return impedance.partialPivLu().solve(bem.excitation.force.at(h).at(n));
}

}  // namespace heavesim::hydro
