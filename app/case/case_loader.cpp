// Reads the case schema documented in docs/case-format.md.
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>

#include <fmt/format.h>

#include "app/case/case_definition.hpp"
#include "app/case/case_merge.hpp"
#include "app/forces/force_registry.hpp"
#include "app/case/hydro_reader.hpp"
#include "app/case/node_reader.hpp"
#include "app/case/contact_reader.hpp"
#include "app/case/driver_reader.hpp"
#include "app/case/expression_constraint_reader.hpp"
#include "app/case/frame_reader.hpp"
#include "app/case/motion_reader.hpp"
#include "kernel/math/numerical_error.hpp"
#include "kernel/spatial/rotation.hpp"

#include <filesystem>

namespace heavesim {
namespace {

// ---------------------------------------------------------------- bodies

Matrix3 read_inertia(const NodeReader& reader) {
  double ixx, iyy, izz, ixy = 0.0, ixz = 0.0, iyz = 0.0;
  if (reader.node().is_map()) {
    reader.expect_section("inertia");
    ixx = reader["ixx"].number_in(inertia_range);
    iyy = reader["iyy"].number_in(inertia_range);
    izz = reader["izz"].number_in(inertia_range);
    for (auto [value, key] : {std::pair{&ixy, "ixy"}, std::pair{&ixz, "ixz"}, std::pair{&iyz, "iyz"}})
      if (auto product = reader.optional(key)) *value = product->number_in(inertia_range);
  } else {
    std::vector<double> values;
    if (reader.node().is_sequence())
      for (const NodeReader& item : reader.items()) values.push_back(item.number_in(inertia_range));
    if (values.size() != 3 && values.size() != 6)
      reader.fail("[ixx, iyy, izz], [ixx, iyy, izz, ixy, ixz, iyz] or a map {ixx: .., ...} (kg m^2 about the CoM)");
    ixx = values[0];
    iyy = values[1];
    izz = values[2];
    if (values.size() == 6) {
      ixy = values[3];
      ixz = values[4];
      iyz = values[5];
    }
  }
  Matrix3 inertia;
  inertia << ixx, ixy, ixz, ixy, iyy, iyz, ixz, iyz, izz;
  return inertia;
}

void read_bodies(const NodeReader& section, CaseDefinition& definition) {
  std::set<std::string> names;
  for (const NodeReader& body : section.items()) {
    body.expect_section("bodies[i]");
    const NodeReader name_reader = body["name"];
    const std::string name = name_reader.text();
    if (name == ModelBuilder::ground_name) name_reader.fail("'ground', which is reserved for the world", "another name");
    if (!names.insert(name).second) name_reader.fail("'" + name + "' a second time", "a unique body name");
    const double mass = body["mass"].number_in(mass_range);
    const Vector3 com =
        body.optional("center_of_mass") ? body["center_of_mass"].vector3_in(length_range) : Vector3::Zero();
    const Matrix3 inertia = read_inertia(body["inertia"]);
    definition.bodies.push_back(BodyDefinition{name, Inertia(mass, com, inertia), std::nullopt});
    definition.body_paths[name] = body.path();
  }
}

// ---------------------------------------------------------------- joints

/// Reads `type` and the axes it needs into a joint or loop-joint definition.
template <class Definition>
void read_joint_kind(const NodeReader& joint, Definition& def) {
  const std::string type =
      joint["type"].choice({"fixed", "revolute", "prismatic", "cylindrical", "universal", "spherical", "free"});
  def.kind = type == "fixed"         ? JointKind::fixed
             : type == "revolute"    ? JointKind::revolute
             : type == "prismatic"   ? JointKind::prismatic
             : type == "cylindrical" ? JointKind::cylindrical
             : type == "universal"   ? JointKind::universal
             : type == "spherical"   ? JointKind::spherical
                                     : JointKind::free;
  const bool axial = def.kind == JointKind::revolute || def.kind == JointKind::prismatic ||
                     def.kind == JointKind::cylindrical;
  if (axial) def.axis = joint["axis"].unit_vector3();
  if (!axial && joint.has("axis"))
    joint["axis"].fail("an axis on a " + type + " joint", "no 'axis' (only revolute, prismatic, cylindrical)");
  if (def.kind != JointKind::universal) {
    if (joint.has("axes")) joint["axes"].fail("'axes' on a " + type + " joint", "no 'axes' (only universal joints)");
    return;
  }
  const NodeReader axes = joint["axes"];
  const std::vector<NodeReader> items = axes.items();
  if (items.size() != 2) axes.fail("two unit axes [[x, y, z], [x, y, z]]");
  def.axis = items[0].unit_vector3();
  def.second_axis = items[1].unit_vector3();
  if (std::abs(def.axis.dot(def.second_axis)) > 1e-6)
    axes.fail(fmt::format("axes at {:.4g} degrees", std::acos(def.axis.dot(def.second_axis)) * 180 / M_PI),
              "perpendicular axes (a Hooke joint)");
}

/// A number, or a list of exactly `size` numbers.
JointVector read_joint_vector(const NodeReader& reader, int size) {
  JointVector values(size);
  if (reader.node().is_scalar() && size == 1) {
    values[0] = reader.number();
    return values;
  }
  const std::vector<double> numbers = reader.node().is_sequence() ? reader.numbers() : std::vector<double>{};
  if (static_cast<int>(numbers.size()) != size)
    reader.fail(size == 1 ? "a number" : fmt::format("a list of {} numbers", size));
  for (int i = 0; i < size; ++i) values[i] = numbers[i];
  return values;
}

/// Reads the raw q (nq) of a joint, checking unit quaternions.
VectorX read_configuration(const NodeReader& reader, const JointType& type) {
  const int nq = joint_nq(type);
  VectorX q = read_joint_vector(reader, nq);
  const int quaternion_offset = std::holds_alternative<SphericalJoint>(type) ? 0
                                : std::holds_alternative<FreeJoint>(type)   ? 3
                                                                             : -1;
  if (quaternion_offset >= 0 && std::abs(q.segment<4>(quaternion_offset).norm() - 1.0) > 1e-6)
    reader.fail(fmt::format("a quaternion of norm {:.6g}", q.segment<4>(quaternion_offset).norm()),
                "a unit quaternion (w, x, y, z)");
  return q;
}

JointInitialState read_initial_state(const std::optional<NodeReader>& reader, const JointType& type) {
  const int nq = joint_nq(type), nv = joint_nv(type);
  JointInitialState state;
  state.q = VectorX::Zero(nq);
  std::visit([&](const auto& joint) { joint.neutral(state.q.data()); }, type);
  state.v = VectorX::Zero(nv);
  if (!reader) return state;
  const bool spherical = std::holds_alternative<SphericalJoint>(type);
  const bool free = std::holds_alternative<FreeJoint>(type);
  if (nv == 0) reader->fail("an initial state for a fixed joint", "no 'initial' (a fixed joint has no coordinates)");
  if (free)
    reader->expect_section("initial", "free");
  else if (spherical)
    reader->expect_section("initial", "spherical");
  else
    reader->expect_section("initial");

  if (auto q = reader->optional("q")) state.q = read_configuration(*q, type);
  if (auto qd = reader->optional("qd")) state.v = read_joint_vector(*qd, nv);
  if (reader->has("q") && (reader->has("orientation") || reader->has("position")))
    reader->fail("'q' together with 'position'/'orientation'", "either raw 'q' or the named form");
  if (reader->has("qd") && (reader->has("angular_velocity") || reader->has("velocity")))
    reader->fail("'qd' together with 'velocity'/'angular_velocity'", "either raw 'qd' or the named form");

  const int quaternion_offset = free ? 3 : 0;
  Matrix3 R = Matrix3::Identity();
  if (auto orientation = reader->optional("orientation")) {
    R = read_orientation(*orientation);
    write_wxyz(Eigen::Quaterniond(R), state.q.segment<4>(quaternion_offset));
  } else if (spherical || free) {
    R = quaternion_from_wxyz(state.q.segment<4>(quaternion_offset)).toRotationMatrix();
  }
  if (auto position = reader->optional("position")) state.q.head<3>() = position->vector3_in(length_range);
  // Named velocities are given in the parent frame; the kernel's are child-side (body) axes.
  if (auto omega = reader->optional("angular_velocity")) state.v.head<3>() = R.transpose() * omega->vector3();
  if (auto velocity = reader->optional("velocity")) state.v.tail<3>() = R.transpose() * velocity->vector3();
  return state;
}

JointSpringDamper read_spring(const NodeReader& reader, const JointType& type, const std::string& type_name) {
  reader.expect_section("spring");
  const int nq = joint_nq(type), nv = joint_nv(type);
  if (std::holds_alternative<FreeJoint>(type) || nv == 0)
    reader.fail("a spring on a " + type_name + " joint", "springs on revolute, prismatic, cylindrical, universal "
                                                         "or spherical joints (use force elements for free bodies)");
  JointSpringDamper spring;
  spring.stiffness = reader.optional("stiffness") ? read_joint_vector(reader["stiffness"], nv) : JointVector::Zero(nv);
  spring.damping = reader.optional("damping") ? read_joint_vector(reader["damping"], nv) : JointVector::Zero(nv);
  for (const auto& [values, key] : {std::pair{&spring.stiffness, "stiffness"}, std::pair{&spring.damping, "damping"}})
    if ((values->array() < 0.0).any()) reader[key].fail("a negative value", "values >= 0");
  spring.rest = JointVector::Zero(nq);
  std::visit([&](const auto& joint) { joint.neutral(spring.rest.data()); }, type);
  if (auto rest = reader.optional("rest")) {
    if (std::holds_alternative<SphericalJoint>(type))
      write_wxyz(Eigen::Quaterniond(read_orientation(*rest)), spring.rest.head<4>());
    else
      spring.rest = read_joint_vector(*rest, nq);
  }
  return spring;
}

JointLimits read_limits(const NodeReader& reader, const JointType& type, const std::string& type_name) {
  reader.expect_section("limits");
  if (joint_nv(type) != 1 || !joint_has_scalar_coordinates(type))
    reader.fail("limits on a " + type_name + " joint", "limits on revolute or prismatic joints only");
  JointLimits limits;
  limits.lower = reader.number_or("lower", -INFINITY);
  limits.upper = reader.number_or("upper", INFINITY);
  if (!(limits.lower < limits.upper))
    reader.fail(fmt::format("lower = {:g} not below upper = {:g}", limits.lower, limits.upper), "lower < upper");
  limits.stiffness = reader["stiffness"].positive_number();
  limits.damping = reader.optional("damping") ? reader["damping"].non_negative_number() : 0.0;
  return limits;
}

/// parent, child and the joint frame on each.
template <class Definition>
void read_joint_placement(const NodeReader& joint, Definition& def) {
  def.parent = joint["parent"].text();
  def.child = joint["child"].text();
  def.X_parent_joint = read_frame(joint.optional("parent_frame"));
  def.X_child_joint = read_frame(joint.optional("child_frame"));
}

/// A name not used before by any joint, loop joint, constraint or force.
std::string read_unique_name(const NodeReader& item, std::set<std::string>& names) {
  const NodeReader name_reader = item["name"];
  const std::string name = name_reader.text();
  if (!names.insert(name).second) name_reader.fail("'" + name + "' a second time", "a unique name");
  return name;
}

void read_joints(const NodeReader& section, CaseDefinition& definition, std::set<std::string>& names) {
  for (const NodeReader& joint : section.items()) {
    joint.expect_section("joints[i]", "tree");
    const std::string name = read_unique_name(joint, names);
    JointDefinition def;
    def.name = name;
    read_joint_kind(joint, def);
    const JointType type = canonical_joint_type(def.kind);
    const std::string type_name = joint_type_name(type);
    read_joint_placement(joint, def);
    if (auto spring = joint.optional("spring")) def.spring = read_spring(*spring, type, type_name);
    if (auto limits = joint.optional("limits")) def.limits = read_limits(*limits, type, type_name);
    definition.initial_states[name] = read_initial_state(joint.optional("initial"), type);
    definition.item_paths[name] = joint.path();
    definition.joints.push_back(std::move(def));
  }
}

// ---------------------------------------------------------------- loops, constraints, forces

void read_loop_joints(const NodeReader& section, CaseDefinition& definition, std::set<std::string>& names) {
  for (const NodeReader& joint : section.items()) {
    joint.expect_section("joints[i]", "loop");
    LoopJointDefinition def;
    def.name = read_unique_name(joint, names);
    read_joint_kind(joint, def);
    read_joint_placement(joint, def);
    definition.item_paths[def.name] = joint.path();
    definition.loop_joints.push_back(std::move(def));
  }
}

void read_constraints(const NodeReader& section, CaseDefinition& definition, std::set<std::string>& names,
                      const ExpressionContext& expressions) {
  for (const NodeReader& item : section.items()) {
    const std::string type = item["type"].choice({"distance", "coupler", "expression"});
    const std::string name = read_unique_name(item, names);
    if (type == "distance") {
      item.expect_section("distance");
      DistanceConstraintDefinition def;
      def.name = name;
      def.body_a = item["body_a"].text();
      def.body_b = item["body_b"].text();
      if (auto point = item.optional("point_a")) def.point_a = point->vector3_in(length_range);
      if (auto point = item.optional("point_b")) def.point_b = point->vector3_in(length_range);
      def.distance = item["distance"].positive_number(length_range);
      definition.distance_constraints.push_back(std::move(def));
    } else if (type == "expression") {
      read_expression_constraint(item, name, definition, expressions);
    } else {
      item.expect_section("coupler");
      CouplerDefinition def;
      def.name = name;
      def.joint_a = item["joint_a"].text();
      def.joint_b = item["joint_b"].text();
      def.ratio = item.number_or("ratio", 1.0);
      def.offset = item.number_or("offset", 0.0);
      definition.couplers.push_back(std::move(def));
    }
    definition.item_paths[name] = item.path();
  }
}

/// drivers[i]: each item read by read_driver (app/case/driver_reader.hpp).
void read_drivers(const NodeReader& section, CaseDefinition& definition, std::set<std::string>& names,
                  const ExpressionContext& expressions) {
  for (const NodeReader& item : section.items()) {
    const std::string name = read_unique_name(item, names);
    read_driver(item, name, definition, expressions);
    definition.item_paths[name] = item.path();
  }
}

void read_forces(const NodeReader& section, CaseDefinition& definition, std::set<std::string>& names) {
  for (const NodeReader& item : section.items()) {
    const ForceKind& kind = force_kind(item["type"].choice(force_kind_names()));
    kind.read(item, std::string(kind.type), read_unique_name(item, names), definition);
  }
}

// ---------------------------------------------------------------- solver, output

/// Refuses at `key` a run of `count` steps or samples `spacing` apart (`what`: "steps",
/// "output samples") that it cannot do: beyond RunLimits::largest_count or too fine for
/// the clock to resolve (t + spacing == t: it would never advance) in any case; beyond
/// `limit` unless large runs are allowed.
void check_run_count(const NodeReader& key, const CaseDefinition& definition, double spacing, double limit,
                     const std::string& what) {
  const SolverSettings& solver = definition.solver;
  const double duration = solver.t_end - solver.t_start, count = duration / spacing;
  const double clock = std::max(std::abs(solver.t_start), std::abs(solver.t_end));
  const double resolution = 1e3 * std::numeric_limits<double>::epsilon() * clock;
  const std::string found = fmt::format("{:g} s, {:.3g} {} over the {:g} s run", spacing, count, what, duration);
  if (!(count <= RunLimits::largest_count) || spacing < resolution)
    key.fail(found, fmt::format("a spacing of {:.3g} s or more (no run can do more: at most {:g} {}, and at t = {:g} s "
                                "the clock resolves {:.3g} s)",
                                std::max(resolution, duration / RunLimits::largest_count), RunLimits::largest_count,
                                what, clock, resolution));
  if (count > limit && !definition.limits.allow_large_runs)
    key.fail(found, fmt::format("at most {:g} {} (a spacing of {:.3g} s or more), or --allow-large-runs for a run "
                                "meant to be this large",
                                limit, what, duration / limit));
}

/// The `equilibrium` section: the static equilibrium solve's settings.
void read_equilibrium(const NodeReader& reader, CaseDefinition& definition) {
  reader.expect_section("equilibrium");
  if (auto tolerance = reader.optional("tolerance")) {
    definition.equilibrium.tolerance = tolerance->positive_number();
    if (definition.equilibrium.tolerance < 1e-15 || definition.equilibrium.tolerance > 1e-2)
      tolerance->fail(fmt::format("{:g}", definition.equilibrium.tolerance), "a tolerance from 1e-15 to 1e-2");
  }
  if (auto iterations = reader.optional("max_iterations")) {
    const long value = iterations->integer();
    if (value < 1 || value > 1000) iterations->fail(std::to_string(value), "1 to 1000 Newton iterations");
    definition.equilibrium.max_iterations = static_cast<int>(value);
  }
}

void read_solver(const NodeReader& reader, CaseDefinition& definition) {
  reader.expect_section("solver");
  SolverSettings& solver = definition.solver;
  if (auto integrator = reader.optional("integrator")) {
    const std::string method = integrator->choice({"rk4", "dopri5", "verner6", "fehlberg8", "ida", "hht", "contact"});
    solver.integrator.method = method == "rk4"         ? IntegrationMethod::rk4
                               : method == "dopri5"    ? IntegrationMethod::dopri5
                               : method == "verner6"   ? IntegrationMethod::verner6
                               : method == "fehlberg8" ? IntegrationMethod::fehlberg8
                               : method == "hht"       ? IntegrationMethod::hht
                               : method == "contact"   ? IntegrationMethod::contact
                                                       : IntegrationMethod::ida;
  }
  solver.t_start = reader.number_or("t_start", 0.0);
  solver.t_end = reader["t_end"].number();
  if (!(solver.t_end > solver.t_start))
    reader["t_end"].fail(fmt::format("t_end = {:g} not after t_start = {:g}", solver.t_end, solver.t_start),
                         "t_end > t_start (seconds)");
  if (auto step = reader.optional("step")) {
    solver.integrator.step = step->positive_number();
    if (solver.integrator.step > solver.t_end - solver.t_start)
      step->fail(fmt::format("a step of {:g} s longer than the run", solver.integrator.step), "step <= t_end - t_start");
    if (is_fixed_step(solver.integrator.method))
      check_run_count(*step, definition, solver.integrator.step, RunLimits::max_steps, "fixed steps");
  } else if (is_fixed_step(solver.integrator.method)) {
    reader["step"];  // required for the fixed-step methods: raises the missing-key error
  }
  if (auto alpha = reader.optional("hht_alpha")) {
    solver.integrator.hht_alpha = alpha->number();
    if (solver.integrator.hht_alpha < -1.0 / 3.0 || solver.integrator.hht_alpha > 0.0)
      alpha->fail(fmt::format("{:g}", solver.integrator.hht_alpha),
                  "a value in [-1/3, 0] (0: no numerical damping; -1/3: the most)");
  }
  if (auto rtol = reader.optional("rtol")) {
    solver.integrator.relative_tolerance = rtol->positive_number();
    if (solver.integrator.relative_tolerance >= 1.0) rtol->fail("a relative tolerance >= 1", "0 < rtol < 1");
    if (solver.integrator.relative_tolerance < 1e-15) rtol->fail("a tolerance below machine precision", "rtol >= 1e-15");
  }
  if (auto atol = reader.optional("atol")) solver.integrator.absolute_tolerance = atol->positive_number();
  if (auto max_step = reader.optional("max_step")) {
    solver.integrator.max_step = max_step->non_negative_number();  // 0: no bound
    if (solver.integrator.max_step > 0.0)
      check_run_count(*max_step, definition, solver.integrator.max_step, RunLimits::max_steps, "adaptive steps (at least)");
  }
  if (auto max_steps = reader.optional("max_steps")) {
    solver.integrator.max_steps_per_output = max_steps->integer();
    if (solver.integrator.max_steps_per_output <= 0) max_steps->fail("a positive whole number");
  }
  if (auto linear_solver = reader.optional("linear_solver"))
    solver.integrator.linear_solver =
        linear_solver->choice({"dense", "sparse"}) == "dense" ? LinearSolver::dense : LinearSolver::sparse;
  if (auto tolerance = reader.optional("constraint_tolerance")) {
    solver.integrator.constraint_tolerance = tolerance->positive_number();
    if (solver.integrator.constraint_tolerance < 1e-14)
      tolerance->fail("a tolerance below round-off of the constraint equations", "constraint_tolerance >= 1e-14");
  }
  if (auto dynamics = reader.optional("dynamics"))
    solver.dynamics = dynamics->choice({"articulated_body", "composite_rigid_body"}) == "articulated_body"
                          ? ForwardDynamicsMethod::articulated_body
                          : ForwardDynamicsMethod::composite_rigid_body;
}

/// Every output sample is at least one step of any method: their number is refused at
/// output.interval (or at solver.t_end when the interval is the default), like steps.
void read_output(const std::optional<NodeReader>& reader, const NodeReader& solver, CaseDefinition& definition) {
  OutputSettings& output = definition.output;
  const double duration = definition.solver.t_end - definition.solver.t_start;
  output.interval = std::min(0.01, duration / 100.0);
  output.evaluate_after = definition.solver.t_start + 0.5 * duration;
  const std::optional<NodeReader> interval = reader ? reader->optional("interval") : std::nullopt;
  if (!interval)
    check_run_count(solver["t_end"], definition, output.interval, RunLimits::max_steps,
                    "output samples (the default interval)");
  if (!reader) return;
  reader->expect_section("output");
  if (auto evaluate_after = reader->optional("evaluate_after")) {
    output.evaluate_after = evaluate_after->number();
    if (output.evaluate_after < definition.solver.t_start || output.evaluate_after >= definition.solver.t_end)
      evaluate_after->fail(fmt::format("{:g} s, outside the run", output.evaluate_after), "t_start <= evaluate_after < t_end");
  }
  if (interval) {
    output.interval = interval->positive_number();
    if (output.interval > duration)
      interval->fail(fmt::format("an interval of {:g} s longer than the run", output.interval),
                     "interval <= t_end - t_start");
    check_run_count(*interval, definition, output.interval, RunLimits::max_steps, "output samples");
  }
  if (auto channels = reader->optional("channels")) {
    output.bodies = output.joints = output.reactions = output.energy = output.forces = false;
    for (const NodeReader& channel : channels->items()) {
      const std::string which = channel.choice({"bodies", "joints", "reactions", "energy", "forces"});
      output.forces |= which == "forces";
      output.bodies |= which == "bodies";
      output.joints |= which == "joints";
      output.reactions |= which == "reactions";
      output.energy |= which == "energy";
    }
  }
}

/// The `kinematics` section: the settings of a kinematic analysis (kinematic_analysis.hpp).
void read_kinematics(const NodeReader& reader, KinematicSettings& settings) {
  reader.expect_section("kinematics");
  for (const char* key : {"equation_tolerance", "solution_tolerance"}) {
    const std::optional<NodeReader> tolerance = reader.optional(key);
    if (!tolerance) continue;
    const double value = tolerance->positive_number();
    if (value < 1e-14) tolerance->fail("a tolerance below round-off of the constraint equations", ">= 1e-14");
    (std::string(key) == "equation_tolerance" ? settings.equation_tolerance : settings.solution_tolerance) = value;
  }
  if (auto iterations = reader.optional("max_iterations")) {
    const long value = iterations->integer();
    if (value < 1 || value > 1000) iterations->fail(fmt::format("{}", value), "a whole number from 1 to 1000");
    settings.max_iterations = static_cast<int>(value);
  }
  if (auto weighting = reader.optional("weighting"))
    settings.weighting = weighting->choice({"mass", "unit"}) == "mass" ? MotionWeighting::mass : MotionWeighting::unit;
  if (auto ratio = reader.optional("singular_ratio")) {
    settings.singular_ratio = ratio->positive_number();
    if (settings.singular_ratio >= 1.0) ratio->fail(fmt::format("{:g}", settings.singular_ratio), "0 < singular_ratio < 1");
  }
}

/// Every key's position by key path, in the reader's spelling (a.b, a[2].c).
void record_sources(const CaseNode& node, const std::string& path, std::map<std::string, SourceLocation>& sources) {
  if (!path.empty()) sources[path] = node.location;
  if (node.is_map())
    for (const CaseNode::Entry& entry : node.entries)
      record_sources(entry.value, path.empty() ? entry.key : path + "." + entry.key, sources);
  else if (node.is_sequence())
    for (std::size_t i = 0; i < node.items.size(); ++i)
      record_sources(node.items[i], path + "[" + std::to_string(i) + "]", sources);
}

void read_parameters(const std::optional<NodeReader>& reader, ExpressionContext& expressions) {
  if (!reader) return;
  if (!reader->node().is_map()) reader->fail("a map of name: value");
  for (const CaseNode::Entry& entry : reader->node().entries) {
    const NodeReader value = (*reader)[entry.key];
    // A parameter becomes a muParser variable: its name is checked against the parser's
    // rules and reserved names here, at its key, before muParser sees it.
    if (const std::string problem = parameter_name_problem(entry.key); !problem.empty())
      throw InputError(entry.key_location, value.path(), "parameter name '" + entry.key + "', " + problem,
                       parameter_name_expectation());
    expressions.define(entry.key, value.number());
  }
}

}  // namespace

CaseNode resolved_case_tree(const std::string& path, const std::vector<std::string>& overrides) {
  CaseNode tree = load_case_tree(path);
  for (const std::string& assignment : overrides) apply_override(tree, assignment);
  return tree;
}

CaseDefinition load_case(const std::string& path, const std::vector<std::string>& overrides, bool allow_large_runs) {
  return read_case(resolved_case_tree(path, overrides), path, allow_large_runs);
}

CaseDefinition read_case(const CaseNode& tree, const std::string& path, bool allow_large_runs) {
  CaseDefinition definition;
  definition.source_path = path;
  definition.limits.allow_large_runs = allow_large_runs;
  definition.resolved_yaml = to_yaml_text(tree);
  record_sources(tree, "", definition.sources);
  ExpressionContext expressions;
  const NodeReader root(tree, "", expressions);
  root.expect_section("top-level");

  definition.name = root.optional("name") ? root["name"].text() : std::filesystem::path(path).stem().string();
  if (auto description = root.optional("description")) definition.description = description->text();
  read_parameters(root.optional("parameters"), expressions);
  if (auto environment = root.optional("environment")) {
    environment->expect_section("environment");
    if (auto gravity = environment->optional("gravity")) definition.gravity = gravity->vector3();
    if (auto density = environment->optional("water_density")) definition.water.density = density->positive_number();
    if (auto depth = environment->optional("water_depth")) {
      if (!(depth->node().is_scalar() && depth->node().scalar == "infinite"))
        definition.water.depth = depth->positive_number();
    }
  }
  if (auto waves = root.optional("waves")) read_waves(*waves, definition);
  read_bodies(root["bodies"], definition);
  std::set<std::string> names;  // joints, loop joints, constraints and forces share one name space
  read_joints(root["joints"], definition, names);
  if (auto section = root.optional("loop_joints")) read_loop_joints(*section, definition, names);
  if (auto section = root.optional("constraints")) read_constraints(*section, definition, names, expressions);
  if (auto section = root.optional("drivers")) read_drivers(*section, definition, names, expressions);
  if (auto section = root.optional("forces")) read_forces(*section, definition, names);
  if (auto section = root.optional("contacts")) read_contacts(*section, definition);
  read_solver(root["solver"], definition);
  // Contacts run under `contact` (velocity-level stepping); under `ida` joint stops alone
  // (event-located). The other integrators take the penalty models only.
  const IntegrationMethod method = definition.solver.integrator.method;
  const bool stops_only = definition.contacts.geometries.empty() && definition.contacts.pairs.empty() &&
                          definition.contacts.lines.empty();
  if (!definition.contacts.empty() && method != IntegrationMethod::contact &&
      !(method == IntegrationMethod::ida && stops_only)) {
    const std::optional<NodeReader> integrator = root["solver"].optional("integrator");
    (integrator ? *integrator : root["contacts"])
        .fail("contacts with the integrator '" + integration_method_name(method) + "'" +
                  (method == IntegrationMethod::ida ? " (shapes or lines: ida locates joint stops only)" : ""),
              "solver.integrator: contact (velocity-level contact stepping: shapes, lines and stops), or ida for "
              "joint stops alone (event-located impacts)");
  }
  read_output(root.optional("output"), root["solver"], definition);
  if (auto section = root.optional("kinematics")) read_kinematics(*section, definition.kinematics);
  if (auto initial = root.optional("initial")) definition.initial_static = initial->choice({"given", "static"}) == "static";
  if (auto section = root.optional("equilibrium")) read_equilibrium(*section, definition);
  check_motions_over_run(definition, expressions, root.optional("drivers"));
  check_distance_drivers_over_run(definition, root.optional("drivers"));
  return definition;
}

SourceLocation CaseDefinition::location_of(const std::string& key_path) const {
  std::string path = key_path;
  if (auto it = sources.find(path); it != sources.end()) return it->second;
  while (true) {
    const std::size_t cut = path.find_last_of(".[");
    if (cut == std::string::npos || cut == 0) break;
    path.resize(cut);
    if (auto name = sources.find(path + ".name"); name != sources.end()) return name->second;
    if (auto it = sources.find(path); it != sources.end()) return it->second;
  }
  return SourceLocation{source_path, 0, 0};
}

InputError CaseDefinition::error_at(const std::string& key_path, const std::string& found,
                                    const std::string& expected) const {
  return InputError(location_of(key_path), key_path, found, expected);
}

InputError CaseDefinition::item_error(const std::string& item, const std::string& field, const std::string& found,
                                      const std::string& expected) const {
  return error_at(item_paths.at(item) + "." + field, found, expected);
}

InputError to_input_error(const CaseDefinition& definition, const ModelError& error) {
  const auto& paths =
      error.kind() == ModelError::ItemKind::body ? definition.body_paths : definition.item_paths;
  const auto it = paths.find(error.item());
  if (it == paths.end())
    return InputError(SourceLocation{definition.source_path, 0, 0}, "", error.found(), error.expected());
  return definition.error_at(it->second + "." + error.field(), error.found(), error.expected());
}

InputError to_input_error(const CaseDefinition& definition, const std::string& base_path, const ParameterError& error,
                          const std::map<std::string, std::string>& key_of_field) {
  const auto renamed = key_of_field.find(error.field());
  const std::string& key = renamed != key_of_field.end() ? renamed->second : error.field();
  return definition.error_at(base_path.empty() ? key : base_path + "." + key, error.found(), error.expected());
}

}  // namespace heavesim
