// Velocity-level contact stepping (kernel/contact/contact_stepper.hpp) against closed
// forms: a sphere that slides into rolling (t = 2 v0 / (7 mu g), final speed 5 v0 / 7),
// Newton's restitution, a stop on a slide, and a 1:100 stack where plain projected
// Gauss-Seidel stalls and the chain says which solver answered. The block on an
// incline and the 20-cube stacks are validation P3 and P4, run as tests by
// tests/validation/test_validation_suite.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "kernel/contact/contact_stepper.hpp"
#include "kernel/model/model_builder.hpp"
#include "samples/contact_scenes.hpp"
#include "samples/joint_definition.hpp"

namespace heavesim {
namespace {

constexpr double g = 9.81;

/// Linear velocity of body `body`'s origin in the world [m/s] (free joint: v is in body axes).
Vector3 world_velocity(const Model& model, const VectorX& q, const VectorX& v, int link) {
  const Joint& joint = model.joints[link];
  const Eigen::Quaterniond orientation(q[joint.q_index + 3], q[joint.q_index + 4], q[joint.q_index + 5],
                                       q[joint.q_index + 6]);
  return orientation.normalized() * v.segment<3>(joint.v_index + 3);
}

struct SteppedScene {
  samples::ContactScene scene;
  Data data;
  ContactStepper stepper;
  VectorX q, v, tau;
  double t = 0.0;
  double h;
  SteppedScene(samples::ContactScene s, double h, int max_contacts, ContactStepOptions options = {})
      : scene(std::move(s)),
        data(*scene.model),
        stepper(*scene.model, scene.contacts, max_contacts, options),
        q(scene.q),
        v(scene.v),
        tau(VectorX::Zero(scene.model->nv)),
        h(h) {}
  ContactStepReport step() {
    const ContactStepReport report = stepper.step(data, t, h, q, v, tau);
    if (report.ok()) t += h;
    return report;
  }
};

TEST(ContactStepper, SlidingSphereRollsAfterTheClosedFormTime) {
  // A solid sphere launched at v0 without spin: friction mu m g slows it and spins it
  // up until v = omega r, at t = 2 v0 / (7 mu g); then it rolls at 5 v0 / 7.
  const double radius = 0.2, v0 = 3.0, mu = 0.3, h = 1e-4;
  SteppedScene run(samples::sphere_on_plane(radius, 2.0, radius, mu, 0.0), h, 4);
  run.v[3] = v0;
  const double rolling_time = 2 * v0 / (7 * mu * g);
  double slip_end = -1.0;
  for (int k = 1; k * h < 1.5 * rolling_time; ++k) {
    ASSERT_TRUE(run.step().ok());
    // The contact point's speed v_x - omega_y r, from the world velocities (v is in the
    // ball's own axes, which turn with it).
    const Matrix3 R =
        Eigen::Quaterniond(run.q[3], run.q[4], run.q[5], run.q[6]).normalized().toRotationMatrix();
    const Vector3 linear = R * run.v.segment<3>(3), angular = R * run.v.head<3>();
    const double slip = linear.x() - angular.y() * radius;
    if (slip_end < 0 && std::abs(slip) < 1e-9) slip_end = k * h;
  }
  EXPECT_NEAR(slip_end, rolling_time, h);
  const Vector3 linear = world_velocity(*run.scene.model, run.q, run.v, 1);
  EXPECT_NEAR(linear.x(), 5 * v0 / 7, 1e-9 * v0);
  EXPECT_NEAR(linear.tail<2>().norm(), 0.0, 1e-12);
}

TEST(ContactStepper, ImpactLeavesWithRestitutionTimesApproachSpeed) {
  const double e = 0.6, h = 1e-3;
  SteppedScene run(samples::sphere_on_plane(0.1, 1.0, 0.6, 0.0, e), h, 4);
  double approach = 0.0;
  for (int k = 0; k < 2000; ++k) {
    const double before = run.v[5];
    ASSERT_TRUE(run.step().ok());
    if (before < 0 && run.v[5] > 0) {
      approach = before;
      break;
    }
  }
  ASSERT_LT(approach, -2.0);  // fell about 0.5 m
  EXPECT_NEAR(run.v[5], -e * approach, 1e-9 * std::abs(approach));
}

TEST(ContactStepper, StopOnASlideHoldsTheWeightAndBouncesWithRestitution) {
  // A 50 kg mass on a vertical slide with stops at [0, 1] m, dropped from 0.5 m.
  ModelBuilder builder;
  builder.add_body({"sled", Inertia(50.0, Vector3::Zero(), Matrix3::Identity()), std::nullopt});
  builder.add_joint(samples::joint_definition("slide", JointKind::prismatic, "ground", "sled", Vector3::UnitZ()));
  const Model model = builder.build();
  ContactModel contacts;
  contacts.joint_stops.push_back({"slide_ends", 1, 0.0, 1.0, 0.5});
  ContactStepOptions options;
  ContactStepper stepper(model, contacts, 0, options);
  Data data(model);
  VectorX q = VectorX::Constant(1, 0.5), v = VectorX::Zero(1), tau = VectorX::Zero(1);
  bool bounced = false;
  for (int k = 0; k < 5000; ++k) {
    const double before = v[0];
    ASSERT_TRUE(stepper.step(data, k * 1e-3, 1e-3, q, v, tau).ok());
    if (!bounced && before < -1.0 && v[0] > 0) {
      bounced = true;
      EXPECT_NEAR(v[0], -0.5 * before, 1e-9 * std::abs(before));
      EXPECT_GT(stepper.stop_impulse(0), 0.0);
    }
    EXPECT_GE(q[0], -1e-9);
  }
  EXPECT_TRUE(bounced);
  EXPECT_NEAR(q[0], 0.0, 1e-9);
  EXPECT_NEAR(stepper.stop_impulse(0), 50.0 * g * 1e-3, 1e-9 * 50.0 * g * 1e-3);
}

TEST(ContactStepper, MassRatioStackStallsPlainGaussSeidelNotTheChain) {
  // Ten cubes, the top one 100 times the bottom one's mass (validation P4 holds such a
  // stack of twenty for 10 s with the default chain): 200 sweeps of plain projected
  // Gauss-Seidel do not reach the tolerance, and the step says so; the default chain
  // answers with Dantzig and the weights are carried.
  for (const bool plain : {true, false}) {
    ContactStepOptions options;
    if (plain) {
      options.solvers.order = {ComplementaritySolver::projected_gauss_seidel, ComplementaritySolver::dantzig,
                               ComplementaritySolver::lemke};
      options.solvers.count = 1;
      options.solvers.projected_gauss_seidel.max_iterations = 200;
    }
    SteppedScene run(samples::box_stack(10, 1.0, 10.0, 100.0, 0.5), 1e-2, 40, options);
    const ContactStepReport report = run.step();
    if (plain) {
      EXPECT_FALSE(report.ok());
      EXPECT_EQ(report.solve.solver, ComplementaritySolver::projected_gauss_seidel);
      EXPECT_EQ(report.solve.status, ComplementarityStatus::not_converged);
      EXPECT_EQ(run.q, run.scene.q);  // a failed step leaves the state as it was
      continue;
    }
    ASSERT_TRUE(report.ok()) << report.solve.message;
    EXPECT_EQ(report.solve.solver, ComplementaritySolver::dantzig);
    EXPECT_EQ(report.contacts, 40);
    double bottom_face = 0.0, total_weight = 0.0;
    for (int c = 0; c < 40; ++c)
      if (run.stepper.contacts()[c].pair == 0) bottom_face += run.stepper.contact_impulse_world(c).z() / 1e-2;
    for (const double m : run.scene.masses) total_weight += m * g;
    EXPECT_NEAR(bottom_face, total_weight, 1e-9 * total_weight);
  }
}

/// The box's velocity along x relative to the deck, u(t), from the piecewise closed form,
/// written apart from the stepper: with the deck's accelerations a_x = -A w^2 sin(w t) and
/// a_z = -B w^2 sin(w t + phase), the box sticks while |a_x| <= mu (g + a_z); in slip
/// (s = sign u) u' = -a_x - s mu (g + a_z), whose integral from t0 is
///   u(t) = u(t0) - (v_x(t) - v_x(t0)) - s mu (g (t - t0) + v_z(t) - v_z(t0)).
/// Events (slip ends at u = 0; stick ends where the bound is reached) by bisection to 1e-13 s.
class DeckSlipReference {
 public:
  DeckSlipReference(const samples::MovingDeck& deck, double mu) : d_(deck), mu_(mu) {}
  /// u at the times `times` (increasing, from 0).
  std::vector<double> relative_velocity(const std::vector<double>& times) const {
    std::vector<double> out;
    double t0 = 0.0, u0 = 0.0;
    int mode = 0;  // 0 stick, +1/-1 slip with that sign of u
    size_t k = 0;
    while (k < times.size()) {
      if (mode == 0) {
        // Stick until the demanded friction -a_x exceeds mu (g + a_z).
        const auto excess = [&](double t) { return std::abs(ax(t)) - mu_ * (g + az(t)); };
        const double end = next_root(excess, t0, times.back());
        while (k < times.size() && times[k] <= end) out.push_back(0.0), ++k;
        if (end >= times.back()) break;
        t0 = end;
        u0 = 0.0;
        mode = ax(end) > 0 ? -1 : 1;  // the deck pulls ahead: the box slips back
      } else {
        const double s = mode, start = t0, u_start = u0;
        const auto u = [&, s, start, u_start](double t) {
          return u_start - (vx(t) - vx(start)) - s * mu_ * (g * (t - start) + vz(t) - vz(start));
        };
        const auto crossing = [&](double t) { return t - start < 1e-12 ? s : u(t); };
        const double end = next_root([&](double t) { return s * crossing(t) <= 0 ? 1.0 : -1.0; }, start + 1e-9,
                                     times.back());
        while (k < times.size() && times[k] <= end) out.push_back(u(times[k])), ++k;
        if (end >= times.back()) break;
        t0 = end;
        u0 = 0.0;
        // At u = 0: stick if the bound holds, else slip the other way.
        mode = std::abs(ax(end)) <= mu_ * (g + az(end)) ? 0 : (ax(end) > 0 ? -1 : 1);
      }
    }
    return out;
  }

