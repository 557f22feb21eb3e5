// Case loading: values, expressions, orientation forms, includes and overrides.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "app/case/case_definition.hpp"
#include "app/case/case_merge.hpp"
#include "app/case/case_node.hpp"
#include "tests/test_support.hpp"

namespace heavesim {
namespace {

class TemporaryDirectory {
 public:
  TemporaryDirectory() : path_(std::filesystem::temp_directory_path() / ("heavesim_test_" + std::to_string(::getpid()))) {
    std::filesystem::create_directories(path_);
  }
  ~TemporaryDirectory() { std::filesystem::remove_all(path_); }
  std::string write(const std::string& name, const std::string& text) const {
    const std::filesystem::path file = path_ / name;
    std::ofstream(file) << text;
    return file.string();
  }

 private:
  std::filesystem::path path_;
};

TEST(CaseLoading, ValidationCaseLoadsWithParametersAndExpressions) {
  const CaseDefinition definition = load_case(testing::source_path("cases/validation/two_link.yaml"));
  EXPECT_EQ(definition.name, "two_link");
  ASSERT_EQ(definition.bodies.size(), 2u);
  EXPECT_DOUBLE_EQ(definition.bodies[0].inertia.mass(), 1.0);
  EXPECT_DOUBLE_EQ(definition.bodies[0].inertia.inertia_com()(0, 0), 1.0 / 12.0);
  EXPECT_DOUBLE_EQ(definition.bodies[0].inertia.com().z(), -0.5);
  ASSERT_EQ(definition.joints.size(), 2u);
  EXPECT_DOUBLE_EQ(definition.initial_states.at("shoulder").q[0], M_PI / 2);
  EXPECT_DOUBLE_EQ(definition.joints[1].X_parent_joint.translation().z(), -1.0);
  EXPECT_EQ(definition.solver.integrator.method, IntegrationMethod::verner6);
}

const char* base_rig = R"(
parameters: {m: 2.0}
bodies:
  - {name: a, mass: m, inertia: [1, 1, 1]}
  - {name: b, mass: 3, inertia: [1, 1, 1]}
joints:
  - {name: ja, type: revolute, parent: ground, child: a, axis: [0, 1, 0]}
  - {name: jb, type: prismatic, parent: a, child: b, axis: [0, 0, 1]}
solver: {t_end: 5}
)";

TEST(CaseLoading, IncludesMergeNamedItemsAndOverridesApplyLast) {
  TemporaryDirectory directory;
  directory.write("base.yaml", base_rig);
  const std::string derived = directory.write("derived.yaml", R"(
include: base.yaml
bodies:
  - {name: b, mass: 7}
  - {name: c, mass: 1, inertia: [1, 1, 1]}
joints:
  - {name: jc, type: fixed, parent: b, child: c}
solver: {t_end: 10, integrator: rk4, step: 0.01}
)");
  const CaseDefinition definition = load_case(derived, {"bodies[a].mass=4", "joints[1].axis=[1, 0, 0]"});
  ASSERT_EQ(definition.bodies.size(), 3u);
  EXPECT_DOUBLE_EQ(definition.bodies[0].inertia.mass(), 4.0);  // --set by name
  EXPECT_DOUBLE_EQ(definition.bodies[1].inertia.mass(), 7.0);  // merged by name, inertia kept from base
  EXPECT_DOUBLE_EQ(definition.bodies[1].inertia.inertia_com()(2, 2), 1.0);
  EXPECT_EQ(definition.joints.size(), 3u);
  EXPECT_TRUE(definition.joints[1].axis.isApprox(Vector3::UnitX()));  // --set by index
  EXPECT_DOUBLE_EQ(definition.solver.t_end, 10.0);
  EXPECT_NE(definition.resolved_yaml.find("integrator: rk4"), std::string::npos);
  EXPECT_EQ(definition.resolved_yaml.find("include"), std::string::npos);
}

TEST(CaseLoading, IncludeCyclesAreRejected) {
  TemporaryDirectory directory;
  directory.write("one.yaml", "include: two.yaml\n");
  const std::string two = directory.write("two.yaml", "include: one.yaml\n");
  EXPECT_THROW(load_case(two), InputError);
}

TEST(CaseLoading, OverrideOfAnUnknownItemNamesIt) {
  TemporaryDirectory directory;
  const std::string path = directory.write("base.yaml", base_rig);
  try {
    load_case(path, {"bodies[z].mass=1"});
    FAIL();
  } catch (const InputError& error) {
    EXPECT_EQ(error.key_path(), "bodies[z]");
    EXPECT_NE(error.location().file.find("--set"), std::string::npos);
  }
}

TEST(CaseLoading, TheFourOrientationFormsAgree) {
  TemporaryDirectory directory;
  const double angle = 0.7;
  const Eigen::Quaterniond q(Eigen::AngleAxisd(angle, Vector3::UnitZ()));
  const Matrix3 R = q.toRotationMatrix();
  const std::vector<std::string> forms = {
      "{axis: [0, 0, 1], angle: 0.7}", "{rpy: [0, 0, 0.7]}",
      "{quaternion: [" + std::to_string(q.w()) + ", 0, 0, " + std::to_string(q.z()) + "]}",
      "{matrix: [[" + std::to_string(R(0, 0)) + ", " + std::to_string(R(0, 1)) + ", 0], [" + std::to_string(R(1, 0)) +
          ", " + std::to_string(R(1, 1)) + ", 0], [0, 0, 1]]}"};
  for (const std::string& form : forms) {
    const std::string path = directory.write("frame.yaml", std::string(base_rig) + "\n");
    const CaseDefinition definition = load_case(path, {"joints[ja].parent_frame.orientation=" + form});
    EXPECT_TRUE(definition.joints[0].X_parent_joint.rotation().isApprox(R, 1e-6)) << form;
  }
}

TEST(CaseLoading, ResolvedYamlReloadsToTheSameCase) {
  TemporaryDirectory directory;
  const CaseDefinition first = load_case(testing::source_path("cases/validation/three_link.yaml"));
  const CaseDefinition second = load_case(directory.write("resolved.yaml", first.resolved_yaml));
  EXPECT_EQ(second.resolved_yaml, first.resolved_yaml);
  EXPECT_EQ(second.joints.size(), first.joints.size());
}

TEST(CaseLoading, FreeJointNamedInitialStateIsConvertedToBodyAxes) {
  const CaseDefinition definition = load_case(testing::source_path("cases/validation/symmetric_top.yaml"));
  const JointInitialState& state = definition.initial_states.at("float");
  const Matrix3 R = Eigen::AngleAxisd(0.4, Vector3::UnitX()).toRotationMatrix();
  EXPECT_TRUE(state.v.head<3>().isApprox(R.transpose() * Vector3(0.6, 0.2, 3.0), 1e-14));
  EXPECT_NEAR(state.q[3], std::cos(0.2), 1e-15);  // quaternion w
}

// `heavesim run` reads its two definitions (the integrated scene's and the recorder's) from
// one resolved tree: each the same as load_case's, the tree left as it was, and the drivers'
// expressions evaluating to the closed form 3 t + sin 2 t (and its derivatives) in both,
// interleaved (a workspace shared between them would still agree here; that they share none
// is what the two reads are for, and what a second evaluation thread relies on).
TEST(CaseLoading, TwoDefinitionsReadFromOneTreeAreLoadCasesOwn) {
  const std::string path = testing::source_path("cases/kinematics/driven_slider_crank.yaml");
  const std::vector<std::string> overrides = {"solver.t_end=2"};
  const CaseNode tree = resolved_case_tree(path, overrides);
  const std::string tree_text = to_yaml_text(tree);
  const CaseDefinition loaded = load_case(path, overrides);
  const CaseDefinition first = read_case(tree, path, false), second = read_case(tree, path, false);
  EXPECT_EQ(to_yaml_text(tree), tree_text);  // reading changes nothing in the tree
  for (const CaseDefinition* definition : {&first, &second}) {
    EXPECT_EQ(definition->name, loaded.name);
    EXPECT_EQ(definition->resolved_yaml, loaded.resolved_yaml);
    EXPECT_EQ(definition->sources.size(), loaded.sources.size());
    EXPECT_DOUBLE_EQ(definition->solver.t_end, 2.0);
    ASSERT_EQ(definition->drivers.size(), 1u);
  }
  for (const double t : {0.0, 0.3, 1.7}) {
    const DriverMotion a = first.drivers[0].motion(t), b = second.drivers[0].motion(t);
    for (const DriverMotion& motion : {a, b}) {
      EXPECT_NEAR(motion.position, 3.0 * t + std::sin(2.0 * t), 1e-14);
      EXPECT_NEAR(motion.velocity, 3.0 + 2.0 * std::cos(2.0 * t), 1e-14);
      EXPECT_NEAR(motion.acceleration, -4.0 * std::sin(2.0 * t), 1e-14);
    }
  }
}

}  // namespace
}  // namespace heavesim
