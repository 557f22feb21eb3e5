#include "kernel/elements/spring_damper.hpp"

#include "kernel/math/numerical_error.hpp"

namespace heavesim {

SpringDamper::State SpringDamper::state(const Data& data) const {
  return state_at(a_.position_world(data), b_.position_world(data), data);
}

SpringDamper::State SpringDamper::state_at(const Vector3& pa, const Vector3& pb, const Data& data) const {
  const Vector3 d = pb - pa;
  const double length = d.norm();
  const double rate = length > 0.0 ? d.dot(b_.velocity_world(data) - a_.velocity_world(data)) / length : 0.0;
  return {length, rate, parameters_.stiffness * (length - parameters_.rest_length) + parameters_.damping * rate};
}

double SpringDamper::potential_energy(const Model&, const Data& data, Eigen::Ref<const VectorX>) const {
  const double extension = (b_.position_world(data) - a_.position_world(data)).norm() - parameters_.rest_length;
  return 0.5 * parameters_.stiffness * extension * extension;
}

void SpringDamper::apply(double t, const Model&, const Data& data, Eigen::Ref<const VectorX>,
                         AppliedForces& forces) const {
  const Vector3 pa = a_.position_world(data), pb = b_.position_world(data);
  const State s = state_at(pa, pb, data);
  // Coincident ends have no line of action; a real strut cannot get there.
  if (!(s.length > 1e-12))
    throw NumericalError(t, "spring-damper '" + name_ + "': its end points coincide (no line of action)",
                         "check the attachment points and the initial state");
  const Vector3 pull_on_a = s.tension * (pb - pa) / s.length;
  forces.add_force_at_point(a_.link, pa, pull_on_a);
  forces.add_force_at_point(b_.link, pb, -pull_on_a);
}

}  // namespace heavesim
