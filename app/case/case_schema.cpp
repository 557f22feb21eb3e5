#include "app/case/case_schema.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "app/forces/force_registry.hpp"

namespace heavesim {
namespace {

constexpr KeySpec root_keys[] = {
    {"name", "text", "–", "the file name without `.yaml`", "case name; names the result file"},
    {"description", "text", "–", "–", "free text"},
    {"include", "text or list", "–", "none", "files merged first (consumed by the merge, app/case/case_merge.cpp)",
     "composition"},
    {"parameters", "map", "–", "none", "name: value numbers usable in later expressions"},
    {"environment", "map", "–", "see below", "gravity and water"},
    {"waves", "map", "–", "none", "the incident sea"},
    {"bodies", "list", "–", "required", "the bodies"},
    {"joints", "list", "–", "required", "the spanning tree (may be empty)"},
    {"loop_joints", "list", "–", "none", "joints that close kinematic loops"},
    {"constraints", "list", "–", "none", "distance, coupler and expression constraints"},
    {"drivers", "list", "–", "none", "prescribed motion of joint coordinates, body points, distances, angles"},
    {"forces", "list", "–", "none", "force elements"},
    {"contacts", "map", "–", "none", "contact shapes, pairs, joint stops and lines (integrator `contact`; stops alone: `ida`)"},
    {"solver", "map", "–", "required", "integration settings"},
    {"output", "map", "–", "everything", "what to record and how often"},
    {"kinematics", "map", "–", "see below", "settings of `heavesim kinematics`"},
    {"initial", "choice", "–", "`given`", "`given`: start from the joints' `initial` values; `static`: from the static equilibrium"},
    {"equilibrium", "map", "–", "see below", "settings of the static equilibrium solve"},
};

constexpr KeySpec equilibrium_keys[] = {
    {"tolerance", "number", "–", "1e-10", "max |Q + J^T lambda| relative to the largest load; max |Phi| (m or rad); max |dz/dt|"},
    {"max_iterations", "number", "–", "50", "Newton iterations"},
};

constexpr KeySpec environment_keys[] = {
    {"gravity", "vector", "m/s²", "`[0, 0, -9.81]`", "gravitational acceleration, world frame"},
    {"water_density", "number", "kg/m³", "1025", "rho of the hydro data and meshes"},
    {"water_depth", "number", "m", "`infinite`", "h for the dispersion relation"},
};

constexpr KeySpec waves_keys[] = {
    {"type", "choice", "–", "required", "regular, jonswap, pierson_moskowitz or none"},
    {"amplitude", "number", "m", "required (regular)", "a = H/2", "regular"},
    {"period", "number", "s", "required (regular)", "T", "regular"},
    {"hs", "number", "m", "required (irregular)", "significant wave height", "irregular"},
    {"tp", "number", "s", "required (irregular)", "peak period", "irregular"},
    {"gamma", "number", "–", "3.3", "JONSWAP peak enhancement", "irregular"},
    {"components", "number", "–", "200", "number of regular components", "irregular"},
    {"seed", "number", "–", "1", "seed of the random phases", "irregular"},
    {"discretization", "choice", "–", "`equal_energy`", "equal_energy or equal_spacing", "irregular"},
    {"min_frequency", "number", "rad/s", "0.1", "lower end of the component band", "irregular"},
    {"max_frequency", "number", "rad/s", "3.0", "upper end of the component band", "irregular"},
    {"heading", "number", "rad", "0", "direction the waves travel", "regular irregular"},
    {"phase", "number", "rad", "0", "phase of the regular wave", "regular"},
    {"ramp", "number or map", "s, or map", "none", "start-up ramp", "regular irregular"},
};

constexpr KeySpec body_keys[] = {
    {"name", "text", "–", "required", "unique; not ground"},
    {"mass", "number", "kg", "required", "> 0, or 0 for a massless connector"},
    {"center_of_mass", "vector", "m", "`[0, 0, 0]`", "CoM in the body frame"},
    {"inertia", "list or map", "kg·m²", "required", "about the CoM, body axes"},
    {"description", "text", "–", "–", "free text"},
};

constexpr KeySpec joint_keys[] = {
    {"name", "text", "–", "required", "unique"},
    {"type", "choice", "–", "required", "fixed, revolute, prismatic, cylindrical, universal, spherical, free"},
    {"parent", "text", "–", "required", "parent body or ground"},
    {"child", "text", "–", "required", "child body"},
    {"parent_frame", "map", "–", "identity", "the joint frame in the parent body frame"},
    {"child_frame", "map", "–", "identity", "the joint frame in the child body frame"},
    {"axis", "vector", "–", "required for revolute, prismatic, cylindrical", "unit axis in the joint frame"},
    {"axes", "list", "–", "required for universal", "two perpendicular unit axes"},
    {"initial", "map", "–", "neutral, at rest", "initial state", "tree"},
    {"spring", "map", "–", "none", "linear spring-damper on the coordinates", "tree"},
    {"limits", "map", "–", "none", "soft end stops", "tree"},
    {"description", "text", "–", "–", "free text"},
};

constexpr KeySpec driver_keys[] = {
    {"name", "text", "–", "required", "unique"},
    {"type", "choice", "–", "`joint`", "joint, absolute, distance or angle"},
    {"joint", "text", "–", "required", "the driven joint"},
    {"coordinate", "number", "–", "0", "which of its coordinates"},
    {"position", "expression", "m or rad", "required (or `table`)", "f(t)"},
    {"velocity", "expression", "m/s or rad/s", "exact, from `position`", "f'(t)"},
    {"acceleration", "expression", "m/s² or rad/s²", "exact, from `position`", "f''(t)"},
    {"table", "text", "–", "none", "CSV file of samples (time s, value) instead of `position`"},
    {"description", "text", "–", "–", "free text"},
};

constexpr KeySpec absolute_driver_keys[] = {
    {"name", "text", "–", "required", "unique"},
    {"type", "choice", "–", "required", "`absolute`"},
    {"body", "text", "–", "required", "the driven body"},
    {"point", "vector", "m", "`[0, 0, 0]`", "the driven point, body frame"},
    {"direction", "vector", "–", "required", "unit vector, world frame: direction . p_world(point) = f(t)"},
    {"position", "expression", "m", "required (or `table`)", "f(t)"},
    {"velocity", "expression", "m/s", "exact, from `position`", "f'(t)"},
    {"acceleration", "expression", "m/s²", "exact, from `position`", "f''(t)"},
    {"table", "text", "–", "none", "CSV file of samples (time s, value) instead of `position`"},
    {"description", "text", "–", "–", "free text"},
};

constexpr KeySpec distance_driver_keys[] = {
    {"name", "text", "–", "required", "unique"},
    {"type", "choice", "–", "required", "`distance`"},
    {"body_a", "text", "–", "required", "first body (`ground` allowed)"},
    {"point_a", "vector", "m", "`[0, 0, 0]`", "point on body a, its frame"},
    {"body_b", "text", "–", "required", "second body (`ground` allowed)"},
    {"point_b", "vector", "m", "`[0, 0, 0]`", "point on body b, its frame"},
    {"position", "expression", "m", "required (or `table`)", "f(t) > 0: the distance between the points"},
    {"velocity", "expression", "m/s", "exact, from `position`", "f'(t)"},
    {"acceleration", "expression", "m/s²", "exact, from `position`", "f''(t)"},
    {"table", "text", "–", "none", "CSV file of samples (time s, value) instead of `position`"},
    {"description", "text", "–", "–", "free text"},
};

constexpr KeySpec angle_driver_keys[] = {
    {"name", "text", "–", "required", "unique"},
    {"type", "choice", "–", "required", "`angle`"},
    {"body_a", "text", "–", "required", "first body (`ground` allowed)"},
    {"frame_a", "map", "–", "identity", "frame a in body a's frame (`frame` keys)"},
    {"body_b", "text", "–", "required", "second body (`ground` allowed)"},
    {"frame_b", "map", "–", "identity", "frame b in body b's frame (`frame` keys)"},
    {"position", "expression", "rad", "required (or `table`)", "f(t): the angle of frame b's x about frame a's z, from frame a's x"},
    {"velocity", "expression", "rad/s", "exact, from `position`", "f'(t)"},
    {"acceleration", "expression", "rad/s²", "exact, from `position`", "f''(t)"},
    {"table", "text", "–", "none", "CSV file of samples (time s, value) instead of `position`"},
    {"description", "text", "–", "–", "free text"},
};

constexpr KeySpec solver_keys[] = {
    {"integrator", "choice", "–", "`ida`", "rk4, dopri5, verner6, fehlberg8, ida, hht, contact"},
    {"t_start", "number", "s", "0", "start time"},
    {"t_end", "number", "s", "required", "end time"},
    {"step", "number", "s", "required for `rk4`, `hht` and `contact`", "fixed step"},
    {"rtol", "number", "–", "1e-8", "relative tolerance"},
    {"atol", "number", "–", "1e-10", "absolute tolerance"},
    {"max_step", "number", "s", "0 (no limit)", "largest adaptive step"},
    {"max_steps", "number", "–", "100000", "most steps between two outputs"},
    {"dynamics", "choice", "–", "`articulated_body`", "articulated_body or composite_rigid_body"},
    {"linear_solver", "choice", "–", "`dense`", "dense or sparse"},
    {"constraint_tolerance", "number", "m or rad", "1e-10", "largest |Phi| accepted"},
    {"hht_alpha", "number", "–", "0", "HHT numerical damping"},
};

constexpr KeySpec contacts_keys[] = {
    {"margin", "number", "m", "0.001", "points within this gap stay in the problem"},
    {"geometries", "list", "–", "none", "shapes on bodies"},
    {"pairs", "list", "–", "none", "geometry pairs checked for contact"},
    {"joint_stops", "list", "–", "none", "one-sided stops on 1-DoF joints"},
    {"lines", "list", "–", "none", "lines that carry tension only (hoist lines, ropes)"},
};

constexpr KeySpec contact_geometry_keys[] = {
    {"name", "text", "–", "required", "unique among the geometries"},
    {"body", "text", "–", "required", "the body it is fixed on (`ground` allowed)"},
    {"shape", "choice", "–", "required", "sphere, box, cylinder or plane"},
    {"frame", "map", "–", "identity", "the shape frame in the body frame (`frame` keys)"},
    {"radius", "number", "m", "required: sphere, cylinder", "radius (> 0)"},
    {"half_length", "number", "m", "required: cylinder", "half length along the frame's z (> 0)"},
    {"half_extents", "list", "m", "required: box", "half sizes along x, y, z (> 0)"},
};

constexpr KeySpec contact_pair_keys[] = {
    {"name", "text", "–", "`<a>_on_<b>`", "names the output channels"},
    {"a", "text", "–", "required", "geometry pushed along the normal"},
    {"b", "text", "–", "required", "the other geometry"},
    {"friction_coefficient", "number", "–", "0", "Coulomb mu (≥ 0)"},
    {"restitution", "number", "–", "0", "Newton's e in [0, 1]"},
    {"friction_directions", "number", "–", "2", "tangents per point, 2..16: a friction polygon of 2k faces"},
    {"torsional_friction", "number", "m", "0", "spin moment <= this x normal force, per point"},
};

constexpr KeySpec joint_stop_keys[] = {
    {"name", "text", "–", "`<joint>_stop`", "names the output channel"},
    {"joint", "text", "–", "required", "a revolute or prismatic joint"},
    {"lower", "number", "m or rad", "none (one bound required)", "lower bound"},
    {"upper", "number", "m or rad", "none", "upper bound (> lower)"},
    {"restitution", "number", "–", "0", "Newton's e in [0, 1]"},
};

constexpr KeySpec tension_line_keys[] = {
    {"name", "text", "–", "`<body_a>_to_<body_b>`", "names the output channels"},
    {"body_a", "text", "–", "required", "body at one end (`ground` allowed)"},
    {"point_a", "vector", "m", "`[0, 0, 0]`", "the end on body a, its frame"},
    {"body_b", "text", "–", "required", "body at the other end"},
    {"point_b", "vector", "m", "`[0, 0, 0]`", "the end on body b, its frame"},
    {"length", "number", "m", "required", "> 0: the ends stay at most this far apart"},
    {"restitution", "number", "–", "0", "Newton's e in [0, 1] when the line snaps taut"},
};

constexpr KeySpec output_keys[] = {
    {"interval", "number", "s", "min(0.01, duration/100)", "time between samples"},
    {"channels", "list", "–", "all", "bodies, joints, reactions, energy, forces"},
    {"evaluate_after", "number", "s", "t_start + duration/2", "start of the summary window"},
};

constexpr KeySpec kinematics_keys[] = {
    {"equation_tolerance", "number", "m or rad", "1e-10", "largest max |Phi| accepted at a time point"},
    {"solution_tolerance", "number", "m or rad", "1e-10", "largest max |dq| of the last Newton step accepted"},
    {"max_iterations", "number", "–", "25", "Newton iterations per time point"},
    {"weighting", "choice", "–", "`mass`", "mass or unit: the metric of the minimum-norm motion"},
    {"singular_ratio", "number", "–", "1e-8", "smallest/largest singular value of J reported as singular"},
};

constexpr KeySpec distance_keys[] = {
    {"name", "text", "–", "required", "unique"},
    {"type", "choice", "–", "required", "`distance`"},
    {"body_a", "text", "–", "required", "first body (`ground` allowed)"},
    {"point_a", "vector", "m", "`[0, 0, 0]`", "point on body a, its frame"},
    {"body_b", "text", "–", "required", "second body"},
    {"point_b", "vector", "m", "`[0, 0, 0]`", "point on body b, its frame"},
    {"distance", "number", "m", "required", "> 0, kept between the points (a massless rod with ball ends)"},
    {"description", "text", "–", "–", "free text"},
};

constexpr KeySpec coupler_keys[] = {
    {"name", "text", "–", "required", "unique"},
    {"type", "choice", "–", "required", "`coupler`"},
    {"joint_a", "text", "–", "required", "a revolute or prismatic joint of the tree"},
    {"joint_b", "text", "–", "required", "another one"},
    {"ratio", "number", "–", "1", "q_a = ratio q_b + offset"},
    {"offset", "number", "rad or m", "0", "offset"},
    {"description", "text", "–", "–", "free text"},
};

constexpr KeySpec expression_constraint_keys[] = {
    {"name", "text", "–", "required", "unique"},
    {"type", "choice", "–", "required", "`expression`"},
    {"expression", "text", "–", "required", "f(x, t), kept at 0: the variables, t and the case parameters"},
    {"variables", "map", "–", "required", "symbol: joint name (its only coordinate), or symbol: {joint, coordinate}"},
    {"description", "text", "–", "–", "free text"},
};

constexpr KeySpec expression_variable_keys[] = {
    {"joint", "text", "–", "required", "a revolute, prismatic, cylindrical or universal joint of the tree"},
    {"coordinate", "number", "–", "its only one", "which of its coordinates (required when it has two)"},
};

constexpr KeySpec frame_keys[] = {
    {"position", "vector", "m", "`[0, 0, 0]`", "origin of the frame in its body frame"},
    {"orientation", "map", "–", "identity", "see Orientations"},
};

constexpr KeySpec orientation_keys[] = {
    {"axis", "vector", "–", "one of four forms", "unit rotation axis (with `angle`)"},
    {"angle", "number", "rad", "with `axis`", "rotation angle"},
    {"rpy", "vector", "rad", "one of four forms", "[roll, pitch, yaw]: R = Rz(yaw) Ry(pitch) Rx(roll)"},
    {"quaternion", "vector", "–", "one of four forms", "unit quaternion [w, x, y, z]"},
    {"matrix", "list", "–", "one of four forms", "rotation matrix, 3 rows"},
};

constexpr KeySpec inertia_keys[] = {
    {"ixx", "number", "kg·m²", "required", "tensor entry (0, 0)"},
    {"iyy", "number", "kg·m²", "required", "tensor entry (1, 1)"},
    {"izz", "number", "kg·m²", "required", "tensor entry (2, 2)"},
    {"ixy", "number", "kg·m²", "0", "tensor entry (0, 1)"},
    {"ixz", "number", "kg·m²", "0", "tensor entry (0, 2)"},
    {"iyz", "number", "kg·m²", "0", "tensor entry (1, 2)"},
};

constexpr KeySpec initial_keys[] = {
    {"q", "number or list", "m, rad or quaternion", "neutral", "raw joint coordinates"},
    {"qd", "number or list", "m/s or rad/s", "0", "raw joint speeds"},
    {"position", "vector", "m", "`[0, 0, 0]`", "free: origin of the child-side frame", "free"},
    {"orientation", "map", "–", "identity", "free, spherical: see Orientations", "free spherical"},
    {"angular_velocity", "vector", "rad/s", "`[0, 0, 0]`", "free, spherical: parent-side axes", "free spherical"},
    {"velocity", "vector", "m/s", "`[0, 0, 0]`", "free: parent-side axes", "free"},
};

constexpr KeySpec spring_keys[] = {
    {"stiffness", "number or list", "N/m or N·m/rad", "0", "k per coordinate (≥ 0)"},
    {"damping", "number or list", "N·s/m or N·m·s/rad", "0", "c per coordinate (≥ 0)"},
    {"rest", "number, list or orientation", "m or rad", "neutral", "q_rest (spherical: an orientation)"},
};

constexpr KeySpec limits_keys[] = {
    {"lower", "number", "m or rad", "none", "lower stop"},
    {"upper", "number", "m or rad", "none", "upper stop (> lower)"},
    {"stiffness", "number", "N/m or N·m/rad", "required", "stop stiffness (> 0)"},
    {"damping", "number", "N·s/m or N·m·s/rad", "0", "stop damping (≥ 0)"},
};

constexpr KeySpec ramp_keys[] = {
    {"kind", "choice", "–", "required", "`cosine`, `tanh` or `none`"},
    {"duration", "number", "s", "required unless `kind: none`", "t_r (> 0)"},
};

/// The sections of everything but the force kinds, whose keys (and nested sections) the
/// kinds hold (app/forces/, through the registry).
constexpr SchemaSection fixed_sections[] = {
    {"top-level", root_keys},
    {"environment", environment_keys},
    {"waves", waves_keys},
    {"ramp", ramp_keys},
    {"bodies[i]", body_keys},
    {"inertia", inertia_keys},
    {"joints[i]", joint_keys},
    {"frame", frame_keys},
    {"initial", initial_keys},
    {"spring", spring_keys},
    {"limits", limits_keys},
    {"orientation", orientation_keys},
    {"distance", distance_keys},
    {"coupler", coupler_keys},
    {"expression_constraint", expression_constraint_keys},
    {"expression_variable", expression_variable_keys},
    {"drivers[i]", driver_keys},
    {"absolute_driver", absolute_driver_keys},
    {"distance_driver", distance_driver_keys},
    {"angle_driver", angle_driver_keys},
    {"contacts", contacts_keys},
    {"contact_geometry", contact_geometry_keys},
    {"contact_pair", contact_pair_keys},
    {"joint_stop", joint_stop_keys},
    {"tension_line", tension_line_keys},
    {"solver", solver_keys},
    {"output", output_keys},
    {"kinematics", kinematics_keys},
    {"equilibrium", equilibrium_keys},
};

bool in_form(std::string_view forms, std::string_view form) {
  for (std::size_t start = 0; start <= forms.size();) {
    const std::size_t end = std::min(forms.find(' ', start), forms.size());
    if (forms.substr(start, end - start) == form) return true;
    start = end + 1;
  }
  return false;
}

}  // namespace

std::span<const SchemaSection> case_schema() {
  static const std::vector<SchemaSection> sections = [] {
    std::vector<SchemaSection> all(std::begin(fixed_sections), std::end(fixed_sections));
    for (const ForceKind& kind : force_kinds()) {
      all.push_back({kind.type, kind.keys()});
      // A kind's nested sections; those two kinds share (a compensator's stroke) once.
      for (const SchemaSection& section : kind.sub_sections())
        if (std::none_of(all.begin(), all.end(), [&](const SchemaSection& s) { return s.name == section.name; }))
          all.push_back(section);
    }
    return all;
  }();
  return sections;
}

std::span<const KeySpec> schema_keys(std::string_view section) {
  for (const SchemaSection& s : case_schema())
    if (s.name == section) return s.keys;
  throw std::out_of_range("no schema section '" + std::string(section) + "'");
}

std::vector<std::string_view> accepted_keys(std::string_view section, std::string_view form) {
  std::vector<std::string_view> keys;
  for (const KeySpec& spec : schema_keys(section))
    if (spec.forms.empty() || (!form.empty() && in_form(spec.forms, form))) keys.push_back(spec.key);
  return keys;
}

}  // namespace heavesim
