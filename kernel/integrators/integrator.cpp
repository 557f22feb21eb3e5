#include "kernel/integrators/integrator.hpp"

#include <stdexcept>

#include "kernel/parameter_error.hpp"

#include "kernel/integrators/contact_stepping_integrator.hpp"
#include "kernel/integrators/erk_integrator.hpp"
#include "kernel/integrators/hht_integrator.hpp"
#include "kernel/integrators/ida_integrator.hpp"
#include "kernel/integrators/rk4_integrator.hpp"
#include "kernel/system/ggl_dae_form.hpp"
#include "kernel/system/index3_form.hpp"
#include "kernel/system/ode_form.hpp"

namespace heavesim {
namespace {

/// An integrator together with the form (or residual wrapper) it integrates, which it
/// owns. Only initialize and advance_to pass through here, once per output interval.
template <class Form>
class OwningIntegrator final : public Integrator {
 public:
  template <class Build>
  OwningIntegrator(std::unique_ptr<Form> form, Build build) : form_(std::move(form)), integrator_(build(*form_)) {}
  void initialize(double t0, const VectorX& y0) override { integrator_->initialize(t0, y0); }
  void advance_to(double t_out) override { integrator_->advance_to(t_out); }
  const VectorX& state() const override { return integrator_->state(); }
  double time() const override { return integrator_->time(); }
  IntegratorStatistics statistics() const override { return integrator_->statistics(); }
  NumericalError explain(const NumericalError& error) const override { return integrator_->explain(error); }

 private:
  std::unique_ptr<Form> form_;  // declared first: destroyed after the integrator that uses it
  std::unique_ptr<Integrator> integrator_;
};

template <class Form, class Build>
std::unique_ptr<Integrator> owning(std::unique_ptr<Form> form, Build build) {
  return std::make_unique<OwningIntegrator<Form>>(std::move(form), build);
}

/// The explicit methods on any OdeSystem.
std::unique_ptr<Integrator> make_explicit(const IntegratorSettings& settings, OdeSystem& system) {
  switch (settings.method) {
    case IntegrationMethod::rk4: return std::make_unique<Rk4Integrator>(system, settings.step);
    case IntegrationMethod::dopri5: return std::make_unique<ErkIntegrator>(system, settings, ARKODE_DORMAND_PRINCE_7_4_5);
    case IntegrationMethod::verner6: return std::make_unique<ErkIntegrator>(system, settings, ARKODE_VERNER_8_5_6);
    case IntegrationMethod::fehlberg8: return std::make_unique<ErkIntegrator>(system, settings, ARKODE_FEHLBERG_13_7_8);
    case IntegrationMethod::ida:
    case IntegrationMethod::hht:
    case IntegrationMethod::contact: break;
  }
  throw std::logic_error("make_explicit: " + integration_method_name(settings.method) + " is not an explicit method");
}

}  // namespace

std::unique_ptr<Integrator> make_integrator(const IntegratorSettings& settings, MultibodySystem& system) {
  switch (settings.method) {
    case IntegrationMethod::ida:
      return owning(std::make_unique<GglDaeForm>(system),
                    [&](GglDaeForm& form) { return std::make_unique<IdaIntegrator>(form, settings); });
    case IntegrationMethod::hht:
      return owning(std::make_unique<Index3Form>(system),
                    [&](Index3Form& form) { return std::make_unique<HhtIntegrator>(form, settings); });
    case IntegrationMethod::contact: return std::make_unique<ContactSteppingIntegrator>(system, settings.step);
    default:
      return owning(std::make_unique<OdeForm>(system),
                    [&](OdeForm& form) { return make_explicit(settings, form); });
  }
}

std::unique_ptr<Integrator> make_integrator(const IntegratorSettings& settings, OdeSystem& system) {
  switch (settings.method) {
    case IntegrationMethod::ida:
      return owning(std::make_unique<OdeResidual>(system),
                    [&](OdeResidual& residual) { return std::make_unique<IdaIntegrator>(residual, settings); });
    case IntegrationMethod::hht:
      throw ParameterError("integrator", "'hht' for a first-order system without a second-order form",
                           "rk4, dopri5, verner6, fehlberg8 or ida (HHT integrates mechanical systems only)");
    case IntegrationMethod::contact:
      throw ParameterError("integrator", "'contact' for a first-order system", "rk4, dopri5, verner6, fehlberg8 or ida");
    default:
      return make_explicit(settings, system);
  }
}

std::string integration_method_name(IntegrationMethod method) {
  switch (method) {
    case IntegrationMethod::rk4: return "rk4";
    case IntegrationMethod::dopri5: return "dopri5";
    case IntegrationMethod::verner6: return "verner6";
    case IntegrationMethod::fehlberg8: return "fehlberg8";
    case IntegrationMethod::ida: return "ida";
    case IntegrationMethod::hht: return "hht";
    case IntegrationMethod::contact: return "contact";
  }
  return "?";
}

}  // namespace heavesim
