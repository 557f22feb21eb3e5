// P3, P4: velocity-level contact stepping (kernel/contact) against statics and the
// Coulomb closed form (docs/physics/contact.md).
//   P3  a box on a 30-degree incline: slides with a = g (sin - mu cos) for mu < tan 30,
//       sticks for mu >= tan 30 (the corner impulses then carry m g h exactly);
//   P4  20 cubes stacked on the ground, uniform and with the top cube 100 times the
//       bottom one, 10 s at rest: each face carries the weight above it, no box moves.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "kernel/contact/contact_stepper.hpp"
#include "samples/contact_scenes.hpp"
#include "validation/checks/validation_suite.hpp"

namespace heavesim::validation {

namespace {

struct Stepped {
  samples::ContactScene scene;
  Data data;
  ContactStepper stepper;
  double h;
  VectorX q, v, tau;
  Stepped(samples::ContactScene s, double h, int max_contacts)
      : scene(std::move(s)),
        data(*scene.model),
        stepper(*scene.model, scene.contacts, max_contacts),
        h(h),
        q(scene.q),
        v(scene.v),
        tau(VectorX::Zero(scene.model->nv)) {}
  /// Steps for `seconds`; false (with `failure` set) if a step's solve failed.
  bool run(double seconds, std::string& failure, const std::function<void()>& after_step = {}) {
    const int steps = static_cast<int>(std::lround(seconds / h));
    for (int k = 0; k < steps; ++k) {
      const ContactStepReport report = stepper.step(data, k * h, h, q, v, tau);
      if (!report.ok()) {
        failure = report.solve.message;
        return false;
      }
      if (after_step) after_step();
    }
    return true;
  }
  /// World velocity of body 1's origin [m/s].
  Vector3 velocity() const {
    const Eigen::Quaterniond orientation(q[3], q[4], q[5], q[6]);
    return orientation.normalized() * v.segment<3>(3);
  }
};

}  // namespace

std::vector<ValidationRow> check_p3_block_on_incline() {
  std::vector<ValidationRow> rows;
  const double slope = M_PI / 6, h = 1e-3, seconds = 1.0, mass = 20.0;
  const Vector3 down_slope(std::cos(slope), 0.0, -std::sin(slope));
  const Vector3 half(0.4, 0.3, 0.1);
  std::string failure;
  {
    const double mu = 0.5;
    Stepped box(samples::box_on_incline(slope, mu, half, mass), h, 16);
    const bool ran = box.run(seconds, failure);
    const double expected = g * (std::sin(slope) - mu * std::cos(slope));  // 0.6569 m/s^2
    const Vector3 velocity = box.velocity();
    const double error =
        ran ? std::max(std::abs(velocity.dot(down_slope) / seconds - expected) / expected,
                       (velocity - velocity.dot(down_slope) * down_slope).norm() / (expected * seconds))
            : INFINITY;
    rows.push_back({"P3", "box on a 30 deg incline, mu = 0.5 < tan 30, 1 s at h = 1 ms" + failure,
                    "down-slope acceleration vs g (sin - mu cos) = 0.657 m/s^2, relative", error, 1e-9});
  }
  for (const double mu : {std::tan(slope) + 1e-3, 0.9}) {
    Stepped box(samples::box_on_incline(slope, mu, half, mass), h, 16);
    const bool ran = box.run(seconds, failure);
    Vector3 impulse = Vector3::Zero();
    for (int c = 0; c < static_cast<int>(box.stepper.contacts().size()); ++c)
      impulse += box.stepper.contact_impulse_world(c);
    const double weight_impulse = mass * g * h;
    const std::string subject = "box on a 30 deg incline, mu = " + std::to_string(mu).substr(0, 5) + " >= tan 30, 1 s";
    rows.push_back({"P3", subject, "speed / (g t): it sticks", ran ? box.velocity().norm() / (g * seconds) : INFINITY,
                    1e-9});
    rows.push_back({"P3", subject, "corner impulses vs m g h upwards, relative",
                    ran ? (impulse - Vector3(0, 0, weight_impulse)).norm() / weight_impulse : INFINITY, 1e-9});
  }
  return rows;
}

std::vector<ValidationRow> check_p4_box_stacks() {
  std::vector<ValidationRow> rows;
  const int count = 20;
  const double h = 1e-2, seconds = 10.0;
  for (const double mass_ratio : {1.0, 100.0}) {
    Stepped stack(samples::box_stack(count, 1.0, 10.0, mass_ratio, 0.5), h, 4 * count);
    double weight_error = 0.0;
    ComplementarityResult last;
    std::string failure;
    const bool ran = stack.run(seconds, failure, [&] {
      std::vector<double> face(count, 0.0);
      const auto contacts = stack.stepper.contacts();
      for (int c = 0; c < static_cast<int>(contacts.size()); ++c)
        face[contacts[c].pair] += stack.stepper.contact_impulse_world(c).z() / h;
      double above = 0.0;
      for (int i = count - 1; i >= 0; --i) {
        above += stack.scene.masses[i] * g;
        weight_error = std::max(weight_error, std::abs(face[i] - above) / above);
      }
    });
    double drift = 0.0;
    for (int i = 1; i <= count; ++i) {
      const int qi = stack.scene.model->joints[i].q_index;
      drift = std::max(drift, (stack.q.segment<3>(qi) - stack.scene.q.segment<3>(qi)).norm());
    }
    const std::string subject = std::to_string(count) + " cubes, 4 points per face, top/bottom mass " +
                                (mass_ratio == 1.0 ? "1:1" : "100:1") + ", 10 s at h = 10 ms" +
                                (ran ? "" : " (failed: " + failure + ")");
    rows.push_back({"P4", subject, "face loads vs the weight above, relative, worst face and step",
                    ran ? weight_error : INFINITY, 1e-8});
    rows.push_back({"P4", subject, "drift of any cube's centre [m]", ran ? drift : INFINITY, 1e-8});
  }
  return rows;
}

}  // namespace heavesim::validation