 private:
  double ax(double t) const { return -d_.surge_amplitude * d_.omega * d_.omega * std::sin(d_.omega * t); }
  double az(double t) const {
    return -d_.heave_amplitude * d_.omega * d_.omega * std::sin(d_.omega * t + d_.phase);
  }
  double vx(double t) const { return d_.surge_amplitude * d_.omega * std::cos(d_.omega * t); }
  double vz(double t) const { return d_.heave_amplitude * d_.omega * std::cos(d_.omega * t + d_.phase); }
  /// The first t in (from, to] where f turns positive (scanned at 1 ms, then bisected);
  /// `to` if none.
  template <typename F>
  static double next_root(const F& f, double from, double to) {
    for (double a = from; a < to; a += 1e-3) {
      const double b = std::min(a + 1e-3, to);
      if (f(b) > 0) {
        double lo = a, hi = b;
        while (hi - lo > 1e-13) (f(0.5 * (lo + hi)) > 0 ? hi : lo) = 0.5 * (lo + hi);
        return hi;
      }
    }
    return to;
  }
  samples::MovingDeck d_;
  double mu_;
};

TEST(ContactStepper, BoxOnASurgingHeavingDeckSticksAndSlipsAsTheClosedForm) {
  // Surge 3 m and heave 2 m at 1 rad/s: the deck's surge acceleration (3 m/s^2) exceeds
  // mu (g + a_z) for mu = 0.2, so the box slips back and forth and sticks between. The
  // scheme is first order: the error halves with the step.
  const samples::MovingDeck deck;
  const double mu = 0.2, seconds = 4 * M_PI;
  double error_at[2] = {0, 0};
  for (const int refinement : {0, 1}) {
    const double h = 2e-3 / (1 << refinement);
    SteppedScene run(samples::box_on_moving_deck(deck, mu, Vector3(0.5, 0.4, 0.1), 200.0), h, 8);
    const Model& model = *run.scene.model;
    const int surge_v = model.joints[model.joint_index("surge")].v_index;
    const int box = model.joint_index("box_free");
    std::vector<double> times, simulated;
    int slip_steps = 0;
    while (run.t < seconds - 0.5 * h) {
      ASSERT_TRUE(run.step().ok()) << "t = " << run.t;
      times.push_back(run.t);
      const double u = world_velocity(model, run.q, run.v, box).x() - run.v[surge_v];
      simulated.push_back(u);
      slip_steps += std::abs(u) > 1e-6;
    }
    const std::vector<double> reference = DeckSlipReference(deck, mu).relative_velocity(times);
    ASSERT_EQ(reference.size(), simulated.size());
    int reference_slip = 0;
    for (size_t k = 0; k < times.size(); ++k) {
      error_at[refinement] = std::max(error_at[refinement], std::abs(simulated[k] - reference[k]));
      reference_slip += std::abs(reference[k]) > 1e-6;
    }
    // Both slip and stick happen, for about as long in the run as in the closed form.
    EXPECT_GT(reference_slip, static_cast<int>(times.size()) / 10);
    EXPECT_LT(reference_slip, static_cast<int>(times.size()) * 9 / 10);
    EXPECT_NEAR(slip_steps, reference_slip, 0.01 * times.size());
    // The deck follows its drivers exactly (joint drivers are linear in q).
    EXPECT_NEAR(run.q[model.joints[model.joint_index("surge")].q_index], 3.0 * std::sin(run.t), 1e-9);
  }
  EXPECT_LT(error_at[1], 0.01);  // m/s, against relative speeds of order 1 m/s
  EXPECT_NEAR(error_at[0] / error_at[1], 2.0, 0.4) << error_at[0] << " " << error_at[1];
}

}  // namespace
}  // namespace heavesim
