#include "kernel/integrators/contact_stepping_integrator.hpp"

#include <cmath>
#include <sstream>

#include "kernel/algorithms/configuration.hpp"
#include "kernel/parameter_error.hpp"

namespace heavesim {

namespace {

const ContactModel& contact_model_of(const MultibodySystem& system) {
  static const ContactModel none;
  return system.contacts() ? system.contacts()->contact_model() : none;
}

}  // namespace

ContactSteppingIntegrator::ContactSteppingIntegrator(MultibodySystem& system, double step)
    : system_(system),
      step_(step),
      stepper_(system.model(), contact_model_of(system), max_contact_points(contact_model_of(system))),
      forces_(system.model()),
      q_(system.model().nq),
      v_(system.model().nv),
      zdot_(system.element_state_size()) {
  if (!(step > 0.0 && std::isfinite(step))) throw ParameterError("step", std::to_string(step), "a finite step > 0 s");
}

void ContactSteppingIntegrator::initialize(double t0, const VectorX& y0) {
  // One step taken and undone: the contact loads at the start (what the recorder writes
  // at t0 and an evaluation there applies) are those of the first step, not zero.
  t_ = grid_start_ = t0;
  grid_steps_ = 0;
  y_ = y0;
  if (system_.contacts()) {
    take_step(step_);
    t_ = t0;
    y_ = y0;
    statistics_ = {};
    system_.contacts()->reset_impulses();
  }
}

void ContactSteppingIntegrator::advance_to(double t_out) {
  // Whole steps on the grid t_grid + k h (the time counted, not summed: no drift), then
  // what is left to t_out as one step -- unless it is below 1e-6 h. A step of a few
  // picoseconds, left over by round-off when an output falls on the grid, divides the
  // gaps' and the drivers' round-off by h (b = gap / h, Phi / h): it threw a rotating drill
  // string off its bit at 1e16 N.
  const double tiny = 1e-6 * step_;
  while (t_out - t_ > tiny) {
    const double remaining = t_out - t_;
    if (remaining < step_ * (1.0 + 1e-6)) {
      take_step(remaining);
      grid_start_ = t_ = t_out;
      grid_steps_ = 0;
      break;
    }
    take_step(step_);
    t_ = grid_start_ + static_cast<double>(++grid_steps_) * step_;
  }
  t_ = t_out;
}

void ContactSteppingIntegrator::take_step(double h) {
  const Model& model = system_.model();
  Data& data = system_.mutable_data();
  q_ = y_.head(model.nq);
  v_ = y_.segment(model.nq, model.nv);
  // The applied forces and the element states' rates at the step's start, without the
  // last step's contact loads (this step's impulses take their place).
  if (system_.contacts()) system_.contacts()->clear();
  update_positions(model, data, q_);
  update_velocities(model, data, q_, v_);
  system_.applied_forces_at(t_, data, q_, v_, y_, forces_);
  if (zdot_.size() > 0) system_.element_state_derivatives(t_, y_, data, zdot_);
  const ContactStepReport report =
      stepper_.step(data, t_, h, q_, v_, forces_.joint_force, forces_.external_force_world);
  if (!report.ok()) {
    std::ostringstream what;
    what << "the contact step from t = " << t_ << " s (h = " << h << " s) found no impulses on its " << report.rows
         << " rows (" << report.contacts << " contact points";
    for (const ContactPoint& c : stepper_.contacts())
      what << (&c == stepper_.contacts().data() ? ": " : ", ") << "'" << contact_model_of(system_).pairs[c.pair].name
           << "' gap " << c.gap << " m";
    what << "; " << report.active_stops << " stops, " << report.constraint_rows << " constraint rows): "
         << (report.solve.message.empty() ? std::string(to_string(report.solve.status)) : report.solve.message);
    throw NumericalError(t_, what.str(),
                         "check that no prescribed motion (a driver) pushes a body into another that cannot give "
                         "way; else a smaller solver.step, or a larger contacts.margin if points come in "
                         "overlapping");
  }
  if (system_.contacts()) system_.contacts()->set_from(stepper_, h);
  y_.head(model.nq) = q_;
  y_.segment(model.nq, model.nv) = v_;
  if (zdot_.size() > 0) y_.tail(zdot_.size()) += h * zdot_;
  if (!y_.allFinite()) system_.report_non_finite(t_ + h, v_, "the velocity after a contact step");
  ++statistics_.steps;
  statistics_.rhs_evaluations += 1;
  statistics_.last_step = h;
}

}  // namespace heavesim
