#pragma once
// A force element wrapper that records the load of the element it wraps on one body:
// force [N] and moment [N m] about the body reference point (body frame origin), world
// axes, appended to the wrapped element's own channels; optionally the incident wave
// elevation [m] at the reference point. Depends on the kernel and hydro/waves only.
#include <memory>
#include <stdexcept>
#include <string>

#include "hydro/waves/wave_train.hpp"
#include "kernel/elements/evaluation_key.hpp"
#include "kernel/elements/force_element.hpp"

namespace heavesim {

/// Records the load an element puts on its body, and passes everything else through.
/// apply() keeps the wrapped element's own load on the body, and outputs() reads it back
/// for the same evaluation (kernel/elements/evaluation_key.hpp); asked at another point,
/// outputs() applies the element again into a scratch AppliedForces sized at
/// construction. No allocation after the first call (not thread-safe: mutable state).
class RecordedLoad : public ForceElement {
 public:
  RecordedLoad(std::unique_ptr<ForceElement> element, const Model& model, int link,
               std::shared_ptr<const hydro::WaveTrain> waves)
      : element_(std::move(element)), link_(link), waves_(std::move(waves)), scratch_(model) {
    channels_ = element_->channels();
    own_ = static_cast<int>(channels_.size());
    for (const std::string axis : {"x", "y", "z"})
      channels_.push_back({"force_" + axis, "N", "force of this element on the body, world " + axis});
    for (const std::string axis : {"x", "y", "z"})
      channels_.push_back({"moment_" + axis, "N m",
                           "moment of this element about the body reference point (body frame origin), world " + axis});
    if (waves_)
      channels_.push_back({"wave_elevation_at_body", "m",
                           "incident wave elevation at the body reference point's instantaneous (x, y), positive up"});
  }
  const std::string& name() const override { return element_->name(); }
  int state_size() const override { return element_->state_size(); }
  void initial_state(Eigen::Ref<VectorX> z) const override { element_->initial_state(z); }
  void apply(double t, const Model& model, const Data& data, Eigen::Ref<const VectorX> z,
             AppliedForces& forces) const override {
    // The element adds its load to a zero on the body, then that goes onto what was there:
    // the same sum, bit for bit, for an element that adds one load to the body.
    Force& on_body = forces.external_force_world[link_];
    const Force before = on_body;
    on_body = Force::Zero();
    applied_point_.keep(data, t, z, [&] {
      try {
        element_->apply(t, model, data, z, forces);
      } catch (...) {
        on_body = before;  // the loads before this element stand
        throw;
      }
      applied_ = on_body;
    });
    on_body = before + applied_;
  }
  void state_derivative(double t, const Model& model, const Data& data, Eigen::Ref<const VectorX> z,
                        Eigen::Ref<VectorX> zdot) const override {
    element_->state_derivative(t, model, data, z, zdot);
  }
  ElementDependencies dependencies() const override { return element_->dependencies(); }
  double potential_energy(const Model& model, const Data& data, Eigen::Ref<const VectorX> z) const override {
    return element_->potential_energy(model, data, z);
  }
  const std::vector<ElementChannel>& channels() const override { return channels_; }
  void outputs(double t, const Model& model, const Data& data, Eigen::Ref<const VectorX> z,
               std::span<double> values) const override {
    // The wrapped element reads the position and velocity stages, which must be those of t.
    if ((data.stages.current & (StageMarker::positions | StageMarker::velocities)) !=
            (StageMarker::positions | StageMarker::velocities) ||
        data.stages.time != t)
      throw std::logic_error("recorded load '" + name() + "': the position and velocity stages are not those of t");
    if (own_ > 0) element_->outputs(t, model, data, z, values.first(static_cast<std::size_t>(own_)));
    const bool applied_here = applied_point_.matches(data, t, z);
    if (!applied_here) {
      scratch_.clear();
      element_->apply(t, model, data, z, scratch_);
    }
    const Force& f = applied_here ? applied_ : scratch_.external_force_world[link_];
    // The kernel's spatial force is about the world origin: M_ref = M_0 - p x F.
    const Vector3 p = (data.X_world_link[link_] * model.links[link_].X_link_body).translation();
    const Vector3 force = f.linear(), moment = f.angular() - p.cross(force);
    for (int i = 0; i < 3; ++i) values[own_ + i] = force[i], values[own_ + 3 + i] = moment[i];
    if (waves_) values[own_ + 6] = waves_->elevation(t, p.x(), p.y());
  }

 private:
  std::unique_ptr<ForceElement> element_;
  int link_;
  std::shared_ptr<const hydro::WaveTrain> waves_;  // the scene's sea, shared by its elements
  mutable AppliedForces scratch_;
  mutable EvaluationKey applied_point_;  // where apply() last ran
  mutable Force applied_ = Force::Zero();  // the element's own load on the body there, about the world origin
  std::vector<ElementChannel> channels_;
  int own_ = 0;
};

}  // namespace heavesim
