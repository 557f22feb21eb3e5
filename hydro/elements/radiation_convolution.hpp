#pragma once
// Radiation memory of one body as a direct convolution (Cummins 1962),
//   F(t) = -int_0^{T_K} K(s) v(t - s) ds   (WAMIT order, world axes),
// with the body velocity kept in a ring buffer sampled every kernel step dt: the first
// evaluation at or after each sample time t_n = n dt stores the velocity it sees (as
// WEC-Sim's fixed-rate memory does). With an explicit fixed-step integrator whose step
// divides dt that is the velocity of the accepted step at t_n; with adaptive or
// implicit integrators a stored sample can come from a trial stage -- use the
// state-space RadiationMemory there. The newest, partial interval uses the current
// velocity; older ones the trapezoidal rule on the stored samples. The buffer is
// sized in the constructor; apply() does not allocate. The body starts from rest
// (older samples are zero); an evaluation back at t <= 0 after a run starts afresh.
// Not thread-safe (the buffer is mutable state of a const apply()); its load depends on the
// evaluations before (ElementDependencies::history, the default it keeps).
#include "hydro/elements/body_motion.hpp"
#include "hydro/radiation/retardation_kernel.hpp"

namespace heavesim::hydro {

class RadiationConvolution : public ForceElement {
 public:
  RadiationConvolution(std::string name, int link, RetardationKernel kernel);
  const std::string& name() const override { return name_; }
  void apply(double t, const Model& model, const Data& data, Eigen::Ref<const VectorX> z,
             AppliedForces& forces) const override;

 private:
  std::string name_;
  int link_;
  RetardationKernel kernel_;
  mutable std::vector<Vector6> history_;  // ring buffer: sample n at index n % size
  mutable long newest_sample_ = -1;       // index n of the newest stored sample
};

}  // namespace heavesim::hydro
