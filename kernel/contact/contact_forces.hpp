#pragma once
// The contact forces of the last contact step as a force element: what the recorder
// writes (per pair its normal and friction force, point count and torsional moment, per
// stop its force, per line its tension)
// and what an evaluation of the system at an output time applies, so that joint
// accelerations and reactions there include the contact loads (the step's impulses
// divided by its length: the mean force over the step). The contact-stepping integrator
// clears them before it computes the applied forces of a step (the step's own impulses
// replace them) and sets them after.
#include "kernel/contact/contact_stepper.hpp"
#include "kernel/elements/force_element.hpp"

namespace heavesim {

class ContactForces : public ForceElement {
 public:
  ContactForces(std::string name, const Model& model, ContactModel contacts);

  const std::string& name() const override { return name_; }
  const ContactModel& contact_model() const { return contacts_; }
  void apply(double t, const Model& model, const Data& data, Eigen::Ref<const VectorX> z,
             AppliedForces& forces) const override;
  ElementDependencies dependencies() const override { return {false, false, false, false, true}; }
  const std::vector<ElementChannel>& channels() const override { return channels_; }
  void outputs(double t, const Model& model, const Data& data, Eigen::Ref<const VectorX> z,
               std::span<double> values) const override;

  /// No contact loads (before a step computes its applied forces).
  void clear();
  /// The loads of the step of length h [s] that `stepper` has just taken; adds its
  /// impulses to the running totals.
  void set_from(const ContactStepper& stepper, double h);
  /// Running totals of the impulses back to zero (the start of a run).
  void reset_impulses() { impulse_totals_.setZero(); }

  /// The joint stops as the model's JointStopConstraint rows (event-located under IDA,
  /// kernel/system/joint_stop_events.hpp): each stop's force is then read from the
  /// multipliers of its rows at output time, and its impulses come from the events.
  void bind_stop_rows(const Model& model);
  /// An impact's generalized impulse on the stop of constraint row `row` [N s or N m s,
  /// > 0 along the coordinate], added to its running total.
  void add_stop_row_impulse(int row, double impulse);

 private:
  std::string name_;
  ContactModel contacts_;
  std::vector<int> stop_velocity_index_;
  std::vector<ElementChannel> channels_;
  AlignedVector<Force> link_force_world_;  ///< per link, about the world origin [N, N m]
  VectorX joint_force_;                     ///< nv: the stops' generalized forces [N or N m]
  VectorX channel_values_;                  ///< per pair: normal [N], friction [N], points; per stop: force
  std::vector<Vector3> friction_sum_;       ///< per pair, world [N]
  VectorX impulse_totals_;                  ///< per pair its normal impulse, per stop its impulse, since the start [N s]
  std::vector<int> impulse_channel_;        ///< the channel of each running total
  std::vector<int> pair_channel_;           ///< per pair: its first channel (normal, friction, points[, torsion])
  int first_stop_channel_ = 0;              ///< the first stop's force channel (lines' tensions follow the stops)
  /// Per stop, its constraint rows and their sides (bind_stop_rows; empty: stepped stops).
  std::vector<std::vector<std::pair<int, double>>> stop_rows_;
};

}  // namespace heavesim
