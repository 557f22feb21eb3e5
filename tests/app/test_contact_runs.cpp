// Runs of cases with `contacts` (solver.integrator: contact) through the command line:
// the recorded contact forces against closed forms. A box on a deck driven in surge and
// heave carries m (g + z_d'') on its face whether it sticks or slips (the deck's heave
// acceleration is prescribed), its friction never exceeds mu times that, and it slips
// for the share of the time the piecewise closed form gives (82.7 % over two periods:
// the kernel test ContactStepper.BoxOnASurgingHeavingDeckSticksAndSlipsAsTheClosedForm
// computes it). The demo case runs to the end; a driver that pushes a box into a fixed
// ceiling ends the run with exit 3 naming the step and the contacts. The rig drilling
// on bottom with a turning string: the torque on bit is its torsional friction times
// the weight on bit, and the top drive supplies it. A subsea lift from a heaving crane:
// the wire goes slack and snaps taut, never longer than itself. The rig's end stops
// under IDA against contact stepping and penalty stops.
#include <gtest/gtest.h>

#include <cmath>

#include "tests/app/h5_file.hpp"
#include "tests/test_support.hpp"

namespace heavesim {
namespace {

TEST(ContactRun, BoxOnADeckCarriesMassTimesGravityPlusHeaveAcceleration) {
  const std::string output = temporary("contact_box_on_deck.h5");
  const testing::CommandResult run = testing::run_case("tests/cases/contact_box_on_deck.yaml", output);
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const H5File file(output);
  const std::vector<double> time = file.read("/time");
  const std::vector<double> normal = file.read("/forces/contacts/box_normal_force");
  const std::vector<double> friction = file.read("/forces/contacts/box_friction_force");
  ASSERT_EQ(normal.size(), time.size());
  const double m = 200.0, g = 9.81, mu = 0.2;
  int slipping = 0;
  for (std::size_t k = 1; k < time.size(); ++k) {  // t = 0: the first step's loads, half the deck's acceleration
    const double heave_acceleration = -2.0 * std::sin(time[k] + M_PI / 3);
    // First order: over one 1 ms step the deck's acceleration moves by h B w^3 = 2e-3 m/s^2.
    EXPECT_NEAR(normal[k], m * (g + heave_acceleration), 5e-4 * m * g) << "t = " << time[k];
    EXPECT_LE(friction[k], mu * normal[k] * (1 + 1e-9)) << "t = " << time[k];
    slipping += std::abs(friction[k] - mu * normal[k]) <= 1e-9 * normal[k];
  }
  EXPECT_NEAR(double(slipping) / (time.size() - 1), 0.827, 0.02);
  EXPECT_EQ(file.long_attribute("/", "complete"), 1);
}

TEST(ContactRun, DeckCargoDemoRunsToTheEnd) {
  const std::string output = temporary("deck_cargo.h5");
  const testing::CommandResult run = testing::run_case("cases/contact/deck_cargo.yaml", output, "--set solver.t_end=12");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const H5File file(output);
  EXPECT_EQ(file.long_attribute("/", "complete"), 1);
  // The container rests on four corners and the pipes on two rim points each, always.
  for (const double points : file.read("/forces/contacts/container_points")) EXPECT_EQ(points, 4.0);
  for (const double points : file.read("/forces/contacts/pipe_2_points")) EXPECT_EQ(points, 2.0);
}

TEST(ContactRun, ADriverPushingABoxIntoTheCeilingStopsWithExit3NamingTheContacts) {
  // The deck rises at 0.5 m/s under a box a fixed ceiling holds down: from t = 0.4 s the
  // box touches both and no impulses can meet the driver (the problem has no solution).
  // The regularized problem of the first step there may still pass its residual test
  // (the overlap it leaves, 8e-5 m, is what eps z allows), so the run stops within a step
  // or two of 0.4 s.
  const std::string output = temporary("fault_contact_ceiling.h5");
  const testing::CommandResult run =
      testing::run_case("tests/cases/fault_contact_driver_into_ceiling.yaml", output);
  EXPECT_EQ(run.exit_code, 3) << run.output;
  for (const char* part : {"at t = 0.4", "found no impulses", "'box_on_deck' gap", "'box_on_ceiling' gap",
                           "1 constraint rows", "Dantzig: ", "residual", "a driver"})
    EXPECT_NE(run.output.find(part), std::string::npos) << "'" << part << "' in: " << run.output;
  const H5File file(output);
  EXPECT_EQ(file.long_attribute("/", "complete"), 0);
  const std::vector<double> time = file.read("/time");
  ASSERT_FALSE(time.empty());
  EXPECT_NEAR(time.back(), 0.4, 0.011);  // the last whole output before the failure
}

TEST(ContactRun, TheBitsTorqueIsItsTorsionalFrictionOfTheWeightOnBitAndTheTopDriveSuppliesIt) {
  // cases/contact/bit_on_bottom.yaml: WOB0 = 150 kN at rest, mu_t = mu_b D / 3 = 0.25 x
  // 0.2159 / 3 m. The bit slides in spin at every step (120 rpm), so its torsional
  // friction is mu_t times the step's normal force exactly; once the spin-up (time
  // constant 2 s) has died away (e^-20 by 40 s) the top drive's torque is that moment.
  const std::string output = temporary("bit_on_bottom.h5");
  const testing::CommandResult run = testing::run_case(
      "cases/contact/bit_on_bottom.yaml", output, " --set solver.t_end=60 --set output.evaluate_after=30");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const H5File file(output);
  const std::vector<double> time = file.read("/time"), wob = file.read("/forces/contacts/bit_normal_force");
  const std::vector<double> tob = file.read("/forces/contacts/bit_torsion"), drive = file.read("/drivers/rotary/torque");
  const double mu_t = 0.25 * 0.2159 / 3;
  double mean = 0.0, lowest = 1e300, highest = 0.0;
  int counted = 0;
  for (std::size_t k = 1; k < time.size(); ++k) {
    EXPECT_NEAR(tob[k], -mu_t * wob[k], 1e-12 * mu_t * wob[k]) << "t = " << time[k];  // against the spin
    if (time[k] < 40.0) continue;
    EXPECT_NEAR(drive[k], -tob[k], 1e-6 * std::abs(tob[k])) << "t = " << time[k];
    mean += wob[k], ++counted;
    lowest = std::min(lowest, wob[k]), highest = std::max(highest, wob[k]);
  }
  // The passive compensator lets the heave through as WOB: measured 142 .. 157 kN about 150 kN.
  EXPECT_NEAR(mean / counted, 150e3, 0.01 * 150e3);
  EXPECT_GT(highest - lowest, 5e3);
  EXPECT_GT(lowest, 0.0);  // the bit stays on bottom
}

TEST(ContactRun, ASubseaLiftsWireGoesSlackAndSnapsButNeverStretches) {
  // cases/contact/subsea_lift.yaml: a 187 kN (submerged) module with 41 t of added mass and
  // the drag of an 80 m^2 roof on a 45 m wire from a crane tip heaving 1.5 m at 7 s. Where
  // the tip falls faster than the module can follow, the wire is slack (tension 0: measured
  // 18 % of the time); it snaps taut again with an impulse (the running total jumps by more
  // than the tension's integral). The wire never exceeds its length.
  const std::string output = temporary("subsea_lift.h5");
  const testing::CommandResult run = testing::run_case("cases/contact/subsea_lift.yaml", output);
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const H5File file(output);
  const std::vector<double> time = file.read("/time"), tension = file.read("/forces/contacts/crane_wire_tension");
  const std::vector<double> total = file.read("/forces/contacts/crane_wire_impulse");
  const std::vector<double> tip = file.read("/joints/tip_heave/q"), module = file.read("/joints/module_heave/q");
  int slack = 0, samples = 0;
  double largest_snap = 0.0;
  for (std::size_t k = 1; k < time.size(); ++k) {
    EXPECT_GE(tension[k], 0.0);
    EXPECT_LE((20.0 + tip[k]) - module[k], 45.0 + 1e-9) << "t = " << time[k];  // tip at 20 m above the module's zero
    if (time[k] < 60.0) continue;
    ++samples;
    slack += tension[k] == 0.0;
    const double delivered = total[k] - total[k - 1], steady = 0.5 * (tension[k] + tension[k - 1]) * (time[k] - time[k - 1]);
    largest_snap = std::max(largest_snap, delivered - steady);
  }
  EXPECT_GT(slack, samples / 10);
  EXPECT_LT(slack, samples / 3);
  // A snap delivers ~17 kN s in one 1 ms step (measured), far beyond the tension's share.
  EXPECT_GT(largest_snap, 5e3);
}

TEST(ContactRun, TheRigsEndStopsUnderIdaMeetContactSteppingAndThePenaltyStops) {
  // The H0 rig's passive compensator with stops at +-0.5 m in the default wave: the crown
  // block strikes them, bounces (restitution exp(-2), what a critically damped penalty
  // stop restitutes in its rigid limit; the case file derives it) and comes to rest on
  // them. Three treatments of the same stops, against the event-located joint stop under
  // IDA (the case's own):
  //  - velocity-level contact stepping, first order: the difference falls with h;
  //  - the compensator's penalty stops, critically damped, at 1e8, 1e9, 1e10 N/m: it falls
  //    as the penetration, of order v sqrt(M_eff / k): by sqrt(10) per decade.
  const std::string extra = " --set solver.t_end=40 --set output.evaluate_after=20 --set output.interval=0.01";
  const std::string events_file = temporary("end_stops_ida.h5");
  const testing::CommandResult events = testing::run_case("cases/contact/drilling_end_stops.yaml", events_file, extra);
  ASSERT_EQ(events.exit_code, 0) << events.output;
  H5File result(events_file);
  const std::vector<double> stroke = result.read("/joints/compensator/q");
  for (const double s : stroke) EXPECT_LE(std::abs(s), 0.5 + 1e-9);
  const std::vector<double> time = result.read("/time"), force = result.read("/forces/contacts/stroke_ends_force");
  const std::vector<double> impacts = result.read("/forces/contacts/stroke_ends_impulse");
  EXPECT_GT(std::abs(impacts.back()), 1e4);  // N s: the stops did work
  for (const double f : force) EXPECT_LT(std::abs(f), 1e6);  // a stop's resting force, not an impact's
  const auto difference = [&](const std::string& file, bool rms) {
    const std::vector<double> other = H5File(file).read("/joints/compensator/q");
    EXPECT_EQ(other.size(), stroke.size());
    double largest = 0.0, squares = 0.0;
    for (std::size_t k = 0; k < std::min(other.size(), stroke.size()); ++k) {
      largest = std::max(largest, std::abs(other[k] - stroke[k]));
      squares += (other[k] - stroke[k]) * (other[k] - stroke[k]);
    }
    return rms ? std::sqrt(squares / stroke.size()) : largest;
  };
  // Contact stepping at 1 and 0.5 ms. Measured rms 1.9e-4 and 7.2e-5 m (4.2e-5 at 0.25 ms):
  // first order, noisily (where each impact falls within its step).
  std::vector<double> stepped;
  double stepped_total = 0.0;
  for (const char* step : {"0.001", "0.0005"}) {
    const std::string file = temporary(std::string("end_stops_stepped_") + step + ".h5");
    const testing::CommandResult run = testing::run_case(
        "cases/contact/drilling_end_stops.yaml", file,
        extra + " --set solver.integrator=contact --set solver.step=" + std::string(step));
    ASSERT_EQ(run.exit_code, 0) << run.output;
    stepped.push_back(difference(file, true));
    stepped_total = H5File(file).read("/forces/contacts/stroke_ends_impulse").back();
  }
  EXPECT_GT(stepped[0] / stepped[1], 1.6) << stepped[0] << " " << stepped[1];
  EXPECT_LT(stepped[1], 1e-4);
  // The stepped run's impulses (impacts and resting force alike) against the events' impacts
  // plus the integral of their resting force: measured 0.07 % apart.
  double resting = 0.0;
  for (std::size_t k = 1; k < time.size(); ++k) resting += 0.5 * (force[k] + force[k - 1]) * (time[k] - time[k - 1]);
  EXPECT_NEAR(stepped_total, impacts.back() + resting, 2e-3 * std::abs(stepped_total));
  // Penalty stops. Measured: 0.072, 0.024, 0.0075 m.
  std::vector<double> penalty;
  for (const char* stiffness : {"1e8", "1e9", "1e10"}) {
    const std::string file = temporary(std::string("end_stops_penalty_") + stiffness + ".h5");
    const testing::CommandResult run = testing::run_case(
        "cases/c3_regular_waves/h0_passive.yaml", file,
        extra + " --set parameters.stroke_half=0.5 --set forces[6].end_stops.stiffness=" + stiffness +
            " --set 'forces[6].end_stops.damping=2*sqrt(" + stiffness + "*M_eff)'");
    ASSERT_EQ(run.exit_code, 0) << run.output;
    penalty.push_back(difference(file, false));
  }
  EXPECT_GT(penalty[0] / penalty[1], 2.5) << penalty[0] << " " << penalty[1];
  EXPECT_GT(penalty[1] / penalty[2], 2.5) << penalty[1] << " " << penalty[2];
  EXPECT_LT(penalty[2], 0.01);
}

}  // namespace
}  // namespace heavesim
