#pragma once
// The kinematic sweep shared by `heavesim kinematics` and the validation suite: the
// scene's mechanism analysed at every output time from solver.t_start to solver.t_end
// (kernel/analysis/kinematic_analysis.hpp), with the inverse dynamics of the motion
// (MultibodySystem::evaluate_prescribed) evaluated before each observation.
#include <functional>

#include "app/case/case_definition.hpp"
#include "app/scene/scene.hpp"
#include "kernel/analysis/kinematic_analysis.hpp"

namespace heavesim {

/// Called at every time point after the system was evaluated there (stages, forces,
/// qdd, multipliers, reactions when asked); y = [q; v; element states]. Return false to
/// stop early.
using KinematicObserver = std::function<bool(double t, const VectorX& y, const KinematicPoint& point)>;

struct KinematicOutcome {
  bool completed = false;         // reached t_end
  double time_reached = 0.0;      // s, of the last time point observed
  long points = 0;                // time points analysed
  long newton_iterations = 0;     // over every time point
  double max_equation_residual = 0.0;    // max |Phi| [m or rad]
  double smallest_singular_ratio = 1.0;  // over every time point
  double max_dynamic_residual = 0.0;     // N or N m
};

/// Analyses the scene from its assembled state at solver.t_start to solver.t_end every
/// output interval (the last point exactly on t_end). A time point whose position
/// cannot be reached throws NumericalError naming the drivers and rows along the
/// direction being lost, with the time (earlier points were observed).
KinematicOutcome run_kinematics(Scene& scene, const CaseDefinition& definition, bool compute_reactions,
                                const KinematicObserver& observe);

}  // namespace heavesim
