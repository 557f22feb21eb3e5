#include "kernel/integrators/integrator.hpp"

#include "kernel/integrators/erk_integrator.hpp"
#include "kernel/integrators/hht_integrator.hpp"
#include "kernel/integrators/ida_integrator.hpp"
#include "kernel/integrators/rk4_integrator.hpp"

namespace heavesim {

std::unique_ptr<Integrator> make_integrator(const IntegratorSettings& settings) {
  switch (settings.method) {
    case IntegrationMethod::rk4:
      return std::make_unique<Rk4Integrator>(settings.step);
    case IntegrationMethod::dopri5:
      return std::make_unique<ErkIntegrator>(settings, ARKODE_DORMAND_PRINCE_7_4_5);
    case IntegrationMethod::verner6:
      return std::make_unique<ErkIntegrator>(settings, ARKODE_VERNER_8_5_6);
    case IntegrationMethod::fehlberg8:
      return std::make_unique<ErkIntegrator>(settings, ARKODE_FEHLBERG_13_7_8);
    case IntegrationMethod::ida:
      return std::make_unique<IdaIntegrator>(settings);
    case IntegrationMethod::hht:
      return std::make_unique<HhtIntegrator>(settings);
  }
  return nullptr;
}

std::string integration_method_name(IntegrationMethod method) {
  switch (method) {
    case IntegrationMethod::rk4: return "rk4";
    case IntegrationMethod::dopri5: return "dopri5";
    case IntegrationMethod::verner6: return "verner6";
    case IntegrationMethod::fehlberg8: return "fehlberg8";
    case IntegrationMethod::ida: return "ida";
    case IntegrationMethod::hht: return "hht";
  }
  return "?";
}

}  // namespace heavesim
