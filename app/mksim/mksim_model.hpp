#pragma once
// An MKSim model as read from its text (docs/mksim-format.md): the SYSTEM settings,
// bodies with their initial placement, triads (frames fixed on bodies), joints between
// two triads and absolute drivers. Every item keeps where it was written, so that the
// conversion to a heavesim case can report its errors at file:line:column too.
#include <Eigen/Core>

#include <optional>
#include <string>
#include <vector>

#include "app/case/input_error.hpp"

namespace heavesim::mksim {

/// MKSim's `par` triple: the frame's origin, a point on its z axis and a point on its
/// x axis (the x axis is the part of origin->point perpendicular to z).
struct PointTriple {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  Eigen::Vector3d z_point = Eigen::Vector3d::UnitZ();
  Eigen::Vector3d x_point = Eigen::Vector3d::UnitX();
  SourceLocation location;
};

struct SystemSettings {
  SourceLocation location;
  std::optional<double> starting_time, ending_time, print_interval;  // s
  std::optional<double> nr_tolerance;        // MKSim's equation error tolerance, m or rad
  std::optional<double> assembly_tolerance;  // the |Phi| accepted when assembling, m or rad
};

/// A body: the ground (the world frame unless placed) or a moving body whose frame is at
/// its centre of gravity. Both given in world coordinates at the initial configuration.
struct Body {
  std::string name;
  SourceLocation location;
  bool ground = false;
  std::optional<Eigen::Vector3d> center_of_gravity;  // m, world, initial configuration
  std::optional<PointTriple> par;                     // world, initial configuration
};

/// A frame fixed on a body; origin and par in the body's frame (m).
struct Triad {
  std::string name;
  SourceLocation location;
  std::string body;
  SourceLocation body_location;
  std::optional<Eigen::Vector3d> origin;
  std::optional<PointTriple> par;
  std::size_t body_index = 0;  // resolved by the reader
};

enum class JointType { revolute, spherical, translational, universal, cylindrical };

struct Joint {
  std::string name;
  SourceLocation location;
  JointType type = JointType::revolute;
  std::string triad_names[2];
  SourceLocation triad_locations[2];
  std::size_t triads[2] = {0, 0};  // resolved by the reader: i (first), j (second)
};

/// `target.x = f(TIME)`: a world coordinate of a body's reference point (its centre of
/// gravity) or of a triad's origin, prescribed as an expression of time.
struct Driver {
  std::string name;
  SourceLocation location;
  std::string target;
  SourceLocation target_location;
  int axis = 0;                    // 0 x, 1 y, 2 z (world)
  std::string expression;          // as written, TIME and all
  SourceLocation expression_location;
  std::size_t body_index = 0;      // resolved: the body whose point is driven
  Eigen::Vector3d point = Eigen::Vector3d::Zero();  // m, that body's frame
};

struct Model {
  std::string file;
  std::string name;
  SourceLocation location;
  SystemSettings system;
  std::vector<Body> bodies;
  std::vector<Triad> triads;
  std::vector<Joint> joints;
  std::vector<Driver> drivers;
  std::size_t ground = 0;  // index of the ground body
};

const char* joint_type_name(JointType type);
/// Haug's number of equations of the joint (Haug 1989, ch. 9): what MKSim counts.
int joint_equation_count(JointType type);

}  // namespace heavesim::mksim
