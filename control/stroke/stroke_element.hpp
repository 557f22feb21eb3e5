#pragma once
// What every compensator element shares: a name, a stroke axis, a table of output
// channels, and one function that evaluates everything at a state -- the force along
// the stroke, the signals, and (when asked) the rates of the internal states. apply(),
// state_derivative() and outputs() are that one evaluation seen three ways, so they
// can never disagree; they share it (evaluated()): a residual's apply() and
// state_derivative(), and a recorded sample's outputs and summary, evaluate once.
#include "control/element_channels.hpp"
#include "control/stroke/stroke_axis.hpp"
#include "kernel/elements/evaluation_key.hpp"

namespace heavesim {

/// State: the element's evaluation, with at least `double force` [N] along the stroke;
/// Parameters: its immutable parameters.
template <class State, class Parameters>
class StrokeElement : public ForceElement {
 public:
  const std::string& name() const override { return name_; }
  const std::vector<ElementChannel>& channels() const override { return table_.channels(); }
  void apply(double t, const Model& model, const Data& data, Eigen::Ref<const VectorX> z,
             AppliedForces& forces) const override {
    apply_stroke_force(axis_, model, data, evaluated(t, model, data, z).force, forces);
  }
  void state_derivative(double t, const Model& model, const Data& data, Eigen::Ref<const VectorX> z,
                        Eigen::Ref<VectorX> zdot) const override {
    if (z.size() == 0) return;
    evaluated(t, model, data, z);
    zdot = last_rates_;
  }
  void outputs(double t, const Model& model, const Data& data, Eigen::Ref<const VectorX> z,
               std::span<double> values) const override {
    table_.fill(evaluated(t, model, data, z), values);
  }
  /// evaluate() with its rates, once per point: the last one is kept and handed back while
  /// the stages' evaluation, t and z are the same (kernel/elements/evaluation_key.hpp).
  /// The reference stays valid until the next call. Allocates on the first call only.
  const State& evaluated(double t, const Model& model, const Data& data, Eigen::Ref<const VectorX> z) const {
    if (!last_point_.matches(data, t, z))
      last_point_.keep(data, t, z, [&] {
        last_rates_.resize(z.size());
        last_ = evaluate(t, model, data, z, z.size() > 0 ? last_rates_.data() : nullptr);
      });
    return last_;
  }
  /// Everything but history: a compensator's evaluation is a function of (t, q, v, z) alone.
  ElementDependencies dependencies() const override { return {true, true, true, true, false}; }

  /// Everything the element computes at time t [s] for internal states z on the
  /// current stages; fills zdot (state_size() entries) when it is not null.
  virtual State evaluate(double t, const Model& model, const Data& data, Eigen::Ref<const VectorX> z,
                         double* zdot) const = 0;
  const StrokeAxis& axis() const { return axis_; }
  const Parameters& parameters() const { return parameters_; }

 protected:
  StrokeElement(std::string name, StrokeAxis axis, Parameters parameters)
      : name_(std::move(name)), axis_(axis), parameters_(std::move(parameters)) {}

  std::string name_;
  StrokeAxis axis_;
  Parameters parameters_;
  ChannelTable<State> table_;

 private:
  mutable EvaluationKey last_point_;
  mutable State last_{};
  mutable VectorX last_rates_;  // dz/dt at last_point_
};

}  // namespace heavesim
