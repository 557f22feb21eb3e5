#include "app/mksim/mksim_to_case.hpp"

#include <yaml-cpp/yaml.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <deque>
#include <filesystem>
#include <limits>
#include <optional>

#include <fmt/format.h>

#include "app/mksim/mksim_reader.hpp"

namespace heavesim::mksim {

std::string Count::summary() const {
  std::string joints;
  for (const std::string& term : joint_terms) joints += (joints.empty() ? "" : ", ") + term;
  return fmt::format(
      "MKSim count: {} generalized coordinates (7 per body: centre of gravity and 4 Euler parameters; {} bodies "
      "including the ground); {} equations: {} normal (1 per body), {} ground, {} joint ({}), {} driving; "
      "DOF = {} - {} = {}",
      coordinates, bodies, equations(), normal, ground, joint_equations, joints.empty() ? "none" : joints, drivers,
      coordinates, equations(), dof());
}

Count count(const Model& model) {
  Count result;
  result.bodies = static_cast<int>(model.bodies.size());
  result.coordinates = 7 * result.bodies;
  result.normal = result.bodies;
  for (const Joint& joint : model.joints) {
    const int rows = joint_equation_count(joint.type);
    result.joint_equations += rows;
    result.joint_terms.push_back(fmt::format("{} {}: {}", joint_type_name(joint.type), joint.name, rows));
  }
  result.drivers = static_cast<int>(model.drivers.size());
  return result;
}

namespace {

/// Free motions of each joint type (heavesim's joint speeds); the rest are its rows.
int free_motions(JointType type) { return 6 - joint_equation_count(type); }

/// A body's placement in the world at the given (initial) configuration.
struct Placement {
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
};

Placement body_placement(const Body& body) {
  Placement placement;
  if (body.par) placement.rotation = frame_axes(*body.par);
  if (body.center_of_gravity) placement.position = *body.center_of_gravity;
  return placement;
}

/// A triad in its body's frame and in the world.
struct TriadFrames {
  Placement local, world;
};

TriadFrames triad_frames(const Model& model, const Triad& triad) {
  TriadFrames frames;
  frames.local.rotation = frame_axes(*triad.par);
  frames.local.position = *triad.origin;
  const Placement body = body_placement(model.bodies[triad.body_index]);
  frames.world.rotation = body.rotation * frames.local.rotation;
  frames.world.position = body.position + body.rotation * frames.local.position;
  return frames;
}

/// A joint of the heavesim case: which MKSim triad is on the parent side, and whether
/// it is a tree joint.
struct CaseJoint {
  std::size_t joint = 0;
  std::size_t parent_triad = 0, child_triad = 0;
  bool tree = false;
};

/// Breadth-first from the ground over the joints in file order: the joint that first
/// reaches a body is its tree joint (parent side on the body reached before), the
/// others close loops (parent side: the joint's first triad). A body left unreached is
/// bad input at its name.
std::vector<CaseJoint> spanning_tree(const Model& model) {
  std::vector<CaseJoint> result(model.joints.size());
  std::vector<bool> reached(model.bodies.size(), false), used(model.joints.size(), false);
  std::deque<std::size_t> queue{model.ground};
  reached[model.ground] = true;
  while (!queue.empty()) {
    const std::size_t body = queue.front();
    queue.pop_front();
    for (std::size_t j = 0; j < model.joints.size(); ++j) {
      if (used[j]) continue;
      const Joint& joint = model.joints[j];
      for (int side = 0; side < 2; ++side) {
        const std::size_t here = model.triads[joint.triads[side]].body_index;
        const std::size_t there = model.triads[joint.triads[1 - side]].body_index;
        if (here != body || reached[there]) continue;
        result[j] = {j, joint.triads[side], joint.triads[1 - side], true};
        used[j] = reached[there] = true;
        queue.push_back(there);
        break;
      }
    }
  }
  for (std::size_t b = 0; b < model.bodies.size(); ++b)
    if (!reached[b])
      throw InputError(model.bodies[b].location, "BODY " + model.bodies[b].name,
                       "a body that no chain of joints connects to the ground '" + model.bodies[model.ground].name + "'",
                       "every body joined to the ground through joints (a kinematic model has no free bodies)");
  for (std::size_t j = 0; j < model.joints.size(); ++j)
    if (!used[j]) result[j] = {j, model.joints[j].triads[0], model.joints[j].triads[1], false};
  return result;
}

/// Haug's equations of the joint between triads i and j (world frames) at the given
/// configuration: the largest |residual| (m for the point rows, a dot product of unit
/// vectors for the others).
double joint_residual(JointType type, const Placement& i, const Placement& j) {
  const Eigen::Vector3d f = i.rotation.col(0), g = i.rotation.col(1), h = i.rotation.col(2);
  const Eigen::Vector3d d = j.position - i.position;
  const double axes_parallel = std::max(std::abs(f.dot(j.rotation.col(2))), std::abs(g.dot(j.rotation.col(2))));
  switch (type) {
    case JointType::spherical: return d.norm();
    case JointType::universal: return std::max(d.norm(), std::abs(h.dot(j.rotation.col(2))));
    case JointType::revolute: return std::max(d.norm(), axes_parallel);
    case JointType::cylindrical:
      return std::max({axes_parallel, std::abs(f.dot(d)), std::abs(g.dot(d))});
    case JointType::translational:
      return std::max({axes_parallel, std::abs(f.dot(d)), std::abs(g.dot(d)), std::abs(f.dot(j.rotation.col(0)))});
  }
  return 0.0;
}

// ---------------------------------------------------------------- YAML

/// Shortest text that reads back as the same double; round-off below a few ulps of the
/// model's scale written as 0, and never "-0".
std::string number_text(double value, double scale = 1.0) {
  if (std::abs(value) <= 4.0 * std::numeric_limits<double>::epsilon() * scale) value = 0.0;
  return fmt::format("{}", value);
}

void emit_vector(YAML::Emitter& out, const Eigen::Vector3d& v, double scale = 1.0) {
  out << YAML::Flow << YAML::BeginSeq;
  for (int k = 0; k < 3; ++k) out << number_text(v[k], scale);
  out << YAML::EndSeq;
}

bool is_identity(const Eigen::Matrix3d& rotation) {
  return (rotation - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff() <= 4.0 * std::numeric_limits<double>::epsilon();
}

/// `{position: [..], orientation: {matrix: [..]}}`, leaving out what is the default.
void emit_frame(YAML::Emitter& out, const char* key, const Placement& frame, double scale) {
  const bool at_origin = frame.position.cwiseAbs().maxCoeff() <= 4.0 * std::numeric_limits<double>::epsilon() * scale;
  if (at_origin && is_identity(frame.rotation)) return;
  out << YAML::Key << key << YAML::Value << YAML::BeginMap;
  if (!at_origin) {
    out << YAML::Key << "position" << YAML::Value;
    emit_vector(out, frame.position, scale);
  }
  if (!is_identity(frame.rotation)) {
    out << YAML::Key << "orientation" << YAML::Value << YAML::BeginMap << YAML::Key << "matrix" << YAML::Value
        << YAML::Flow << YAML::BeginSeq;
    for (int row = 0; row < 3; ++row) emit_vector(out, frame.rotation.row(row).transpose());
    out << YAML::EndSeq << YAML::EndMap;
  }
  out << YAML::EndMap;
}

const char* case_joint_type(JointType type) {
  switch (type) {
    case JointType::revolute: return "revolute";
    case JointType::spherical: return "spherical";
    case JointType::translational: return "prismatic";
    case JointType::universal: return "universal";
    case JointType::cylindrical: return "cylindrical";
  }
  return "?";
}

/// One joint of the case. The parent frame is the parent triad as written. The child
/// frame is the child triad, turned where MKSim's convention and heavesim's differ so
/// that the two frames coincide at the given configuration up to the joint's free
/// motion: z pointing the other way (MKSim only asks z parallel), a translational
/// joint's x axes (MKSim: perpendicular, Haug's f_i . f_j = 0; heavesim: equal) and a
/// universal joint's cross (heavesim's zero is the given configuration). The initial
/// coordinates of a tree joint are read from the given configuration.
void emit_joint(YAML::Emitter& out, const Model& model, const CaseJoint& entry, double scale) {
  const Joint& joint = model.joints[entry.joint];
  const Triad& parent_triad = model.triads[entry.parent_triad];
  const Triad& child_triad = model.triads[entry.child_triad];
  const TriadFrames parent = triad_frames(model, parent_triad), child = triad_frames(model, child_triad);
  const Eigen::Matrix3d relative = parent.world.rotation.transpose() * child.world.rotation;
  const Eigen::Vector3d offset = parent.world.rotation.transpose() * (child.world.position - parent.world.position);
  Placement child_frame = child.local;
  std::vector<double> initial;
  std::optional<Eigen::Vector3d> second_axis;
  switch (joint.type) {
    case JointType::revolute:
    case JointType::cylindrical: {
      Eigen::Matrix3d turned = relative;
      if (relative(2, 2) < 0.0) {  // z reversed: turn the child frame half a turn about its x
        const Eigen::Matrix3d flip = Eigen::Vector3d(1.0, -1.0, -1.0).asDiagonal();
        child_frame.rotation = child.local.rotation * flip;
        turned = relative * flip;
      }
      initial.push_back(std::atan2(turned(1, 0), turned(0, 0)));
      if (joint.type == JointType::cylindrical) initial.push_back(offset.z());
      break;
    }
    case JointType::translational:
      child_frame.rotation = child.local.rotation * relative.transpose();
      initial.push_back(offset.z());
      break;
    case JointType::universal: {
      child_frame.rotation = child.local.rotation * relative.transpose();
      const Eigen::Vector3d h = relative.col(2);  // the child's axis in the parent triad's frame
      second_axis = Eigen::Vector3d(h.x(), h.y(), 0.0).normalized();
      initial = {0.0, 0.0};
      break;
    }
    case JointType::spherical: {
      const Eigen::Quaterniond q(relative);
      if (!is_identity(relative)) initial = {q.w(), q.x(), q.y(), q.z()};
      break;
    }
  }
  const auto body_name = [&](const Triad& triad) {
    return triad.body_index == model.ground ? std::string("ground") : model.bodies[triad.body_index].name;
  };
  out << YAML::BeginMap;
  out << YAML::Key << "name" << YAML::Value << joint.name;
  out << YAML::Key << "type" << YAML::Value << case_joint_type(joint.type);
  out << YAML::Key << "parent" << YAML::Value << body_name(parent_triad);
  out << YAML::Key << "child" << YAML::Value << body_name(child_triad);
  // A triad on the ground is in the world frame only when the ground is not placed.
  Placement parent_frame = parent_triad.body_index == model.ground ? parent.world : parent.local;
  if (child_triad.body_index == model.ground) {
    child_frame.position = child.world.position;
    child_frame.rotation = body_placement(model.bodies[model.ground]).rotation * child_frame.rotation;
  }
  emit_frame(out, "parent_frame", parent_frame, scale);
  emit_frame(out, "child_frame", child_frame, scale);
  if (joint.type == JointType::universal) {
    out << YAML::Key << "axes" << YAML::Value << YAML::Flow << YAML::BeginSeq;
    emit_vector(out, Eigen::Vector3d::UnitZ());
    emit_vector(out, *second_axis);
    out << YAML::EndSeq;
  } else if (joint.type != JointType::spherical) {
    out << YAML::Key << "axis" << YAML::Value;
    emit_vector(out, Eigen::Vector3d::UnitZ());
  }
  const bool zero = std::all_of(initial.begin(), initial.end(), [](double v) { return v == 0.0; });
  if (entry.tree && !initial.empty() && !zero) {
    out << YAML::Key << "initial" << YAML::Value << YAML::Flow << YAML::BeginMap << YAML::Key << "q" << YAML::Value;
    if (initial.size() == 1) {
      out << number_text(initial[0]);
    } else {
      out << YAML::Flow << YAML::BeginSeq;
      for (double v : initial) out << number_text(v);
      out << YAML::EndSeq;
    }
    out << YAML::EndMap;
  }
  out << YAML::EndMap;
}

/// The model's length scale: round-off below a few ulps of it is written as zero.
double model_scale(const Model& model) {
  double scale = 1.0;
  for (const Body& body : model.bodies)
    if (body.center_of_gravity) scale = std::max(scale, body.center_of_gravity->cwiseAbs().maxCoeff());
  for (const Triad& triad : model.triads) scale = std::max(scale, triad.origin->cwiseAbs().maxCoeff());
  return scale;
}

}  // namespace

std::string JointCoordinateCount::summary() const {
  const auto list = [](const std::vector<std::string>& names) {
    std::string text;
    for (const std::string& name : names) text += (text.empty() ? "" : ", ") + name;
    return text.empty() ? std::string("none") : text;
  };
  return fmt::format(
      "heavesim count: {} joint speeds (tree joints: {}); {} equations: {} of the loop joints ({}), {} driving; "
      "DOF = {} - {} = {}",
      speeds, list(tree_joints), loop_rows + driver_rows, loop_rows, list(loop_joints), driver_rows, speeds,
      loop_rows + driver_rows, speeds - loop_rows - driver_rows);
}

JointCoordinateCount joint_coordinate_count(const Model& model) {
  JointCoordinateCount result;
  for (const CaseJoint& entry : spanning_tree(model)) {
    const Joint& joint = model.joints[entry.joint];
    if (entry.tree) {
      result.speeds += free_motions(joint.type);
      result.tree_joints.push_back(joint.name);
    } else {
      result.loop_rows += joint_equation_count(joint.type);
      result.loop_joints.push_back(joint.name);
    }
  }
  result.driver_rows = static_cast<int>(model.drivers.size());
  return result;
}

std::string to_case_yaml(const Model& model) {
  const std::vector<CaseJoint> joints = spanning_tree(model);
  const double scale = model_scale(model);
  // The given configuration must be assembled within the assembly tolerance (default:
  // 1e-6 of the model's size): the tree is built from it and the loops start there.
  const double tolerance = model.system.assembly_tolerance.value_or(1e-6 * scale);
  for (const CaseJoint& entry : joints) {
    const Joint& joint = model.joints[entry.joint];
    const double residual = joint_residual(joint.type, triad_frames(model, model.triads[joint.triads[0]]).world,
                                           triad_frames(model, model.triads[joint.triads[1]]).world);
    if (residual > tolerance)
      throw InputError(joint.location, std::string(joint_type_name(joint.type)) + " joint " + joint.name,
                       fmt::format("triads '{}' and '{}' that miss the joint's equations by {:.3g} at the given "
                                   "configuration",
                                   joint.triad_names[0], joint.triad_names[1], residual),
                       fmt::format("an assembled configuration: the joint's equations within the assembly "
                                   "tolerance {:.3g} (SYSTEM's assembly tolerance{})",
                                   tolerance, model.system.assembly_tolerance ? "" : "; default 1e-6 of the model's size"));
  }

  YAML::Emitter out;
  out << YAML::Comment(fmt::format("Imported from {} by heavesim import-mksim (docs/mksim-format.md).",
                                   std::filesystem::path(model.file).filename().string()));
  out << YAML::Newline << YAML::Comment(count(model).summary());
  out << YAML::Newline << YAML::Comment(joint_coordinate_count(model).summary());
  out << YAML::Newline << YAML::BeginMap;
  out << YAML::Key << "name" << YAML::Value << model.name;
  out << YAML::Key << "description" << YAML::Value
      << fmt::format("MKSim model {}. MKSim bodies have no mass: each carries 1 kg and 1 kg m^2 about its centre "
                     "of gravity in every axis, so that the minimum-kinetic-energy motion heavesim chooses in the "
                     "free directions is MKSim's smoothest motion; driving forces are those of these placeholder "
                     "bodies, without gravity.",
                     model.name);
  out << YAML::Key << "environment" << YAML::Value << YAML::Flow << YAML::BeginMap << YAML::Key << "gravity"
      << YAML::Value;
  emit_vector(out, Eigen::Vector3d::Zero());
  out << YAML::EndMap;

  out << YAML::Key << "bodies" << YAML::Value << YAML::BeginSeq;
  for (std::size_t b = 0; b < model.bodies.size(); ++b) {
    if (b == model.ground) continue;
    out << YAML::Flow << YAML::BeginMap << YAML::Key << "name" << YAML::Value << model.bodies[b].name << YAML::Key
        << "mass" << YAML::Value << 1 << YAML::Key << "inertia" << YAML::Value << YAML::Flow << YAML::BeginSeq << 1
        << 1 << 1 << YAML::EndSeq << YAML::EndMap;
  }
  out << YAML::EndSeq;

  for (const bool tree : {true, false}) {
    const bool any = std::any_of(joints.begin(), joints.end(), [&](const CaseJoint& j) { return j.tree == tree; });
    if (!tree && !any) continue;
    out << YAML::Key << (tree ? "joints" : "loop_joints") << YAML::Value << YAML::BeginSeq;
    for (const CaseJoint& entry : joints)
      if (entry.tree == tree) emit_joint(out, model, entry, scale);
    out << YAML::EndSeq;
  }

  if (!model.drivers.empty()) {
    out << YAML::Key << "drivers" << YAML::Value << YAML::BeginSeq;
    for (const Driver& driver : model.drivers) {
      out << YAML::BeginMap;
      out << YAML::Key << "name" << YAML::Value << driver.name;
      out << YAML::Key << "type" << YAML::Value << "absolute";
      out << YAML::Key << "body" << YAML::Value << model.bodies[driver.body_index].name;
      out << YAML::Key << "point" << YAML::Value;
      emit_vector(out, driver.point, scale);
      out << YAML::Key << "direction" << YAML::Value;
      emit_vector(out, Eigen::Vector3d::Unit(driver.axis));
      out << YAML::Key << "position" << YAML::Value << with_time_named(driver.expression, "t");
      out << YAML::EndMap;
    }
    out << YAML::EndSeq;
  }

  const SystemSettings& system = model.system;
  out << YAML::Key << "solver" << YAML::Value << YAML::BeginMap;
  if (system.starting_time) out << YAML::Key << "t_start" << YAML::Value << number_text(*system.starting_time);
  out << YAML::Key << "t_end" << YAML::Value << number_text(*system.ending_time);
  if (system.assembly_tolerance)
    out << YAML::Key << "constraint_tolerance" << YAML::Value << number_text(*system.assembly_tolerance);
  out << YAML::EndMap;
  if (system.print_interval)
    out << YAML::Key << "output" << YAML::Value << YAML::BeginMap << YAML::Key << "interval" << YAML::Value
        << number_text(*system.print_interval) << YAML::EndMap;
  if (system.nr_tolerance)
    out << YAML::Key << "kinematics" << YAML::Value << YAML::BeginMap << YAML::Key << "equation_tolerance"
        << YAML::Value << number_text(*system.nr_tolerance) << YAML::EndMap;
  out << YAML::EndMap;
  if (!out.good()) throw std::logic_error("import-mksim: YAML emitter: " + out.GetLastError());
  return std::string(out.c_str()) + "\n";
}

}  // namespace heavesim::mksim
