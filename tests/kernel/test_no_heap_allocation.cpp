// No operator-new allocation in the integrators' steps. The checked build's
// no-allocation tests (test_no_malloc.cpp) see Eigen's allocations only: Eigen's check
// (EIGEN_RUNTIME_NO_MALLOC) is inside Eigen's allocator, and a std::vector, std::string
// or std::function allocates through operator new, which it never sees. Here operator
// new itself is replaced for this test program and counts while a test asks it to. The
// two together cover what C++ code allocates; not counted: malloc called directly (C
// libraries such as SUNDIALS, which allocate at set-up) and the aligned operator new.
// (Found this way: Eigen's indexed views copied their std::vector of row indices on
// every IDA residual; kernel/math/index_list.hpp.)
#include <gtest/gtest.h>

#include <cstdlib>
#include <memory>
#include <new>

#include "kernel/elements/spring_damper.hpp"
#include "kernel/integrators/integrator.hpp"
#include "kernel/system/multibody_system.hpp"
#include "samples/floating_bodies.hpp"
#include "samples/loop_mechanisms.hpp"

namespace {
bool counting_allocations = false;
long allocations_counted = 0;
}  // namespace

// The replaceable global allocation functions (C++17 [new.delete.single]); the array
// forms call these by default.
void* operator new(std::size_t size) {
  if (counting_allocations) ++allocations_counted;
  if (void* memory = std::malloc(size > 0 ? size : 1)) return memory;
  throw std::bad_alloc();
}
void operator delete(void* memory) noexcept { std::free(memory); }
void operator delete(void* memory, std::size_t) noexcept { std::free(memory); }

namespace heavesim {
namespace {

/// Counts operator new calls over its lifetime.
class AllocationCounter {
 public:
  AllocationCounter() {
    allocations_counted = 0;
    counting_allocations = true;
  }
  ~AllocationCounter() { counting_allocations = false; }
  long count() const { return allocations_counted; }
};

/// The parallelogram four-bar (a closed loop) with a spring-damper across it, moving.
std::unique_ptr<MultibodySystem> strut_four_bar(VectorX& y) {
  auto system = std::make_unique<MultibodySystem>(samples::parallelogram_four_bar());
  system->add_force_element(std::make_unique<SpringDamper>("strut", BodyPoint{0, Vector3(0, -1, 0)},
                                                          BodyPoint{1, Vector3(0.5, 0, 0)},
                                                          SpringDamperParameters{100.0, 5.0, 0.5}));
  y = system->initial_state(Vector3(0.3, -0.3, 0.3), Vector3(1.0, -1.0, 1.0));
  return system;
}

TEST(NoHeapAllocation, TheCounterSeesAStandardContainer) {
  AllocationCounter counter;
  std::vector<int> copied(3, 1);
  const long counted = counter.count();
  EXPECT_EQ(copied.size() + copied[2], 4u);  // used, so that its allocation is not elided
  EXPECT_EQ(counted, 1);
}

TEST(NoHeapAllocation, IntegratorStepsOnAClosedLoop) {
  // Every integrator that steps a closed loop: IDA on the stabilized index-2 DAE with its
  // own Newton matrix (dense LU), the explicit ones on the projected ODE, HHT on the
  // index-3 form, the contact stepper's velocity-level loop. The first output interval
  // sizes every workspace; the later ones must not allocate at all.
  for (const IntegrationMethod method :
       {IntegrationMethod::ida, IntegrationMethod::rk4, IntegrationMethod::dopri5, IntegrationMethod::hht,
        IntegrationMethod::contact}) {
    VectorX y;
    const std::unique_ptr<MultibodySystem> system = strut_four_bar(y);
    IntegratorSettings settings;
    settings.method = method;
    settings.step = 1e-3;
    settings.relative_tolerance = settings.absolute_tolerance = 1e-8;
    auto integrator = make_integrator(settings, *system);
    integrator->initialize(0.0, y);
    integrator->advance_to(0.01);
    AllocationCounter counter;
    for (int k = 2; k <= 20; ++k) integrator->advance_to(0.01 * k);
    EXPECT_EQ(counter.count(), 0) << integration_method_name(method);
    EXPECT_GT(integrator->statistics().steps, 20) << integration_method_name(method);
  }
}

TEST(NoHeapAllocation, IdaStepsOnAFreeBody) {
  // A free joint: the quaternion's maps N and N+ in the residual and the Newton matrix.
  MultibodySystem system(samples::free_floating_body(
      "box", Inertia(2.0, Vector3(0.1, 0.0, 0.0), Matrix3(Vector3(0.3, 0.4, 0.5).asDiagonal()))));
  VectorX q(7);
  q << 0.1, 0.2, 0.3, std::sqrt(0.5), std::sqrt(0.5), 0.0, 0.0;
  IntegratorSettings settings;
  settings.method = IntegrationMethod::ida;
  auto integrator = make_integrator(settings, system);
  integrator->initialize(0.0, system.initial_state(q, VectorX::Constant(6, 0.3)));
  integrator->advance_to(0.01);
  AllocationCounter counter;
  for (int k = 2; k <= 20; ++k) integrator->advance_to(0.01 * k);
  EXPECT_EQ(counter.count(), 0);
}

}  // namespace
}  // namespace heavesim
