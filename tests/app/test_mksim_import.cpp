// heavesim import-mksim (app/mksim/): MKSim's count of the seed's slider-crank, the
// committed case against a fresh import, every joint type placed where the MKSim model
// says, and the corpus of malformed models in tests/bad_mksim (exit 2 at file:line:column).
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "app/case/case_definition.hpp"
#include "app/mksim/mksim_reader.hpp"
#include "app/mksim/mksim_to_case.hpp"
#include "app/scene/scene.hpp"
#include "kernel/algorithms/kinematics.hpp"
#include "tests/app/h5_file.hpp"
#include "tests/test_support.hpp"

// A namespace of its own: the unity build compiles this file together with others
// (top CMakeLists.txt), whose file-local names must not meet these.
namespace heavesim::test_mksim_import {
namespace {

std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(MksimImport, SeedSliderCrankCountsTwentyEightCoordinatesTwentySevenEquationsOneDof) {
  // The seed's model summary: 4 bodies (ground, pend1, pend2, block) x 7 = 28; 4 normal
  // + 6 ground + revolute 5 + spherical 3 + spherical 3 + translational 5 + 1 driver = 27.
  const mksim::Model model = mksim::read_model_file(testing::source_path("cases/kinematics/mksim_slider_crank.mks"));
  const mksim::Count count = mksim::count(model);
  EXPECT_EQ(count.bodies, 4);
  EXPECT_EQ(count.coordinates, 28);
  EXPECT_EQ(count.normal, 4);
  EXPECT_EQ(count.joint_equations, 16);
  EXPECT_EQ(count.drivers, 1);
  EXPECT_EQ(count.equations(), 27);
  EXPECT_EQ(count.dof(), 1);
  // In joint coordinates the breadth-first tree from the ground takes rev1 (1 speed), tran1
  // (1) and sph1 (3); sph2 closes the loop (3 rows); with the driver 5 - 4 = 1 again.
  const mksim::JointCoordinateCount joints = mksim::joint_coordinate_count(model);
  EXPECT_EQ(joints.speeds, 5);
  EXPECT_EQ(joints.loop_rows, 3);
  EXPECT_EQ(joints.driver_rows, 1);
  EXPECT_EQ(joints.loop_joints, std::vector<std::string>{"sph2"});

  const std::filesystem::path output = temporary("slider_crank.yaml");
  const testing::CommandResult result = testing::run_command_line(
      testing::heavesim_binary() + " import-mksim " + testing::source_path("cases/kinematics/mksim_slider_crank.mks") +
      " -o " + output.string());
  std::filesystem::remove(output);
  EXPECT_EQ(result.exit_code, 0) << result.output;
  EXPECT_NE(result.output.find("28 generalized coordinates"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("DOF = 28 - 27 = 1"), std::string::npos) << result.output;
}

TEST(MksimImport, CommittedSliderCrankCaseEqualsAFreshImport) {
  const std::filesystem::path output = temporary("fresh.yaml");
  const testing::CommandResult result = testing::run_command_line(
      testing::heavesim_binary() + " import-mksim " + testing::source_path("cases/kinematics/mksim_slider_crank.mks") +
      " -o " + output.string());
  ASSERT_EQ(result.exit_code, 0) << result.output;
  const std::string fresh = read_text(output);
  std::filesystem::remove(output);
  EXPECT_EQ(fresh, read_text(testing::source_path("cases/kinematics/mksim_slider_crank_imported.yaml")))
      << "re-import: heavesim import-mksim cases/kinematics/mksim_slider_crank.mks -o "
         "cases/kinematics/mksim_slider_crank_imported.yaml";
}

TEST(MksimImport, EveryJointTypeIsAssembledWhereTheModelPlacesItsBodies) {
  // cases/kinematics/mksim_every_joint.mks: a closed chain through all five joint types
  // with a reversed revolute axis, perpendicular translational x axes and a universal
  // cross, given assembled. The imported case must put each body exactly where the MKSim
  // file does (its centre of gravity and par axes, typed here from the file) with no
  // assembly correction: the tree from the joints' initial coordinates, the loop closed.
  const std::filesystem::path output = temporary("every_joint.yaml");
  const testing::CommandResult result = testing::run_command_line(
      testing::heavesim_binary() + " import-mksim " + testing::source_path("cases/kinematics/mksim_every_joint.mks") +
      " -o " + output.string());
  ASSERT_EQ(result.exit_code, 0) << result.output;
  EXPECT_NE(result.output.find("DOF = 35 - 32 = 3"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("DOF = 7 - 4 = 3"), std::string::npos) << result.output;  // the same mobility
  const CaseDefinition definition = load_case(output.string());
  std::filesystem::remove(output);
  const Scene scene = build_scene(definition);
  const Model& model = *scene.model;
  // Round-off: a few operations on numbers of order 1..5 -> a few 1e-16 each.
  const double tolerance = 1e-13;
  EXPECT_LE(scene.assembly.largest_position_change, tolerance);
  EXPECT_LE(scene.assembly.position_residual, tolerance);
  Data data(model);
  update_positions(model, data, scene.initial_state.head(model.nq));
  struct Expected {
    const char* body;
    Vector3 position, x, y, z;
  };
  const Expected expected[] = {
      {"a", {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, 0, 1}},
      {"b", {2, 1, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}},
      {"c", {2, 3, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 0}},
      {"d", {3, 4, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}},
  };
  for (const Expected& body : expected) {
    SCOPED_TRACE(body.body);
    const int link = model.link_index(body.body);
    const Transform placement = data.X_world_link[link] * model.links[link].X_link_body;
    EXPECT_LE((placement.translation() - body.position).norm(), tolerance);
    EXPECT_LE((placement.rotation().col(0) - body.x).norm(), tolerance);
    EXPECT_LE((placement.rotation().col(1) - body.y).norm(), tolerance);
    EXPECT_LE((placement.rotation().col(2) - body.z).norm(), tolerance);
  }
}

TEST(MksimImport, KeywordsIgnoreCaseCommentsAndSeparatorsAreOptional) {
  // The same model in two spellings gives the same case: upper/lower-case keywords,
  // `//` comments, with and without `;` after a block.
  const std::string plain =
      "MODEL m SYSTEM { KINEMATIC ANALYSIS, ending time = 2 }; BODY g { ground }; "
      "BODY b { center of gravity = (0,0,1), par = {(0,0,1),(0,0,2),(1,0,1)} }; "
      "triad tg { associated body = g, origin = (0,0,0), par = {(0,0,0),(0,0,1),(1,0,0)} }; "
      "triad tb { associated body = b, origin = (0,0,-1), par = {(0,0,-1),(0,0,0),(1,0,-1)} }; "
      "cylindrical joint j { triad = tg, triad = tb }; driver d { b.z = 1 + 0.5*TIME }; ENDMODEL";
  const std::string spelled =
      "model m // the name\n system { kinematic Analysis; ENDING TIME = 2; }\n Body g { GROUND }\n"
      "body b { Center Of Gravity = (0, 0, 1); PAR = {(0,0,1), (0,0,2), (1,0,1)} }\n"
      "TRIAD tg { Associated Body = g; origin = (0,0,0); par = {(0,0,0),(0,0,1),(1,0,0)} }\n"
      "triad tb { associated body = b, origin = (0,0,-1), par = {(0,0,-1),(0,0,0),(1,0,-1)}, }\n"
      "CYLINDRICAL JOINT j { triad = tg; triad = tb }\nDriver d { b.Z = 1 + 0.5*time } // comment\nEndModel\n";
  const std::string a = mksim::to_case_yaml(mksim::parse_model(plain, "plain.mks"));
  const std::string b = mksim::to_case_yaml(mksim::parse_model(spelled, "plain.mks"));
  EXPECT_EQ(a, b);
  EXPECT_NE(a.find("position: 1 + 0.5*t"), std::string::npos) << a;
  EXPECT_NE(a.find("direction: [0, 0, 1]"), std::string::npos) << a;
}

TEST(MksimImport, TimeIsRenamedOnlyAsAWholeWord) {
  EXPECT_EQ(mksim::with_time_named("8.00 + 3*sin(TIME)", "t"), "8.00 + 3*sin(t)");
  EXPECT_EQ(mksim::with_time_named("Time*time_1 + timer(TIME)", "t"), "t*time_1 + timer(t)");
}

TEST(MksimImport, SliderCrankKinematicsFollowsTheDriverAndHoldsTheRodSpinAtZero) {
  // Issue #14, "Must show" 1: the seed's slider-crank, imported (the committed case) and
  // run by `heavesim kinematics`. The block follows x = 8 + 3 sin t exactly; the one free
  // direction heavesim reports is the rod's spin between its spherical joints, which the
  // minimum-kinetic-energy motion holds at zero: omega_rod . u_rod = 0, u_rod the rod's
  // body x axis (its triads sit at x = -5 and +5 m), computed here from the recorded
  // orientation and angular velocity.
  const std::string output = temporary("mksim_slider_crank.h5");
  const testing::CommandResult result = testing::run_command_line(
      testing::heavesim_binary() + " kinematics " +
      testing::source_path("cases/kinematics/mksim_slider_crank_imported.yaml") + " -q -o " + output);
  ASSERT_EQ(result.exit_code, 0) << result.output;
  const H5File file(output);
  ASSERT_TRUE(file.ok());
  EXPECT_EQ(file.long_attribute("/", "dof"), 1);
  const std::vector<double> time = file.read("/time");
  const std::vector<double> block = file.read("/bodies/block/position");
  const std::vector<double> rod_orientation = file.read("/bodies/pend2/orientation");
  const std::vector<double> rod_velocity = file.read("/bodies/pend2/velocity");
  ASSERT_EQ(time.size(), 81u);  // 0 .. 8 s every 0.1 s
  double block_error = 0.0, spin = 0.0;
  for (std::size_t k = 0; k < time.size(); ++k) {
    // Round-off: x of order 10 m, the prismatic coordinate set by one linear driver row.
    block_error = std::max({block_error, std::abs(block[3 * k] - (8.0 + 3.0 * std::sin(time[k]))),
                            std::abs(block[3 * k + 1]), std::abs(block[3 * k + 2])});
    const Eigen::Quaterniond q(rod_orientation[4 * k], rod_orientation[4 * k + 1], rod_orientation[4 * k + 2],
                               rod_orientation[4 * k + 3]);
    const Eigen::Vector3d axis = q.normalized() * Eigen::Vector3d::UnitX();
    const Eigen::Vector3d omega(rod_velocity[6 * k], rod_velocity[6 * k + 1], rod_velocity[6 * k + 2]);
    spin = std::max(spin, std::abs(omega.dot(axis)));
  }
  std::filesystem::remove(output);
  EXPECT_LE(block_error, 1e-12);
  EXPECT_LE(spin, 1e-12);
}

// ---------------------------------------------------------------- the corpus

struct BadModel {
  std::string path;
  std::string at;    // "line:column"
  std::string text;  // a piece of the message
};

BadModel read_expectations(const std::filesystem::path& file) {
  BadModel bad;
  bad.path = file.string();
  std::filesystem::path expectations = file;
  if (std::filesystem::file_size(file) == 0) expectations += ".expect";  // an empty file holds none
  std::ifstream in(expectations, std::ios::binary);
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("// expect-text: ", 0) == 0) bad.text = line.substr(16);
    if (line.rfind("// expect-at: ", 0) == 0) bad.at = line.substr(14);
  }
  return bad;
}

std::vector<BadModel> corpus() {
  std::vector<BadModel> models;
  for (const auto& entry : std::filesystem::directory_iterator(testing::source_path("tests/bad_mksim")))
    if (entry.path().extension() == ".mks") models.push_back(read_expectations(entry.path()));
  std::sort(models.begin(), models.end(), [](const BadModel& a, const BadModel& b) { return a.path < b.path; });
  return models;
}

TEST(MksimBadInput, CorpusHasAtLeastFifteenModels) { EXPECT_GE(corpus().size(), 15u); }

TEST(MksimBadInput, EveryModelIsRefusedAtItsLineAndColumnWithFoundAndExpected) {
  const std::filesystem::path output = temporary("bad.yaml");
  for (const BadModel& bad : corpus()) {
    SCOPED_TRACE(bad.path);
    ASSERT_FALSE(bad.at.empty()) << "no '// expect-at: LINE:COLUMN'";
    ASSERT_FALSE(bad.text.empty()) << "no '// expect-text: ...'";
    const testing::CommandResult result = testing::run_command_line(
        "timeout 10 " + testing::heavesim_binary() + " import-mksim " + bad.path + " -o " + output.string());
    EXPECT_EQ(result.exit_code, 2) << "(124 means it hung) " << result.output;
    const std::string position = bad.path + ":" + bad.at + ": ";
    EXPECT_NE(result.output.find(position), std::string::npos) << "no '" << position << "' in: " << result.output;
    EXPECT_NE(result.output.find("found "), std::string::npos) << result.output;
    EXPECT_NE(result.output.find("expected "), std::string::npos) << result.output;
    EXPECT_NE(result.output.find(bad.text), std::string::npos) << "no '" << bad.text << "' in: " << result.output;
    EXPECT_FALSE(std::filesystem::exists(output)) << "a refused model wrote a case";
  }
}

TEST(MksimBadInput, MissingAndDirectoryModelFilesAreBadInput) {
  for (const std::string& path : {std::string("/nonexistent.mks"), testing::source_path("tests/bad_mksim")}) {
    const testing::CommandResult result = testing::run_command_line(testing::heavesim_binary() + " import-mksim " +
                                                                     path + " -o /tmp/heavesim_never_written.yaml");
    EXPECT_EQ(result.exit_code, 2) << result.output;
    EXPECT_NE(result.output.find(path), std::string::npos) << result.output;
  }
}

}  // namespace
}  // namespace heavesim::test_mksim_import
