#pragma once
// An MKSim model as a heavesim case (docs/mksim-format.md, "Mapping"): bodies of 1 kg
// and 1 kg m^2 about their centre of gravity, a breadth-first spanning tree of the joints
// from the ground as `joints` (initial coordinates from the given configuration), the
// other joints as `loop_joints`, drivers as absolute drivers, SYSTEM as the solver,
// output and kinematics settings. The YAML is written by yaml-cpp's emitter.
#include <string>
#include <vector>

#include "app/mksim/mksim_model.hpp"

namespace heavesim::mksim {

/// MKSim's own count (the seed's model summary): 7 Cartesian coordinates per body (the
/// position of its centre of gravity and 4 Euler parameters), the ground included; one
/// normalization equation per body, 6 ground equations, Haug's count per joint, one per
/// driver.
struct Count {
  int bodies = 0;
  int coordinates = 0;
  int normal = 0;
  int ground = 6;
  int joint_equations = 0;
  int drivers = 0;
  int equations() const { return normal + ground + joint_equations + drivers; }
  int dof() const { return coordinates - equations(); }
  std::vector<std::string> joint_terms;  // "revolute rev1: 5", in file order
  /// One paragraph, as printed by the import and written at the top of the case.
  std::string summary() const;
};

Count count(const Model& model);

/// heavesim's count of the same model in joint coordinates: the tree joints' speeds,
/// the loop joints' rows and the drivers' rows.
struct JointCoordinateCount {
  int speeds = 0;
  int loop_rows = 0;
  int driver_rows = 0;
  std::vector<std::string> tree_joints, loop_joints;
  std::string summary() const;
};

/// The case as YAML text (comments at the top: the source, both counts). A body that no
/// chain of joints connects to the ground, or a joint whose triads do not meet at the
/// given configuration within the assembly tolerance, is bad input at its name.
std::string to_case_yaml(const Model& model);

JointCoordinateCount joint_coordinate_count(const Model& model);

}  // namespace heavesim::mksim
