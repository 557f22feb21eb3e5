#pragma once
// What every compensator element shares: a name, a stroke axis, a table of output
// channels, and one function that evaluates everything at a state -- the force along
// the stroke, the signals, and (when asked) the rates of the internal states. apply(),
// state_derivative() and outputs() are that one evaluation seen three ways, so they
// can never disagree.
#include "control/element_channels.hpp"
#include "control/stroke/stroke_axis.hpp"

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
    apply_stroke_force(axis_, model, data, evaluate(t, model, data, z, nullptr).force, forces);
  }
  void state_derivative(double t, const Model& model, const Data& data, Eigen::Ref<const VectorX> z,
                        Eigen::Ref<VectorX> zdot) const override {
    if (z.size() > 0) evaluate(t, model, data, z, zdot.data());
  }
  void outputs(double t, const Model& model, const Data& data, Eigen::Ref<const VectorX> z,
               std::span<double> values) const override {
    table_.fill(evaluate(t, model, data, z, nullptr), values);
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
};

}  // namespace heavesim
