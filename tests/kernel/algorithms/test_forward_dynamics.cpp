// Forward dynamics: a non-finite acceleration stops the system with a diagnosis.
#include <gtest/gtest.h>

#include "kernel/system/multibody_system.hpp"
#include "samples/oscillators.hpp"

namespace heavesim {
namespace {

TEST(Dynamics, NonFiniteAccelerationStopsWithADiagnosisNamingTheJoint) {
  auto model = std::make_shared<const Model>(samples::prismatic_oscillator(1.0, 1e300));
  MultibodySystem system(model);
  VectorX y = system.initial_state(VectorX::Constant(1, 1e300), VectorX::Zero(1)), ydot(2);
  try {
    system.derivative(0.0, y, ydot);
    FAIL() << "expected a NumericalError";
  } catch (const NumericalError& error) {
    EXPECT_NE(std::string(error.what()).find("joint 'slide'"), std::string::npos) << error.what();
    EXPECT_FALSE(error.suggestion().empty());
  }
}

}  // namespace
}  // namespace heavesim
