#pragma once
// Starting one of the kernel's integrators on a system, for the control tests.
#include <memory>

#include "kernel/integrators/integrator.hpp"

namespace heavesim::testing {

/// System: a MultibodySystem or a plain OdeSystem (make_integrator picks the form).
template <class System>
std::unique_ptr<Integrator> start_integrator(System& system, const VectorX& y0, IntegrationMethod method,
                                                    double relative_tolerance, double absolute_tolerance) {
  IntegratorSettings settings;
  settings.method = method;
  settings.relative_tolerance = relative_tolerance;
  settings.absolute_tolerance = absolute_tolerance;
  std::unique_ptr<Integrator> integrator = make_integrator(settings, system);
  integrator->initialize(0.0, y0);
  return integrator;
}

}  // namespace heavesim::testing
