// The compensator set-up analysis (control/analysis/static_balance.hpp and the gain
// check of stroke_loop.hpp) against hand values: a platform on a vertical prismatic
// joint carrying a load on a second vertical prismatic joint (the compensator stroke).
#include <gtest/gtest.h>

#include <cmath>

#include "control/analysis/static_balance.hpp"
#include "control/analysis/stroke_loop.hpp"
#include "kernel/algorithms/kinematics.hpp"
#include "kernel/algorithms/mass_matrix.hpp"
#include "kernel/elements/point_force.hpp"
#include "kernel/model/model_builder.hpp"
#include "kernel/parameter_error.hpp"

namespace heavesim {
namespace {

constexpr double platform_mass = 1.0e6, load_mass = 2.9e5, g = 9.81;  // kg, kg, m/s^2

/// A joint of `kind` about or along `axis` (parent frame), its frame at `position` in the parent.
JointDefinition joint(const std::string& name, JointKind kind, const Vector3& axis, const std::string& parent,
                      const std::string& child, const Vector3& position = Vector3::Zero()) {
  JointDefinition definition;
  definition.name = name;
  definition.kind = kind;
  definition.axis = axis;
  definition.parent = parent;
  definition.child = child;
  definition.X_parent_joint = Transform(Matrix3::Identity(), position);
  return definition;
}

std::shared_ptr<const Model> platform_and_load() {
  ModelBuilder builder;
  builder.set_gravity(Vector3(0.0, 0.0, -g));
  builder.add_body({"platform", Inertia(platform_mass, Vector3::Zero(), Matrix3::Identity() * 1e8), std::nullopt});
  builder.add_body({"load", Inertia(load_mass, Vector3(0.3, 0.0, 1.0), Matrix3::Identity() * 1e6), std::nullopt});
  builder.add_joint(joint("heave", JointKind::prismatic, Vector3::UnitZ(), ModelBuilder::ground_name, "platform"));
  builder.add_joint(joint("stroke", JointKind::prismatic, Vector3::UnitZ(), "platform", "load"));
  return std::make_shared<const Model>(builder.build());
}

struct Rig {
  std::shared_ptr<const Model> model = platform_and_load();
  Data data{*model};
  VectorX q0 = (VectorX(2) << 0.4, -0.2).finished();
  StrokeAxis axis = StrokeAxis::on_joint(*model, model->joint_index("stroke"), 0.0);
  Rig() {
    update_positions(*model, data, q0);
    update_velocities(*model, data, q0, VectorX::Zero(2));
  }
};

TEST(StaticBalance, UnitStrokeForceIsTheStrokeCoordinate) {
  Rig rig;
  const VectorX unit = unit_stroke_generalized_force(rig.axis, *rig.model, rig.data);
  // A force along a prismatic joint's own axis is that coordinate's generalized force;
  // its reaction on the platform cancels in the platform coordinate.
  EXPECT_NEAR(unit[0], 0.0, 1e-12);
  EXPECT_NEAR(unit[1], 1.0, 1e-12);
}

TEST(StaticBalance, StaticLoadIsTheCarriedWeightLessTheOtherLoads) {
  Rig rig;
  MultibodySystem system(rig.model);
  const VectorX unit = unit_stroke_generalized_force(rig.axis, *rig.model, rig.data);
  EXPECT_NEAR(static_stroke_load(*rig.model, rig.data, system, 0.0, rig.q0, unit), load_mass * g, 1e-6);
  // An upward 1e5 N on the load carries part of it.
  const BodyPoint load_origin = BodyPoint::on_body(*rig.model, "load", Vector3::Zero());
  system.add_force_element(std::make_unique<PointForce>("lift", load_origin, Vector3(0, 0, 1e5)));
  EXPECT_NEAR(static_stroke_load(*rig.model, rig.data, system, 0.0, rig.q0, unit), load_mass * g - 1e5, 1e-6);
}

// A lever carried through a loop: a beam of mass m_b pinned to the ground at the origin
// (revolute about y), its CoM at x = c, rests horizontally on a vertical rod (a distance
// constraint, length d) whose lower end is on a slider of mass m_s on a vertical stroke
// joint under x = a. Hand statics: moments about the pin, m_b g c = T a, so the rod
// carries T = m_b g c / a and the stroke F = m_s g + T. The stroke's own coordinate sees
// only m_s g: the rest arrives through the loop.
TEST(StaticBalance, StaticLoadCountsWhatTheLoopsCarry) {
  constexpr double beam_mass = 2000.0, slider_mass = 300.0, c = 1.5, a = 0.6, d = 2.0;  // kg, kg, m, m, m
  ModelBuilder builder;
  builder.set_gravity(Vector3(0.0, 0.0, -g));
  builder.add_body({"beam", Inertia(beam_mass, Vector3(c, 0.0, 0.0), Matrix3::Identity() * 50.0), std::nullopt});
  builder.add_body({"slider", Inertia(slider_mass, Vector3::Zero(), Matrix3::Identity() * 5.0), std::nullopt});
  builder.add_joint(joint("pin", JointKind::revolute, Vector3::UnitY(), ModelBuilder::ground_name, "beam"));
  builder.add_joint(joint("stroke", JointKind::prismatic, Vector3::UnitZ(), ModelBuilder::ground_name, "slider",
                          Vector3(a, 0.0, -d)));
  builder.add_distance_constraint({"rod", "slider", "beam", Vector3::Zero(), Vector3(a, 0.0, 0.0), d});
  const auto model = std::make_shared<const Model>(builder.build());
  Data data(*model);
  const VectorX q0 = VectorX::Zero(2);  // beam horizontal, rod vertical and of length d
  update_positions(*model, data, q0);
  const StrokeAxis axis = StrokeAxis::on_joint(*model, model->joint_index("stroke"), 0.0);
  const VectorX unit = unit_stroke_generalized_force(axis, *model, data);
  MultibodySystem system(model);
  EXPECT_NEAR(static_stroke_load(*model, data, system, 0.0, q0, unit), slider_mass * g + beam_mass * g * c / a,
              1e-9 * beam_mass * g);
}

// A stroke that a driver holds has no static load of its own: the driver takes it.
TEST(StaticBalance, StrokeHeldByADriverIsRefused) {
  ModelBuilder builder;
  builder.set_gravity(Vector3(0.0, 0.0, -g));
  builder.add_body({"load", Inertia(load_mass, Vector3::Zero(), Matrix3::Identity() * 1e6), std::nullopt});
  builder.add_joint(joint("stroke", JointKind::prismatic, Vector3::UnitZ(), ModelBuilder::ground_name, "load"));
  DriverDefinition hold;
  hold.name = "hold";
  hold.joint = "stroke";
  hold.motion = [](double) { return DriverMotion{}; };
  builder.add_driver(hold);
  const auto model = std::make_shared<const Model>(builder.build());
  Data data(*model);
  const VectorX q0 = VectorX::Zero(1);
  update_positions(*model, data, q0);
  const VectorX unit = unit_stroke_generalized_force(StrokeAxis::on_joint(*model, model->joint_index("stroke"), 0.0), *model, data);
  MultibodySystem system(model);
  try {
    static_stroke_load(*model, data, system, 0.0, q0, unit);
    ADD_FAILURE() << "no ParameterError";
  } catch (const ParameterError& error) {
    EXPECT_EQ(error.field(), "gas_pressure");
    EXPECT_NE(error.found().find("drivers hold"), std::string::npos) << error.found();
  }
}

TEST(StaticBalance, ApparentMassOfAJointStrokeIsItsDiagonalEntry) {
  Rig rig;
  const VectorX unit = unit_stroke_generalized_force(rig.axis, *rig.model, rig.data);
  // M = [[m_p + m_l, m_l], [m_l, m_l]] for two stacked vertical sliders.
  EXPECT_NEAR(apparent_stroke_mass(mass_matrix(*rig.model, rig.data), unit), load_mass, 1e-6);
  // Q^T M Q / |Q|^4 scales as 1/|Q|^2: a stroke geared 2:1 moves a quarter of the mass.
  EXPECT_NEAR(apparent_stroke_mass(mass_matrix(*rig.model, rig.data), 2.0 * unit), load_mass / 4.0, 1e-6);
}

TEST(StaticBalance, BalancedGasPressureCarriesTheLoad) {
  PneumaticParameters p;
  p.piston_area = 0.5;
  p.gas_volume = 2.0;
  p.atmospheric_pressure = 1e5;
  p.exponent_compression = p.exponent_expansion = 1.4;
  // At s = 0.4 m: p = 1e5 + 1e5 / 0.5 = 3e5 Pa in V = 2.2 m^3; at mid-stroke (V0 = 2 m^3)
  // p0 = 3e5 (2.2 / 2)^1.4.
  EXPECT_NEAR(balanced_pneumatic(p, 1e5, 0.4).gas_pressure, 3e5 * std::pow(1.1, 1.4), 1e-6);
  // With the gas temperature as a state the pressure starts isothermal: p0 = p V / V0.
  p.cooling = GasCooling{100.0, 288.15};
  EXPECT_NEAR(balanced_pneumatic(p, 1e5, 0.4).gas_pressure, 3e5 * 1.1, 1e-6);
  // A load pulling the stroke out needs less than the atmosphere.
  try {
    balanced_pneumatic(p, -1e5, 0.4);
    ADD_FAILURE() << "no ParameterError";
  } catch (const ParameterError& error) {
    EXPECT_EQ(error.field(), "gas_pressure");
    EXPECT_NE(error.found().find("below atmospheric"), std::string::npos) << error.found();
  }
}

TEST(StrokeLoopCheck, FlagsGrowthFasterThanTheTolerance) {
  ActiveCompensatorParameters active;
  active.actuator = ActuatorType::force;
  StrokeLoopPoles stable{{{-1.0, 0.0}, {1e-3, 2.0}}, 1e-3};  // slower than one e-fold in 500 s
  EXPECT_NO_THROW(check_stroke_loop_stable(stable, active, 1e3));
  StrokeLoopPoles unstable{{{-1.0, 0.0}, {0.2, -2.0}}, 0.2};
  try {
    check_stroke_loop_stable(unstable, active, 1e3);
    ADD_FAILURE() << "no ParameterError";
  } catch (const ParameterError& error) {
    EXPECT_EQ(error.field(), "controller");
    EXPECT_NE(error.found().find("closed-loop pole at 0.2 - 2i 1/s"), std::string::npos) << error.found();
    EXPECT_NE(error.expected().find("pole placement"), std::string::npos) << error.expected();
  }
}

TEST(StrokeLoopCheck, HydraulicAdviceNamesTheOilColumnResonance) {
  ActiveCompensatorParameters active;
  active.actuator = ActuatorType::hydraulic;
  HydraulicCylinderParameters& c = active.hydraulic.cylinder;
  c.bulk_modulus = 1e9;
  c.area_a = 0.1;
  c.volume_a = 0.1;
  c.area_b = 0.05;
  c.volume_b = 0.05;
  // omega_h = sqrt(beta (A_A^2/V_A + A_B^2/V_B) / m) = sqrt(1e9 x 0.15 / 1.5e6) = 10 rad/s.
  EXPECT_NE(stable_gain_advice(active, 1.5e6).find("omega_h = 10 rad/s"), std::string::npos)
      << stable_gain_advice(active, 1.5e6);
}

}  // namespace
}  // namespace heavesim
