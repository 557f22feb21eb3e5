#pragma once
// Moves a model along a prescribed motion q(t), v(t) and integrates only what rides
// on it: the internal states of force elements (gas temperature, filters, pressures)
// and the work W(t) = integral of the elements' power sum_i v_i . f_i + v . tau.
// The kernel's integrators advance it like any OdeSystem. This is how validation
// drives a compensator through a stroke history without dynamics (C3), and how tests
// drive a sensor with a platform motion. The stroke models it moves are
// samples::vertical_slider and samples::base_and_load (samples/oscillators.hpp).
#include <functional>
#include <memory>
#include <vector>

#include "kernel/elements/force_element.hpp"
#include "kernel/system/ode_system.hpp"

namespace heavesim::validation {

/// Fills q (nq) and v (nv) at time t [s].
using MotionLaw = std::function<void(double t, VectorX& q, VectorX& v)>;

class PrescribedMotionSystem : public OdeSystem {
 public:
  PrescribedMotionSystem(std::shared_ptr<const Model> model, MotionLaw motion);
  void add_force_element(std::unique_ptr<ForceElement> element);

  /// y = [z_1; ...; z_k; W]: element states, then the work W [J] done by the elements.
  int size() const override { return size_ + 1; }
  void derivative(double t, const VectorX& y, VectorX& ydot) override;
  VectorX initial_state() const;

  /// Places the model at time t (stages in data()); element e's states are y.segment(state_offset(e), n).
  void place(double t);
  const Data& data() const { return data_; }
  const Model& model() const { return *model_; }
  int state_offset(std::size_t element) const { return offsets_[element]; }
  const ForceElement& element(std::size_t e) const { return *elements_[e]; }

 private:
  std::shared_ptr<const Model> model_;
  MotionLaw motion_;
  Data data_;
  AppliedForces forces_;
  VectorX q_, v_;
  std::vector<std::unique_ptr<ForceElement>> elements_;
  std::vector<int> offsets_;
  int size_ = 0;
};

}  // namespace heavesim::validation
