#include "app/output/recorder.hpp"

#include <algorithm>
#include <cmath>
#include <span>
#include <stdexcept>
#include <typeinfo>
#include <utility>

#include <fmt/format.h>

#include "kernel/algorithms/energy.hpp"
#include "kernel/algorithms/joint_forces.hpp"
#include "kernel/algorithms/joint_reactions.hpp"
#include "kernel/algorithms/constraint_equations.hpp"
#include "kernel/integrators/integrator.hpp"
#include "kernel/math/two_thread_loop.hpp"
#include "signal/statistic_fields.hpp"

namespace heavesim {
namespace {

std::string coordinate_units(const JointType& type) {
  return std::visit(
      [](const auto& joint) -> std::string {
        using J = std::decay_t<decltype(joint)>;
        if constexpr (std::is_same_v<J, PrismaticJoint>) return "m";
        if constexpr (std::is_same_v<J, CylindricalJoint>) return "rad, m";
        if constexpr (std::is_same_v<J, SphericalJoint>) return "- (quaternion w, x, y, z)";
        if constexpr (std::is_same_v<J, FreeJoint>) return "m, - (x, y, z, quaternion w, x, y, z)";
        return "rad";
      },
      type);
}

/// Units of joint speeds; `per` = "/s" gives accelerations.
std::string speed_units(const JointType& type, const std::string& per) {
  return std::visit(
      [&per](const auto& joint) -> std::string {
        using J = std::decay_t<decltype(joint)>;
        if constexpr (std::is_same_v<J, PrismaticJoint>) return "m/s" + per;
        if constexpr (std::is_same_v<J, CylindricalJoint>) return "rad/s" + per + ", m/s" + per;
        if constexpr (std::is_same_v<J, FreeJoint>) return "rad/s" + per + ", m/s" + per;
        return "rad/s" + per;
      },
      type);
}

/// The unit of each coordinate of a joint, in order (CSV headers; the `units` attribute
/// above describes the same in words).
std::vector<std::string> coordinate_column_units(const JointType& type, int coordinates) {
  return std::visit(
      [coordinates](const auto& joint) -> std::vector<std::string> {
        using J = std::decay_t<decltype(joint)>;
        if constexpr (std::is_same_v<J, PrismaticJoint>) return {"m"};
        if constexpr (std::is_same_v<J, CylindricalJoint>) return {"rad", "m"};
        if constexpr (std::is_same_v<J, SphericalJoint>) return {"-", "-", "-", "-"};
        if constexpr (std::is_same_v<J, FreeJoint>) return {"m", "m", "m", "-", "-", "-", "-"};
        return std::vector<std::string>(coordinates, "rad");
      },
      type);
}

/// The unit of each joint speed, in order; `per` = "/s" gives accelerations.
std::vector<std::string> speed_column_units(const JointType& type, int speeds, const std::string& per) {
  return std::visit(
      [speeds, &per](const auto& joint) -> std::vector<std::string> {
        using J = std::decay_t<decltype(joint)>;
        if constexpr (std::is_same_v<J, PrismaticJoint>) return {"m/s" + per};
        if constexpr (std::is_same_v<J, CylindricalJoint>) return {"rad/s" + per, "m/s" + per};
        if constexpr (std::is_same_v<J, FreeJoint>)
          return {"rad/s" + per, "rad/s" + per, "rad/s" + per, "m/s" + per, "m/s" + per, "m/s" + per};
        return std::vector<std::string>(speeds, "rad/s" + per);
      },
      type);
}

/// The unit of a constraint row's multiplier: a force for rows that hold a distance, a
/// moment for rows that hold an angle.
std::string multiplier_unit(ConstraintRowKind kind) {
  switch (kind) {
    case ConstraintRowKind::along:
    case ConstraintRowKind::distance:
    case ConstraintRowKind::length:
      return "N";
    case ConstraintRowKind::perpendicular:
    case ConstraintRowKind::angle:
      return "N m";
    default:
      return "N or N m";
  }
}

}  // namespace

Recorder::Recorder(const CaseDefinition& definition, Scene& scene, ResultFile& file, CsvWriter* csv,
                   const std::vector<ExtraChannel>& extra_channels)
    : scene_(scene),
      file_(file),
      csv_(csv),
      compensators_(*scene.system, scene.summarised, definition.output.evaluate_after) {
  response_options_.time_step = definition.output.interval;
  const double window = definition.solver.t_end - std::max(definition.solver.t_start, evaluate_after());
  window_samples_ = std::max<std::int64_t>(0, std::llround(window / definition.output.interval) + 1);
  define_channels(definition);
  has_extra_channels_ = !extra_channels.empty();
  for (const ExtraChannel& extra : extra_channels)
    add({extra.path, 0, extra.units, extra.description, {},
         [value = extra.value](SampleContext&, double, double* out) { out[0] = value(); }});
  own_ = make_context(*scene_.system);
  measured_.assign(compensators_.measured_values(), 0.0);
  if (csv_) csv_row_.assign(row_width_, 0.0);
  // HDF5 lists groups alphabetically; keep the model's (topological) order too.
  const Model& model = *scene_.model;
  std::string bodies, joints;
  for (int i = 1; i < model.num_links(); ++i) {
    bodies += (i > 1 ? "," : "") + model.links[i].name;
    joints += (i > 1 ? "," : "") + model.joints[i].name;
  }
  if (definition.output.bodies) group_orders_.emplace_back("/bodies", bodies);
  if (definition.output.joints || definition.output.reactions) group_orders_.emplace_back("/joints", joints);
  if (csv_) {
    std::vector<std::string> header;
    // "joints/hook/q [m]": the units of the HDF5 attribute, per column.
    for (const Channel& channel : channels_)
      for (std::size_t c = 0; c < channel.labels.size(); ++c)
        header.push_back(channel.path.substr(1) + channel.labels[c] + " [" + channel.column_units[c] + "]");
    csv_->write_header(header);
  }
}

void Recorder::add(Channel channel) {
  const int width = std::max(channel.columns, 1);
  if (channel.labels.empty()) {
    if (channel.columns == 0)
      channel.labels = {""};
    else
      for (int c = 0; c < width; ++c) channel.labels.push_back("[" + std::to_string(c) + "]");
  }
  if (channel.column_units.empty()) channel.column_units.assign(width, channel.units);
  channel.statistics = RunningStatistics(width);
  // Cost (docs/performance.md): moments for every column; crossings, peaks, extreme-value
  // fits and the Welch spectrum for the channels a designer takes extremes of, the scalar
  // series (forces, drivers, compensator signals) and the reactions, not for body and
  // joint kinematics.
  stats::StatisticsOptions options = response_options_;
  if (!has_extreme_statistics(channel)) {
    options.cycles = false;
    options.segment_length = -1;
  }
  for (int c = 0; c < width; ++c) channel.response.emplace_back(options, window_samples_);
  channel.row_offset = row_width_;
  row_width_ += width;
  if (channel.fill) fills_.push_back({std::move(channel.fill), channel.row_offset});
  channels_.push_back(std::move(channel));
}

void Recorder::lay_out_file() {
  if (std::exchange(layout_started_, true)) throw std::logic_error("Recorder: the file is laid out once");
  if (!evaluates_beside()) {
    create_layout();
    return;
  }
  // The thread's first job; the batches wait for it (hand_over_batch).
  layout_pending_ = true;
  call_evaluation_worker(&BackgroundWorker::start);
}

void Recorder::create_layout() {
  for (Channel& channel : channels_) {
    // The recorder's row is the file's staged sample: the file holds its series only, in
    // the channels' order (require_file_block_agrees checks the widths at every sample).
    channel.series = file_.add_series(channel.path, channel.columns, channel.units, channel.description);
    // The statistics exist from the start, NaN until finish() overwrites them in place
    // (after the layout is published, a series' object header must not grow:
    // app/output/result_file.hpp).
    const std::vector<std::string> names = statistic_names(channel);
    file_.set_record_attribute(channel.series, "statistics", names,
                               std::vector<double>(names.size() * std::max(channel.columns, 1), std::nan("")));
  }
  for (const auto& [group, order] : group_orders_) file_.set_attribute(group, "order", order);
  file_.flush();  // the layout on disk: the file appears under its name
}

void Recorder::define_channels(const CaseDefinition& definition) {
  const OutputSettings& output = definition.output;
  const Model& model = *scene_.model;
  const std::vector<std::string> xyz = {".x", ".y", ".z"};

  add({"/time", 0, "s", "simulation time", {}, [](SampleContext&, double t, double* out) { out[0] = t; }});

  // The fills read the evaluation of whichever scene the sample's context holds, by index:
  // the channels are the same on every build of the case.
  if (output.bodies) {
    records_bodies_ = true;
    for (int i = 1; i < model.num_links(); ++i) {
      const std::string base = "/bodies/" + model.links[i].name;
      add({base + "/position", 3, "m", "body reference point (body frame origin), world frame", xyz,
           [i](SampleContext& sample, double, double* out) { map3(out) = sample.body_frames[i].translation(); }});
      add({base + "/orientation", 4, "-", "unit quaternion w, x, y, z of the body frame, body -> world",
           {".w", ".x", ".y", ".z"}, [i](SampleContext& sample, double, double* out) {
             const Eigen::Quaterniond q(sample.body_frames[i].rotation());
             out[0] = q.w(); out[1] = q.x(); out[2] = q.y(); out[3] = q.z();
           }});
      add({base + "/velocity", 6, "rad/s, m/s",
           "[angular velocity; velocity of the body reference point], world axes",
           {".wx", ".wy", ".wz", ".vx", ".vy", ".vz"}, [i](SampleContext& sample, double, double* out) {
             const Motion& v = sample.system->data().velocity_world[i];
             map3(out) = v.angular();
             map3(out + 3) = v.point_velocity(sample.body_frames[i].translation());
           }, -1, {}, {}, {"rad/s", "rad/s", "rad/s", "m/s", "m/s", "m/s"}});
    }
  }

  for (int i = 1; i < model.num_links(); ++i) {
    const Joint& joint = model.joints[i];
    const std::string base = "/joints/" + joint.name;
    const std::string type = joint_type_name(joint.type);
    if (output.joints && joint.nv > 0) {
      const int q_index = joint.q_index, nq = joint.nq, v_index = joint.v_index, nv = joint.nv;
      add({base + "/q", nq, coordinate_units(joint.type),
           type + " joint coordinates (order in docs/result-file.md)", {},
           [q_index, nq](SampleContext& sample, double, double* out) {
             Eigen::Map<VectorX>(out, nq) = sample.system->configuration().segment(q_index, nq);
           }, -1, {}, {}, coordinate_column_units(joint.type, nq)});
      add({base + "/qd", nv, speed_units(joint.type, ""),
           type + " joint speeds (child-side axes for spherical and free joints)", {},
           [v_index, nv](SampleContext& sample, double, double* out) {
             Eigen::Map<VectorX>(out, nv) = sample.system->velocity().segment(v_index, nv);
           }, -1, {}, {}, speed_column_units(joint.type, nv, "")});
      add({base + "/qdd", nv, speed_units(joint.type, "/s"), type + " joint accelerations", {},
           [v_index, nv](SampleContext& sample, double, double* out) {
             Eigen::Map<VectorX>(out, nv) = sample.system->data().qdd.segment(v_index, nv);
           }, -1, {}, {}, speed_column_units(joint.type, nv, "/s")});
    }
    if (output.reactions) {
      needs_reactions_ = true;
      const std::size_t k = reaction_joints_.size();  // this joint's entry of the contexts' reactions
      reaction_joints_.push_back(i);
      joint_loads_.push_back({joint.name, 0.0, RunningStatistics(1)});
      reaction_force_row_offsets_.push_back(row_width_);  // the load is its norm
      add({base + "/reaction_force", 3, "N",
           "force exerted by the parent on the child at the joint origin, world axes", xyz,
           [k](SampleContext& sample, double, double* out) { map3(out) = sample.reactions[k].force_world; }});
      add({base + "/reaction_moment", 3, "N m",
           "moment exerted by the parent on the child about the joint origin, world axes", xyz,
           [k](SampleContext& sample, double, double* out) { map3(out) = sample.reactions[k].moment_world; }});
      add({base + "/reaction_force_joint", 3, "N",
           "force exerted by the parent on the child, joint (child-side) axes", xyz,
           [k](SampleContext& sample, double, double* out) { map3(out) = sample.reactions[k].force_joint; }});
      add({base + "/reaction_moment_joint", 3, "N m",
           "moment exerted by the parent on the child about the joint origin, joint (child-side) axes", xyz,
           [k](SampleContext& sample, double, double* out) { map3(out) = sample.reactions[k].moment_joint; }});
    }
  }

  define_constraint_channels(output);
  define_driver_channels();
  if (output.forces) define_element_channels();

  records_energy_ = output.energy;
  // Energy checks the integration only where nothing but gravity and joint springs does
  // work: with force elements, drivers, limits or joint damping it changes by their work.
  const std::vector<Joint>& joints = scene_.model->joints;
  energy_is_conserved_ =
      scene_.system->force_elements().empty() && definition.drivers.empty() &&
      std::none_of(joints.begin(), joints.end(), [](const Joint& joint) {
        return joint.limits.has_value() || (joint.spring && joint.spring->damping.cwiseAbs().maxCoeff() > 0.0);
      });
  if (output.energy) {
    // The energies of the sample, computed once per sample (fill_row), side by side.
    energy_row_offset_ = row_width_;
    add({"/signals/kinetic_energy", 0, "J", "kinetic energy of all bodies (including added mass)", {},
         [](SampleContext& sample, double, double* out) { out[0] = sample.energy.kinetic; }});
    add({"/signals/potential_energy", 0, "J",
         "gravitational, joint-spring and force-element (springs, gas, restoring, contact) potential energy", {},
         [](SampleContext& sample, double, double* out) { out[0] = sample.energy.potential; }});
    add({"/signals/total_energy", 0, "J", "kinetic plus potential energy", {},
         [](SampleContext& sample, double, double* out) { out[0] = sample.energy.total; }});
  }
}

void Recorder::define_constraint_channels(const OutputSettings& output) {
  const Model& model = *scene_.model;
  if (!model.has_constraints()) return;
  const std::vector<std::string> xyz = {".x", ".y", ".z"};
  // Drift is always recorded: it is how a user sees that a loop stayed closed.
  add({"/signals/constraint_residual", 0, "m or rad", "max |Phi(q, t)| over all constraint rows", {},
       [](SampleContext& sample, double t, double* out) {
         const MultibodySystem& system = *sample.system;
         constraint_residual(system.model(), system.data(), system.configuration(), t, sample.phi);
         out[0] = sample.phi.cwiseAbs().maxCoeff();
       }});
  add({"/signals/constraint_velocity_residual", 0, "m/s or rad/s",
       "max |J v + dPhi/dt| over all constraint rows", {}, [](SampleContext& sample, double t, double* out) {
         const MultibodySystem& system = *sample.system;
         constraint_velocity_target(system.model(), system.data(), t, sample.constraint_velocity);
         sample.constraint_velocity.noalias() -= system.data().constraint_jacobian * system.velocity();
         out[0] = sample.constraint_velocity.cwiseAbs().maxCoeff();
       }});
  if (!output.reactions) return;
  for (std::size_t c = 0; c < model.constraints.size(); ++c) {
    const Constraint& constraint = model.constraints[c];
    if (constraint.is_driver() || constraint.is_unilateral()) continue;  // drivers: /drivers; stops: the contacts element
    const std::string base = "/constraints/" + constraint.name;
    const int rows = static_cast<int>(constraint.rows.size());
    std::vector<std::string> labels, units;
    for (const ConstraintRow& row : constraint.rows) {
      labels.push_back("." + row.description);
      units.push_back(multiplier_unit(row.kind));
    }
    add({base + "/multipliers", rows, "N, N m or N/m",
         "Lagrange multipliers lambda of the constraint rows (M qdd + C = tau + J^T lambda); "
         "minimum-norm where rows are redundant; a driver's is the force (N) or torque (N m) it applies "
         "along its coordinate",
         labels, [first_row = constraint.first_row, rows](SampleContext& sample, double, double* out) {
           Eigen::Map<VectorX>(out, rows) = sample.system->data().constraint_multipliers.segment(first_row, rows);
         }, -1, {}, {}, units});
    if (!constraint.acts_on_frames()) continue;
    // The wrench on side B (the loop joint's child side) about frame B's origin.
    auto wrench_at_b = [c](const SampleContext& sample) {
      const MultibodySystem& system = *sample.system;
      const Constraint& on_scene = system.model().constraints[c];
      const Force f = constraint_wrench(system.model(), system.data(), on_scene, system.data().constraint_multipliers);
      const Vector3 origin = constraint_frame_b(system.data(), on_scene).translation();
      return std::pair<Vector3, Vector3>(f.linear(), f.angular() - origin.cross(f.linear()));
    };
    add({base + "/reaction_force", 3, "N",
         "force exerted by side A (parent/body_a) on side B (child/body_b) at frame B's origin, world axes", xyz,
         [wrench_at_b](SampleContext& sample, double, double* out) { map3(out) = wrench_at_b(sample).first; }});
    add({base + "/reaction_moment", 3, "N m",
         "moment exerted by side A on side B about frame B's origin, world axes", xyz,
         [wrench_at_b](SampleContext& sample, double, double* out) { map3(out) = wrench_at_b(sample).second; }});
  }
}

void Recorder::define_driver_channels() {
  const MultibodySystem& system = *scene_.system;
  for (std::size_t c = 0; c < system.model().constraints.size(); ++c) {
    const Constraint& constraint = system.model().constraints[c];
    if (!constraint.driver_motion()) continue;
    // f(t) of the sample's own scene: a driver's expression keeps its evaluation workspace.
    const auto motion = [c](const SampleContext& sample, double t) {
      return (*sample.system->model().constraints[c].driver_motion())(t);
    };
    const std::string base = "/drivers/" + constraint.name;
    const bool angular = driver_is_angular(system.model(), constraint);
    const std::string unit = angular ? "rad" : "m";
    const int row = constraint.first_row;
    // Phi = g(q) - f(t) with dPhi/dg = 1, so J^T lambda is lambda along the increasing
    // coordinate g: the multiplier is the actuator's force or torque (docs/physics/drivers.md).
    add({base + (angular ? "/torque" : "/force"), 0, angular ? "N m" : "N",
         std::string(constraint.kind_name()) + " '" + constraint.name + "': the " + (angular ? "torque" : "force") +
             " it applies along its increasing coordinate (" + constraint.rows[0].description +
             "), the multiplier lambda of M qdd + C = tau + J^T lambda",
         {}, [row](SampleContext& sample, double, double* out) {
           out[0] = sample.system->data().constraint_multipliers[row];
         }});
    add({base + "/position", 0, unit, "prescribed f(t)", {},
         [motion](SampleContext& sample, double t, double* out) { out[0] = motion(sample, t).position; }});
    add({base + "/velocity", 0, unit + "/s", "prescribed f'(t)", {},
         [motion](SampleContext& sample, double t, double* out) { out[0] = motion(sample, t).velocity; }});
    add({base + "/acceleration", 0, unit + "/s/s", "prescribed f''(t)", {},
         [motion](SampleContext& sample, double t, double* out) { out[0] = motion(sample, t).acceleration; }});
  }
}

void Recorder::define_element_channels() {
  const MultibodySystem& system = *scene_.system;
  element_row_offsets_.assign(system.force_elements().size(), -1);
  for (std::size_t e = 0; e < system.force_elements().size(); ++e) {
    const ForceElement& element = *system.force_elements()[e];
    if (element.channels().empty()) continue;
    // Scalar channels added one after the other lie side by side in the row: the
    // element's outputs() writes them all there (fill_row), no fill of their own.
    element_row_offsets_[e] = row_width_;
    for (const ElementChannel& channel : element.channels())
      add({"/forces/" + element.name() + "/" + channel.name, 0, channel.units, channel.description, {}, {}});
  }
}

void Recorder::record(double t, const VectorX& y) {
  require_layout();
  if (!evaluates_beside()) {
    evaluate_and_record(own_, t, y);
    return;
  }
  SampleBatch& batch = batches_[filling_];
  batch.times[batch.count] = t;
  batch.states[batch.count] = y;  // the same size: no allocation
  if (++batch.count == evaluation_batch) hand_over_batch();
}

std::string Recorder::why_samples_in_line(const CaseDefinition& definition, const Scene& scene) {
  const long samples = output_sample_count(definition.solver, definition.output.interval);
  if (samples <= 4 * evaluation_batch)
    return fmt::format("{} samples, too few to repay a second build of the scene", samples);
  if (usable_cores() < 2) return "one core to run on";
  if (scene.system->applied_dependencies().history)
    for (const std::unique_ptr<ForceElement>& element : scene.system->force_elements())
      if (element->dependencies().history)
        return fmt::format("force element '{}' depends on its evaluations before (ElementDependencies::history)",
                           element->name());
  // What the integrated system's Data keeps from one evaluation to the next, a copy's would
  // not: the rows the ODE form sets aside as redundant (kernel/system/ode_form.cpp), judged
  // by it at the run's first state -- the assembled one, whose rank the scene holds, unless
  // the run starts from a static equilibrium -- and the joint stops' active rows (events).
  const Model& model = scene.system->model();
  if (integrates_the_ode_form(definition.solver.integrator.method) && model.has_constraints() &&
      (!scene.assembly.rank.redundant_rows.empty() || scene.equilibrium))
    return "loop constraint rows an explicit method may set aside step by step (redundant ones, or a static start)";
  const std::vector<Constraint>& constraints = model.constraints;
  const auto stop = std::find_if(constraints.begin(), constraints.end(),
                                 [](const Constraint& constraint) { return constraint.is_unilateral(); });
  if (stop != constraints.end()) return fmt::format("joint stop '{}', active or not by events", stop->name);
  return "";
}

void Recorder::evaluate_on_second_thread(Scene* caller_scene) {
  if (samples_ > 0) throw std::logic_error("Recorder: evaluate_on_second_thread after the first sample");
  if (evaluates_beside()) throw std::logic_error("Recorder: evaluate_on_second_thread twice");
  if (caller_scene) {
    // The fills and the compensators' measures read the caller's scene by index: it must
    // be a build of the same case (the same links, constraint rows and elements, in the
    // same order, with states of the same sizes).
    const MultibodySystem& own = *scene_.system;
    const MultibodySystem& callers = *caller_scene->system;
    bool same = &callers != &own && callers.size() == own.size() &&
                callers.model().num_links() == own.model().num_links() &&
                callers.model().num_constraint_rows == own.model().num_constraint_rows &&
                callers.force_elements().size() == own.force_elements().size();
    for (std::size_t e = 0; same && e < own.force_elements().size(); ++e) {
      const ForceElement& mine = *own.force_elements()[e];
      const ForceElement& theirs = *callers.force_elements()[e];
      same = typeid(theirs) == typeid(mine) && theirs.state_size() == mine.state_size() &&
             theirs.channels().size() == mine.channels().size();
    }
    if (!same) throw std::logic_error("Recorder: the caller's scene is not another build of the recorder's case");
    // A command's extra channel reads what the command keeps, on whichever thread asks.
    if (has_extra_channels_) throw std::logic_error("Recorder: extra channels are read on one thread only");
    caller_ = std::make_unique<SampleContext>(make_context(*caller_scene->system));
  }
  batches_.resize(evaluation_batches);
  for (SampleBatch& batch : batches_) {
    batch.times.assign(evaluation_batch, 0.0);
    batch.states.assign(evaluation_batch, VectorX::Zero(scene_.system->size()));
    if (!caller_) continue;
    batch.row_width = row_width_;
    batch.measured_width = compensators_.measured_values();
    batch.rows.reset(new double[evaluation_batch * batch.row_width]);
    batch.measured.reset(new double[evaluation_batch * batch.measured_width]);
  }
  for (std::vector<int>* list : {&free_, &ready_, &handed_}) list->reserve(evaluation_batches);
  drop_batches();
}

Recorder::SampleContext Recorder::make_context(MultibodySystem& system) const {
  SampleContext sample;
  sample.system = &system;
  if (records_bodies_) sample.body_frames.resize(system.model().num_links());
  sample.reactions.resize(reaction_joints_.size());
  sample.phi.resize(system.model().num_constraint_rows);
  sample.constraint_velocity.resize(system.model().num_constraint_rows);
  return sample;
}

void Recorder::hand_over_batch() {
  ready_.push_back(std::exchange(filling_, -1));
  // The caller would wait here for the thread to record the batches before; it evaluates
  // the ready batches' samples instead, oldest first, glancing at the thread between
  // samples, and then integrates on into a free batch: the thread evaluates what is left
  // when it takes them. The caller's scene is the one it integrates, free between the
  // integrator's steps: evaluated at a sample, it gives that sample's numbers, as it does
  // when every sample is evaluated in line.
  while (evaluation_worker_.busy()) {
    if (evaluate_next_ready_sample()) continue;
    // A sample that failed is thrown by the thread once it has the batch: at once, rather
    // than after integrating on into samples that would be dropped.
    const bool failed = std::any_of(ready_.begin(), ready_.end(), [this](int index) {
      return static_cast<bool>(batches_[index].failure);
    });
    if (!free_.empty() && !failed) {
      filling_ = take_free_batch();
      return;
    }
    break;  // nothing left to do but wait for the thread
  }
  start_ready_batches();
  filling_ = take_free_batch();
}

bool Recorder::evaluate_next_ready_sample() {
  if (!caller_) return false;
  for (const int index : ready_) {
    SampleBatch& batch = batches_[index];
    if (batch.failure) return false;  // the samples after it are dropped
    if (batch.evaluated == batch.count) continue;
    const long k = batch.evaluated;
    try {
      evaluate_row(*caller_, batch.times[k], batch.states[k], batch.row(k), batch.measured_values(k));
      ++batch.evaluated;
    } catch (...) {
      batch.failure = std::current_exception();  // thrown by the thread after the samples before it
    }
    return true;
  }
  return false;
}

void Recorder::start_ready_batches() {
  free_handed_batches();
  handed_.swap(ready_);  // ready_ takes the emptied list
  call_evaluation_worker(&BackgroundWorker::start);
  // Every batch was ready (the thread was on the layout all along): the caller waits for
  // them to be recorded, having none left to fill.
  if (free_.empty()) free_handed_batches();
}

void Recorder::free_handed_batches() {
  settle_evaluation();
  free_.insert(free_.end(), handed_.begin(), handed_.end());
  handed_.clear();
}

void Recorder::call_evaluation_worker(void (BackgroundWorker::*call)()) {
  try {
    (evaluation_worker_.*call)();
  } catch (...) {
    drop_batches();
    throw;
  }
}

int Recorder::take_free_batch() {
  const int index = free_.back();
  free_.pop_back();
  return index;
}

void Recorder::drop_batches() {
  free_.clear();
  ready_.clear();
  handed_.clear();
  // Taken last in, first out: batch 0 first.
  for (int index = evaluation_batches - 1; index >= 0; --index) {
    SampleBatch& batch = batches_[index];
    batch.count = batch.evaluated = 0;
    batch.failure = nullptr;
    free_.push_back(index);
  }
  filling_ = take_free_batch();
}

void Recorder::record_batch(SampleBatch& batch, SampleContext& sample) {
  const long count = std::exchange(batch.count, 0);
  const long evaluated = std::exchange(batch.evaluated, 0);
  const std::exception_ptr failure = std::exchange(batch.failure, nullptr);
  for (long k = 0; k < evaluated; ++k) {
    commit_row(batch.times[k], batch.row(k), batch.measured_values(k));
    ++samples_evaluated_by_caller_;
  }
  if (failure) std::rethrow_exception(failure);
  for (long k = evaluated; k < count; ++k) evaluate_and_record(sample, batch.times[k], batch.states[k]);
}

void Recorder::evaluate_and_record(SampleContext& sample, double t, const VectorX& y) {
  evaluate_row(sample, t, y, file_.sample_row(), measured_.data());
  commit_row(t, file_.sample_row(), measured_.data());
}

void Recorder::settle_evaluation() { call_evaluation_worker(&BackgroundWorker::wait); }

void Recorder::record_queued_samples() {
  require_layout();
  if (!evaluates_beside()) return;
  if (batches_[filling_].count > 0) ready_.push_back(std::exchange(filling_, -1));
  while (evaluation_worker_.busy() && evaluate_next_ready_sample()) {
  }
  free_handed_batches();
  // In line, the thread being idle: the ready batches' rows the caller evaluated are
  // recorded, the rest evaluated on the recorder's scene.
  for (const int index : ready_) {
    try {
      record_batch(batches_[index], own_);
    } catch (...) {
      drop_batches();
      throw;
    }
    free_.push_back(index);
  }
  ready_.clear();
  if (filling_ < 0) filling_ = take_free_batch();
}

void Recorder::record_evaluation(double t, const VectorX& y) {
  // The caller's evaluation is recorded here, in order: no thread may hold the file.
  if (evaluates_beside()) throw std::logic_error("Recorder: record_evaluation with samples evaluated beside");
  require_layout();
  fill_row(own_, t, y, file_.sample_row(), measured_.data());
  commit_row(t, file_.sample_row(), measured_.data());
}

void Recorder::evaluate_row(SampleContext& sample, double t, const VectorX& y, double* row, double* measured) {
  sample.system->evaluate(t, y, needs_reactions_);
  fill_row(sample, t, y, row, measured);
}

void Recorder::fill_row(SampleContext& sample, double t, const VectorX& y, double* row, double* measured) {
  MultibodySystem& system = *sample.system;
  // Everything below reads the stages of this one evaluation; require_stages catches a
  // read after something evaluated the system again (a stale read).
  const long evaluation = system.data().stages.evaluation;
  const unsigned stages = StageMarker::positions | StageMarker::velocities | StageMarker::accelerations |
                          (needs_reactions_ ? StageMarker::reactions : 0u);
  // The sample's row: every channel's values side by side.
  for (std::size_t e = 0; e < element_row_offsets_.size(); ++e) {
    if (element_row_offsets_[e] < 0) continue;
    const ForceElement& element = *system.force_elements()[e];
    const std::span<double> values(row + element_row_offsets_[e], element.channels().size());
    // The row holds an older sample's values: one the element leaves unwritten reads NaN.
    std::fill(values.begin(), values.end(), std::numeric_limits<double>::quiet_NaN());
    element.outputs(t, system.model(), system.data(), y.segment(system.state_offset(e), element.state_size()),
                    values);
  }
  compensators_.measure(system, t, y, measured);
  if (records_energy_) {
    // T + V with V = gravity + joint springs + what the force elements store; summed left
    // to right so that a scene whose elements store nothing gives the same digits as T + V_g + V_j.
    double element_energy = 0.0;
    for (std::size_t e = 0; e < system.force_elements().size(); ++e) {
      const ForceElement& element = *system.force_elements()[e];
      element_energy += element.potential_energy(system.model(), system.data(),
                                                 y.segment(system.state_offset(e), element.state_size()));
    }
    const double gravity = gravity_potential_energy(system.model(), system.data());
    const double joint_springs = joint_elastic_energy(system.model(), system.configuration());
    sample.energy.kinetic = kinetic_energy(system.model(), system.data());
    sample.energy.potential = gravity + joint_springs + element_energy;
    sample.energy.total = sample.energy.kinetic + gravity + joint_springs + element_energy;
  }
  // Once a sample: the four reaction channels and the load read it.
  for (std::size_t k = 0; k < reaction_joints_.size(); ++k)
    sample.reactions[k] = joint_reaction(system.model(), system.data(), reaction_joints_[k]);
  require_stages(system.data(), stages, t, evaluation);
  for (std::size_t i = 1; i < sample.body_frames.size(); ++i)
    sample.body_frames[i] = system.data().X_world_link[i] * system.model().links[i].X_link_body;
  for (Fill& fill : fills_) fill.write(sample, t, row + fill.row_offset);
  require_stages(system.data(), stages, t, evaluation);
}

void Recorder::commit_row(double t, const double* row, const double* measured) {
  compensators_.observe(t, measured);
  for (std::size_t k = 0; k < reaction_joints_.size(); ++k) {
    const double load = map3(row + reaction_force_row_offsets_[k]).norm();
    joint_loads_[k].peak = std::max(joint_loads_[k].peak, load);
    if (compensators_.in_window(t)) joint_loads_[k].window.add(&load);
  }
  if (csv_) csv_row_.assign(row, row + row_width_);  // sized once: no allocation
  // Read before end_sample(): the staged row (`row`, in line) is the file's after it.
  const double kinetic = records_energy_ ? row[energy_row_offset_] : 0.0;
  const double energy = records_energy_ ? row[energy_row_offset_ + 2] : 0.0;
  if (window_first_row_ < 0 && compensators_.in_window(t)) window_first_row_ = block_samples_;
  // This sample ends a block: the file's end_sample() writes it and makes it the last
  // whole block, in place of the one the block worker may still be reading.
  const bool ends_block = block_samples_ + 1 == static_cast<long>(ResultFile::block_rows);
  require_file_block_agrees();
  if (ends_block) block_worker_.wait();
  double* const staged = file_.sample_row();
  if (row != staged) std::copy(row, row + row_width_, staged);
  file_.end_sample();
  // The sample is in the file: counted with the file's count, before anything else can
  // fail (a CSV write).
  ++block_samples_;
  ++samples_;
  last_sample_time_ = t;
  if (ends_block) hand_over_block();
  if (csv_) csv_->write_row(csv_row_);

  if (records_energy_) {
    if (samples_ == 1) initial_energy_ = energy;
    max_kinetic_energy_ = std::max(max_kinetic_energy_, kinetic);
    const double scale = std::max(std::abs(initial_energy_), max_kinetic_energy_);
    if (scale > 0.0) energy_drift_ = std::max(energy_drift_, std::abs(energy - initial_energy_) / scale);
  }
}

void Recorder::require_file_block_agrees() const {
  // The file ends its block when the recorder does (its end_sample() swaps the last whole
  // block, which the statistics worker reads): a count that drifted would race, and the
  // block being built would not be the samples the recorder counts.
  if (file_.buffered_samples() != static_cast<hsize_t>(block_samples_))
    throw std::logic_error("Recorder: the result file's block and the recorder's disagree");
  // A series of the file's not the recorder's (before, among or after its own) would
  // shift the channels' offsets or keep stale staged values.
  if (file_.staging_width() != static_cast<hsize_t>(row_width_))
    throw std::logic_error("Recorder: the result file holds series other than the recorder's");
}

void Recorder::hand_over_block() {
  handed_window_first_row_ = window_first_row_;
  block_samples_ = 0;
  window_first_row_ = window_first_row_ >= 0 ? 0 : -1;  // the window, once begun, runs to the end
  block_worker_.start();
}

void Recorder::add_last_block_statistics(long window_first_row) {
  // Column by column over a block instead of channel by channel every sample: the
  // recording's share of the drilling run (docs/performance.md). The rows are where the
  // channels wrote them, in the file's last whole block.
  for (Channel& channel : channels_)
    add_block_statistics(channel, file_.last_block(channel.series), static_cast<long>(ResultFile::block_rows),
                         window_first_row);
}

void Recorder::add_block_statistics(Channel& channel, const double* block, long rows, long window_first_row) {
  const long width = std::max(channel.columns, 1);
  // Each sample's moments are taken once: the window's rows by the response
  // statistics, the rows before it here; the whole record's merges the two at the end.
  // Summing the window's rows twice was 23.5 M instructions, ~2.5 % of the drilling
  // run's (docs/performance.md, "Issue #18, eleventh round").
  channel.statistics.add_rows(block, window_first_row >= 0 ? window_first_row : rows);
  if (window_first_row >= 0)
    for (std::size_t c = 0; c < channel.response.size(); ++c)
      channel.response[c].add(block + window_first_row * width + c, width, rows - window_first_row);
}

std::vector<std::string> Recorder::statistic_names(const Channel& channel) {
  const bool extremes = has_extreme_statistics(channel);
  std::vector<std::string> names;
  for (const stats::StatisticField& field : stats::statistic_fields())
    if (extremes || field.group == stats::FieldGroup::moments) names.push_back(field.name);
  return names;
}

bool Recorder::has_extreme_statistics(const Channel& channel) {
  if (channel.path == "/time") return false;
  return channel.columns == 0 || channel.path.find("/reaction_") != std::string::npos;
}

std::vector<double> Recorder::response_statistic_values(Channel& channel) {
  const bool extremes = has_extreme_statistics(channel);
  std::vector<double> values;
  for (stats::ResponseStatisticsAccumulator& accumulator : channel.response) {
    const stats::ResponseStatistics column = accumulator.result();
    for (const stats::StatisticField& field : stats::statistic_fields())
      if (extremes || field.group == stats::FieldGroup::moments) values.push_back(field.value(column));
  }
  return values;
}

RunningStatistics Recorder::whole_record_statistics(const Channel& channel) {
  RunningStatistics whole = channel.statistics;
  for (std::size_t c = 0; c < channel.response.size(); ++c)
    whole.merge(static_cast<int>(c), channel.response[c].moments());
  return whole;
}

double Recorder::channel_maximum(const std::string& path) const {
  for (const Channel& channel : channels_)
    if (channel.path == path) return whole_record_statistics(channel).maximum()[0];
  return std::nan("");
}

void Recorder::write_statistics(const Channel& channel, const std::vector<double>& response_values) {
  const RunningStatistics whole = whole_record_statistics(channel);
  file_.set_attribute(channel.series, "minimum", whole.minimum());
  file_.set_attribute(channel.series, "maximum", whole.maximum());
  file_.set_attribute(channel.series, "mean", whole.mean());
  file_.set_attribute(channel.series, "standard_deviation", whole.standard_deviation());
  // One compound attribute per channel (a record per column, a field per statistic): one
  // HDF5 attribute write instead of ~40 keeps the end of a run short (docs/performance.md).
  file_.set_record_attribute(channel.series, "statistics", statistic_names(channel), response_values);
}

void Recorder::finish() {
  record_queued_samples();
  block_worker_.wait();
  // The block being built, as far as it goes (the file holds the same samples), and then
  // the window's statistics of every column, channel by channel on two threads: nothing
  // else runs now, and the spectra, cycle counts and extreme-value fits were the end of
  // the run's largest part (docs/performance.md, "Issue #18, fourteenth round").
  std::vector<const double*> blocks(channels_.size(), nullptr);
  if (block_samples_ > 0) {
    require_file_block_agrees();
    for (std::size_t c = 0; c < channels_.size(); ++c) blocks[c] = file_.block(channels_[c].series);  // moves the staged rows
  }
  std::vector<std::vector<double>> values(channels_.size());
  // A second thread only where the run has a core of its own beside the integration's, as
  // for the samples (not in the runs of a sweep side by side). The file's writes stay on
  // this thread, channel after channel as their statistics are ready, between this
  // thread's own channels: they overlap the other thread's statistics instead of
  // following all of them (docs/performance.md, "Issue #18, twenty-fourth round").
  for_each_index_in_order(
      channels_.size(), evaluates_beside() ? 2 : 1,
      [&](std::size_t c) {
        if (blocks[c] != nullptr) add_block_statistics(channels_[c], blocks[c], block_samples_, window_first_row_);
        values[c] = response_statistic_values(channels_[c]);
      },
      [&](std::size_t c) { write_statistics(channels_[c], values[c]); });
  block_samples_ = 0;
  file_.set_attribute("/", "statistics_window_start", evaluate_after());
  file_.set_attribute("/summary", "samples", samples_);
  // The same number under the name of what it is: a drift only where energy is conserved.
  if (records_energy_)
    file_.set_attribute("/summary", energy_is_conserved_ ? "relative_energy_drift" : "relative_energy_change",
                         energy_drift_);
  compensators_.write(file_);
  for (const JointLoad& load : joint_loads_) {
    file_.set_attribute("/summary", "peak_reaction_force_" + load.joint, load.peak);
    if (load.window.count() == 0) continue;
    const std::string prefix = "reaction_force_" + load.joint;
    file_.set_attribute("/summary", prefix + "_mean_N", load.window.mean()[0]);
    file_.set_attribute("/summary", prefix + "_std_N", load.window.standard_deviation()[0]);
    file_.set_attribute("/summary", prefix + "_min_N", load.window.minimum()[0]);
    file_.set_attribute("/summary", prefix + "_max_N", load.window.maximum()[0]);
  }
  if (!joint_loads_.empty()) file_.set_attribute("/summary", "reaction_window_start_s", evaluate_after());
  file_.flush();
}

}  // namespace heavesim
