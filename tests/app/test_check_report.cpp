// What `heavesim check` says a run evaluates, against what the evaluation then does. Here:
// which pass gives the joint reactions of a recorded sample. On a tree integrated by ABA
// they are read from the articulated-body pass that gave the accelerations (f = I^A a +
// p^A); with loops, drivers' rows or CRBA, an inverse-dynamics pass computes them, and that
// pass clears Data::articulated_evaluation, so the evaluation itself records which one ran.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "app/case/case_definition.hpp"
#include "app/scene/scene.hpp"
#include "tests/test_support.hpp"

namespace heavesim {
namespace {

struct ReactionCase {
  std::string path;
  std::string override_text;  // one --set, or ""
};

TEST(CheckReport, TheReactionsPassItNamesIsTheOneTheEvaluationTakes) {
  const std::vector<ReactionCase> cases = {
      {"cases/drilling.yaml", ""},                                             // a tree, ABA
      {"cases/drilling.yaml", "solver.dynamics=composite_rigid_body"},         // the same tree by CRBA
      {"cases/c3_regular_waves/h1_passive.yaml", ""},                          // the H1 rig's loop
      {"cases/c2_prescribed_heave/h0_base.yaml", ""},                          // a prescribed heave
      {"cases/contact/deck_cargo.yaml", ""},                                   // contacts, and drivers' rows
      {"cases/contact/drilling_end_stops.yaml", ""},                           // joint stops as IDA's rows
      {"cases/contact/drilling_end_stops.yaml", "solver.integrator=contact"},  // the same stops as impulses
  };
  int from_articulated_pass = 0, from_inverse_dynamics = 0;
  for (const ReactionCase& reaction_case : cases) {
    SCOPED_TRACE(reaction_case.path + " " + reaction_case.override_text);
    std::vector<std::string> overrides;
    if (!reaction_case.override_text.empty()) overrides.push_back(reaction_case.override_text);
    const CaseDefinition definition = load_case(testing::source_path(reaction_case.path), overrides);
    Scene scene = build_scene(definition);
    MultibodySystem& system = *scene.system;
    system.evaluate(definition.solver.t_start, scene.initial_state, true);
    const Data& data = system.data();
    ASSERT_TRUE(data.stages.current & StageMarker::reactions);
    const bool took_articulated_pass = data.articulated_evaluation == data.stages.evaluation;
    EXPECT_EQ(system.reactions_from_articulated_pass(), took_articulated_pass);
    (took_articulated_pass ? from_articulated_pass : from_inverse_dynamics) += 1;

    std::string command = testing::heavesim_binary() + " check " + testing::source_path(reaction_case.path);
    if (!reaction_case.override_text.empty()) command += " --set " + reaction_case.override_text;
    const testing::CommandResult check = testing::run_command_line(command);
    ASSERT_EQ(check.exit_code, 0) << check.output;
    const std::string said = took_articulated_pass ? "reactions (from each sample's articulated-body pass)"
                                                   : "reactions (one inverse-dynamics pass per sample)";
    EXPECT_NE(check.output.find(said), std::string::npos) << check.output;
  }
  // Both kinds among the cases, as many of each as the cases' structure says: the trees run
  // by ABA without constraint rows (drilling; the end stops stepped as impulses) and the
  // rest. The path is chosen by the predicate, so only these counts catch a predicate
  // that is false where the articulated pass would have served.
  EXPECT_EQ(from_articulated_pass, 2);
  EXPECT_EQ(from_inverse_dynamics, 5);
}

}  // namespace
}  // namespace heavesim
