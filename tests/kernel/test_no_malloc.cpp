// No heap allocation in the hot paths: the kernel is compiled for this test with
// EIGEN_RUNTIME_NO_MALLOC, and Eigen's allocation check throws (see
// no_malloc_config.hpp) if anything allocates while allocation is forbidden.
#include <gtest/gtest.h>

#include <sunmatrix/sunmatrix_dense.h>

#include <cmath>

#include <array>
#include <random>

#include "app/case/coordinate_expression.hpp"
#include "control/active/active_compensator.hpp"
#include "control/pneumatic/pneumatic_compensator.hpp"
#include "kernel/algorithms/constraint_equations.hpp"
#include "kernel/complementarity/fallback_chain.hpp"
#include "kernel/contact/contact_stepper.hpp"
#include "samples/contact_scenes.hpp"
#include "kernel/complementarity/gauss_seidel.hpp"
#include "kernel/algorithms/forward_dynamics.hpp"
#include "kernel/algorithms/joint_forces.hpp"
#include "kernel/algorithms/joint_reactions.hpp"
#include "kernel/analysis/kinematic_analysis.hpp"
#include "kernel/elements/ground_contact.hpp"
#include "kernel/elements/spring_damper.hpp"
#include "kernel/integrators/dense_lu_linear_solver.hpp"
#include "kernel/integrators/reforming_linear_solver.hpp"
#include "kernel/integrators/integrator.hpp"
#include "kernel/integrators/sundials_support.hpp"
#include "kernel/model/model_builder.hpp"
#include "kernel/system/ggl_dae_form.hpp"
#include "kernel/system/multibody_system.hpp"
#include "kernel/system/ode_form.hpp"
#include "samples/complementarity_problems.hpp"
#include "samples/floating_bodies.hpp"
#include "samples/loop_mechanisms.hpp"
#include "kernel/algorithms/inverse_dynamics_derivatives.hpp"
#include "samples/random_models.hpp"

namespace heavesim {
namespace {

struct ForbidAllocation {
  ForbidAllocation() { Eigen::internal::set_is_malloc_allowed(false); }
  ~ForbidAllocation() { Eigen::internal::set_is_malloc_allowed(true); }
};

TEST(NoMalloc, AllocationCheckIsActive) {
  ForbidAllocation forbid;
  EXPECT_THROW({ VectorX v(100); (void)v; }, std::runtime_error);
}

TEST(NoMalloc, KernelAlgorithmsDoNotAllocate) {
  std::mt19937_64 random(3);
  samples::RandomTreeOptions options;
  options.bodies = 21;  // all seven joint types, three times
  options.added_inertia = true;
  const Model model = samples::random_tree(random, options);
  Data data(model);
  const samples::RandomState state = samples::random_state(model, random);
  VectorX tau = state.tau;
  const auto every_algorithm = [&] {
    update_positions(model, data, state.q);
    update_velocities(model, data, state.q, state.v);
    add_joint_element_forces(model, state.q, state.v, tau);
    inverse_dynamics(model, data, state.tau, state.external_forces);
    mass_matrix(model, data);
    articulated_body_forward_dynamics(model, data, tau, state.external_forces);
    composite_rigid_body_forward_dynamics(model, data, tau, state.external_forces);
    compute_joint_wrenches(model, data, state.external_forces);
    joint_reaction(model, data, 5);
    inverse_dynamics_derivatives(model, data, state.q, state.v, data.qdd, state.external_forces);
  };
  // The first call sizes the dense nv x nv matrices (M, its factor, dtau/dq, dtau/dv:
  // Data(model) is O(n) and leaves them for the algorithms that need them); it must and
  // does allocate. From the second call on, nothing does.
  {
    ForbidAllocation forbid;
    EXPECT_THROW(every_algorithm(), std::runtime_error);
  }
  every_algorithm();
  {
    ForbidAllocation forbid;
    EXPECT_NO_THROW(every_algorithm());
  }
}

TEST(NoMalloc, ConstraintEquationsOfEveryKindDoNotAllocate) {
  // Loop joints of every kind, a distance, a coupler and the joint, absolute, distance
  // and angle drivers: Phi, J, nu, gamma and the loads, per time point of a kinematic
  // sweep and per step of a run.
  std::mt19937_64 random(5);
  samples::RandomTreeOptions options;
  options.bodies = 10;
  options.constraints = true;
  const Model model = samples::random_tree(random, options);
  Data data(model);
  const samples::RandomState state = samples::random_state(model, random);
  const int m = model.num_constraint_rows;
  VectorX phi(m), nu(m), gamma(m), lambda = VectorX::Ones(m), tau = VectorX::Zero(model.nv);
  MatrixX J(m, model.nv);
  AlignedVector<Force> loads(model.num_links(), Force::Zero());
  ForbidAllocation forbid;
  EXPECT_NO_THROW({
    update_positions(model, data, state.q);
    update_velocities(model, data, state.q, state.v);
    constraint_residual(model, data, state.q, 0.7, phi);
    constraint_jacobian(model, data, 0.7, J);
    constraint_velocity_target(model, data, 0.7, nu);
    constraint_bias(model, data, 0.7, gamma);
    add_constraint_loads(model, data, 0.7, lambda, loads, tau);
  });
}

TEST(NoMalloc, ExpressionConstraintDoesNotAllocate) {
  // A cam s = r sin(theta) + 0.01 t theta written as an expression: Phi, J, nu, gamma and
  // its load gather x on the stack and evaluate the expression's bytecode on a stack
  // sized when it was parsed.
  ModelBuilder builder;
  builder.add_body({"cam", Inertia(1.0, Vector3::Zero(), Matrix3::Identity()), std::nullopt});
  builder.add_body({"follower", Inertia(2.0, Vector3::Zero(), Matrix3::Identity()), std::nullopt});
  JointDefinition joint;
  joint.name = "shaft", joint.kind = JointKind::revolute, joint.parent = "ground", joint.child = "cam";
  builder.add_joint(joint);
  joint.name = "slide", joint.kind = JointKind::prismatic, joint.child = "follower";
  builder.add_joint(joint);
  builder.add_expression_constraint(
      {"cam_profile", {{"s", "slide", {}}, {"theta", "shaft", {}}},
       std::make_shared<const CoordinateExpression>("s - 0.2*sin(theta) + 0.01*t*theta",
                                                    std::vector<std::string>{"s", "theta"},
                                                    std::map<std::string, double>{})});
  const Model model = builder.build();
  Data data(model);
  const VectorX q = Eigen::Vector2d(0.1, 0.7), v = Eigen::Vector2d(-0.3, 2.0);
  VectorX phi(1), nu(1), gamma(1), lambda = VectorX::Ones(1), tau = VectorX::Zero(model.nv);
  MatrixX J(1, model.nv);
  AlignedVector<Force> loads(model.num_links(), Force::Zero());
  ForbidAllocation forbid;
  EXPECT_NO_THROW({
    update_positions(model, data, q);
    update_velocities(model, data, q, v);
    constraint_residual(model, data, q, 0.7, phi);
    constraint_jacobian(model, data, 0.7, J);
    constraint_velocity_target(model, data, 0.7, nu);
    constraint_bias(model, data, 0.7, gamma);
    add_constraint_loads(model, data, 0.7, lambda, loads, tau);
  });
}

TEST(NoMalloc, SystemDerivativeDoesNotAllocate) {
  std::mt19937_64 random(4);
  auto model = std::make_shared<const Model>(samples::random_tree(random, samples::RandomTreeOptions{}));
  for (ForwardDynamicsMethod method : {ForwardDynamicsMethod::articulated_body, ForwardDynamicsMethod::composite_rigid_body}) {
    SystemSettings settings;
    settings.method = method;
    MultibodySystem system(model, settings);
    const samples::RandomState state = samples::random_state(*model, random);
    OdeForm ode(system);
    VectorX y = system.initial_state(state.q, state.v), ydot(system.size());
    ForbidAllocation forbid;
    EXPECT_NO_THROW(ode.derivative(0.0, y, ydot));
    EXPECT_NO_THROW(ode.project(0.0, y));
  }
}

/// The parallelogram four-bar with a spring-damper strut, started on its loop and moving.
struct StrutFourBar {
  StrutFourBar() : system(samples::parallelogram_four_bar()) {
    system.add_force_element(std::make_unique<SpringDamper>("strut", BodyPoint{0, Vector3(0, -1, 0)},
                                                            BodyPoint{1, Vector3(0.5, 0, 0)},
                                                            SpringDamperParameters{100.0, 5.0, 0.5}));
    VectorX q(3), v(3);
    q << 0.3, -0.3, 0.3;  // the coupler stays parallel to the ground link
    v << 1.0, -1.0, 1.0;
    y = system.initial_state(q, v);
  }
  MultibodySystem system;
  VectorX y;
};

// The bit-on-bottom contact: its force (in contact: the surface above the point) and
// its channels in the derivative and output path.
TEST(NoMalloc, GroundContactDoesNotAllocate) {
  StrutFourBar four_bar;
  four_bar.system.add_force_element(std::make_unique<GroundContact>(
      "bit", BodyPoint{1, Vector3(0.5, 0, 0)}, GroundContactParameters{5e7, 5e5, 10.0}));
  const ForceElement& contact = *four_bar.system.force_elements().back();
  VectorX y = four_bar.system.initial_state(VectorX::Constant(3, 0.3).cwiseProduct(Vector3(1, -1, 1)), Vector3(1, -1, 1));
  VectorX ydot(four_bar.system.size());
  std::array<double, 2> values{};
  ForbidAllocation forbid;
  EXPECT_NO_THROW(four_bar.system.state_derivative(0.0, y, ydot));
  contact.outputs(0.0, four_bar.system.model(), four_bar.system.data(), y.tail(0), values);
  EXPECT_GT(values[0], 0.0);
}

TEST(NoMalloc, ClosedLoopDaeResidualDoesNotAllocate) {
  StrutFourBar four_bar;
  GglDaeForm system(four_bar.system);
  VectorX dae_y, dae_yp;
  // Sizes the DAE's workspaces (and picks its independent rows): allowed to allocate.
  system.dae_initial_values(0.0, four_bar.y, dae_y, dae_yp);
  VectorX residual(dae_y.size());
  system.residual(0.0, dae_y, dae_yp, residual);
  ForbidAllocation forbid;
  EXPECT_NO_THROW(system.residual(0.0, dae_y, dae_yp, residual));
}

TEST(NoMalloc, DaeNewtonMatrixDoesNotAllocate) {
  // IDA rebuilds the Newton matrix dF/dy + cj dF/dy' many times per run: with a closed
  // loop (the multiplier columns) and with a free joint (the quaternion's N and N+).
  StrutFourBar four_bar;
  MultibodySystem floating(samples::free_floating_body("box", Inertia(2.0, Vector3(0.1, 0.0, 0.0),
                                                                    Matrix3(Vector3(0.3, 0.4, 0.5).asDiagonal()))));
  VectorX floating_q(7);
  floating_q << 0.1, 0.2, 0.3, std::sqrt(0.5), std::sqrt(0.5), 0.0, 0.0;  // turned 90 degrees about x
  for (MultibodySystem* system : {&four_bar.system, &floating}) {
    GglDaeForm form(*system);
    const VectorX state =
        system == &floating ? floating.initial_state(floating_q, VectorX::Constant(6, 0.3)) : four_bar.y;
    VectorX dae_y, dae_yp;
    form.dae_initial_values(0.0, state, dae_y, dae_yp);
    MatrixX residual_y(dae_y.size(), dae_y.size()), residual_yp(dae_y.size(), dae_y.size());
    form.jacobian(0.0, dae_y, dae_yp, residual_y, residual_yp);  // first use sizes the workspaces
    VectorX residual(dae_y.size()), moved = dae_y;
    moved.head(system->model().nq).array() += 0.2;  // J has turned: the loop's blocks are rewritten
    form.residual(0.0, moved, dae_yp, residual);
    ForbidAllocation forbid;
    EXPECT_NO_THROW(form.jacobian(0.0, dae_y, dae_yp, residual_y, residual_yp));
    bool refreshed = false;
    EXPECT_NO_THROW(refreshed = form.refresh_jacobian(residual_y));
    EXPECT_EQ(refreshed, system == &four_bar.system);  // the loop's blocks rewritten; none without a loop
  }
}

TEST(NoMalloc, DenseLuLinearSolverDoesNotAllocate) {
  // IDA factors its Newton matrix with this solver at every matrix and solves with it at
  // every Newton iteration; a size past Eigen's LU blocking (> 16). With x and b the same
  // vector too: Eigen's in-place permutation allocates a mask (found here).
  const int n = 40;
  sundials::Context context;
  SUNMatrix matrix = SUNDenseMatrix(n, n, context);
  N_Vector rhs = N_VNew_Serial(n, context), solution = N_VNew_Serial(n, context);
  std::mt19937_64 random(5);
  std::uniform_real_distribution<double> entry(-1.0, 1.0);
  Eigen::Map<MatrixX>(SUNDenseMatrix_Data(matrix), n, n) = MatrixX::NullaryExpr(n, n, [&] { return entry(random); });
  sundials::map(rhs) = VectorX::NullaryExpr(n, [&] { return entry(random); });
  SUNLinearSolver solver = sundials::make_dense_lu_linear_solver(matrix, context);
  {
    ForbidAllocation forbid;
    EXPECT_NO_THROW({
      EXPECT_EQ(SUNLinSolSetup(solver, matrix), SUNLS_SUCCESS);
      EXPECT_EQ(SUNLinSolSolve(solver, matrix, solution, rhs, 0.0), SUNLS_SUCCESS);
      EXPECT_EQ(SUNLinSolSolve(solver, matrix, rhs, rhs, 0.0), SUNLS_SUCCESS);
    });
  }
  SUNLinSolFree(solver);
  // Wrapped to re-form the Newton matrix: a solve after a refresh re-forms and factors it;
  // one at a cj within the kept band solves with the factor and scales.
  struct Parts {
    MatrixX residual_y, residual_yp, work;
    double cj = 3.0;
    bool refresh = true;
  } parts{Eigen::Map<MatrixX>(SUNDenseMatrix_Data(matrix), n, n), MatrixX::Identity(n, n), MatrixX(n, n)};
  solver = sundials::make_reforming_linear_solver(
      sundials::make_dense_lu_linear_solver(matrix, context),
      {[](void* p) { return static_cast<Parts*>(p)->cj; }, [](void* p) { return static_cast<Parts*>(p)->refresh; },
       [](void* p, double cj, SUNMatrix m) {
         auto& parts = *static_cast<Parts*>(p);
         parts.work.noalias() = parts.residual_y + cj * parts.residual_yp;
         Eigen::Map<MatrixX>(SUNDenseMatrix_Data(m), parts.work.rows(), parts.work.cols()) = parts.work;
       },
       &parts},
      context);
  {
    ForbidAllocation forbid;
    EXPECT_NO_THROW({
      EXPECT_EQ(SUNLinSolSetup(solver, matrix), SUNLS_SUCCESS);
      parts.cj = 4.5;
      EXPECT_EQ(SUNLinSolSolve(solver, matrix, solution, rhs, 0.0), SUNLS_SUCCESS);
      parts.refresh = false;
      parts.cj = 4.5 * (1.0 + 0.5 * sundials::kCjChangeSolvedWithTheFactor);
      EXPECT_EQ(SUNLinSolSolve(solver, matrix, solution, rhs, 0.0), SUNLS_SUCCESS);
    });
  }
  SUNLinSolFree(solver);
  N_VDestroy(rhs);
  N_VDestroy(solution);
  SUNMatDestroy(matrix);
}

TEST(NoMalloc, ClosedLoopExplicitPathDoesNotAllocate) {
  // The KKT solve (minimum-norm multipliers by the regularized Cholesky of J M^-1 J^T)
  // and the projection after each explicit step.
  StrutFourBar four_bar;
  OdeForm ode(four_bar.system);
  VectorX ydot(four_bar.system.size());
  ode.derivative(0.0, four_bar.y, ydot);  // first use sizes the workspaces
  ForbidAllocation forbid;
  EXPECT_NO_THROW(ode.derivative(0.0, four_bar.y, ydot));
  EXPECT_NO_THROW(ode.project(0.0, four_bar.y));
}

TEST(NoMalloc, KinematicTimePointDoesNotAllocate) {
  // The kinematic analysis of one time point (predictor, Newton with line search and the
  // pivoted-QR minimum-norm solves in the mass and unit metrics, the singular values)
  // and the inverse dynamics of the prescribed motion, on a four-bar with redundant rows.
  StrutFourBar four_bar;
  const Model& model = four_bar.system.model();
  Data& data = four_bar.system.mutable_data();
  for (const MotionWeighting weighting : {MotionWeighting::mass, MotionWeighting::unit}) {
    KinematicSettings settings;
    settings.weighting = weighting;
    KinematicWorkspace workspace(model);
    VectorX q = four_bar.y.head(model.nq), v = VectorX::Zero(model.nv), a = VectorX::Zero(model.nv);
    VectorX y = four_bar.y;
    analyse_time_point(model, data, workspace, settings, 0.0, 0.0, q, v, a);  // sizes Eigen's internals
    ForbidAllocation forbid;
    EXPECT_NO_THROW({
      const KinematicPoint point = analyse_time_point(model, data, workspace, settings, 0.01, 0.01, q, v, a);
      EXPECT_TRUE(point.converged);
      y.head(model.nq) = q;
      y.segment(model.nq, model.nv) = v;
      four_bar.system.evaluate_prescribed(0.01, y, a, true);
    });
  }
}

TEST(NoMalloc, HhtStepsDoNotAllocate) {
  StrutFourBar four_bar;
  IntegratorSettings settings;
  settings.method = IntegrationMethod::hht;
  settings.step = 1e-3;
  auto integrator = make_integrator(settings, four_bar.system);
  integrator->initialize(0.0, four_bar.y);
  integrator->advance_to(0.002);  // first steps size every workspace
  ForbidAllocation forbid;
  EXPECT_NO_THROW(integrator->advance_to(0.05));
}

/// A platform heaving on a prismatic joint, a load on the stroke joint, and every
/// compensator state the control library has: gas temperature, PID integral,
/// centring reference, MRU filter, force-actuator lag, spool and chamber pressures.
std::unique_ptr<MultibodySystem> compensated_rig() {
  ModelBuilder builder;
  builder.add_body({"platform", Inertia(1e6, Vector3::Zero(), Matrix3::Identity() * 1e8), std::nullopt});
  builder.add_body({"load", Inertia(2.9e5, Vector3::Zero(), Matrix3::Identity() * 1e6), std::nullopt});
  JointDefinition heave, stroke;
  heave.name = "heave";
  heave.kind = stroke.kind = JointKind::prismatic;
  heave.parent = "ground";
  heave.child = stroke.parent = "platform";
  stroke.name = "stroke";
  stroke.child = "load";
  builder.add_joint(heave);
  builder.add_joint(stroke);
  auto model = std::make_shared<const Model>(builder.build());
  auto system = std::make_unique<MultibodySystem>(model);
  const StrokeAxis joint_axis = StrokeAxis::on_joint(*model, 2, 0.0);
  const StrokeAxis body_axis = StrokeAxis::between(*model, BodyPoint{1, Vector3::Zero()}, BodyPoint{2, Vector3::Zero()},
                                                   Vector3::UnitZ(), 0.0);
  PneumaticParameters gas;
  gas.cooling = GasCooling{30.0, 288.15};
  gas.exponent_compression = 1.3;
  gas.piping = piping_loss_from_pipe(30.0, 0.2, 0.05, 870.0, 3.0);
  gas.friction = {26e3, 1e3, 0.01};
  system->add_force_element(std::make_unique<PneumaticCompensator>("passive", joint_axis, gas));
  ActiveCompensatorParameters hydraulic;
  hydraulic.actuator = ActuatorType::hydraulic;
  hydraulic.gains = {0.5, 0.05, 0.2, 0.0, 1.0};
  hydraulic.velocity_feedforward = 0.3;
  hydraulic.acceleration_feedforward = 0.01;
  hydraulic.centring_time = 60.0;
  hydraulic.mru = MruParameters{};
  hydraulic.controlled_point = BodyPoint{2, Vector3::Zero()};
  system->add_force_element(std::make_unique<ActiveCompensator>("hydraulic", body_axis, hydraulic));
  ActiveCompensatorParameters force;
  force.gains = {1e6, 2e5, 9e5, 0.0, 3.9e5};
  force.force_actuator.max_rate = 1e6;
  force.controlled_point = BodyPoint{2, Vector3::Zero()};
  system->add_force_element(std::make_unique<ActiveCompensator>("force", joint_axis, force));
  return system;
}

TEST(NoMalloc, CompensatorsDoNotAllocate) {
  auto system = compensated_rig();
  VectorX q(2), v(2);
  q << 0.3, -0.4;
  v << 0.5, -0.2;
  VectorX y = system->initial_state(q, v), ydot(system->size());
  std::vector<std::vector<double>> values;
  for (const auto& element : system->force_elements()) values.emplace_back(element->channels().size());
  GglDaeForm dae(*system);
  VectorX dae_y, dae_yp;
  dae.dae_initial_values(0.0, y, dae_y, dae_yp);
  VectorX residual(dae_y.size());
  dae.residual(0.0, dae_y, dae_yp, residual);
  ForbidAllocation forbid;
  EXPECT_NO_THROW(system->state_derivative(0.0, y, ydot));  // apply() and state_derivative() of each element
  EXPECT_NO_THROW(dae.residual(0.0, dae_y, dae_yp, residual));
  EXPECT_NO_THROW({
    for (std::size_t e = 0; e < values.size(); ++e) {
      const ForceElement& element = *system->force_elements()[e];
      element.outputs(0.0, system->model(), system->data(), y.segment(system->state_offset(e), element.state_size()),
                      values[e]);
    }
  });
}

TEST(NoMalloc, ComplementaritySolversDoNotAllocate) {
  // Workspaces larger than the problem (a contact count that varies from step to step),
  // a plain LCP, a boxed one and one with friction rows; every solver and the chain.
  const int n = 12;
  const samples::LcpSample sample = samples::random_spd_lcp(n, 3);
  const VectorX lo = -VectorX::Constant(n, 0.3), hi = VectorX::Constant(n, 0.4);
  Eigen::VectorXi normal = Eigen::VectorXi::Constant(n, -1);
  normal[1] = normal[2] = 0;
  const VectorX mu = VectorX::Constant(n, 0.5);
  const ComplementarityProblem plain{sample.M, sample.q};
  const ComplementarityProblem boxed{sample.M, sample.q, lo, hi};
  const ComplementarityProblem friction{sample.M, sample.q, std::nullopt, std::nullopt, normal, mu};
  ComplementarityWorkspace workspace(n + 5);
  GaussSeidelWorkspace linear(n);
  std::vector<LemkePivot> pivots;
  pivots.reserve(4 * n);
  LemkeOptions lemke_options;
  lemke_options.pivot_log = &pivots;
  VectorX z(n), x(n);
  ForbidAllocation forbid;
  EXPECT_NO_THROW({
    EXPECT_TRUE(lemke(plain, workspace.lemke, z, lemke_options).solved());
    EXPECT_TRUE(lemke(boxed, workspace.lemke, z).solved());
    EXPECT_TRUE(dantzig(plain, workspace.dantzig, z).solved());
    EXPECT_TRUE(dantzig(boxed, workspace.dantzig, z).solved());
    dantzig(friction, workspace.dantzig, z);
    EXPECT_TRUE(projected_gauss_seidel(friction, workspace.projected_gauss_seidel, z).solved());
    EXPECT_TRUE(solve_complementarity(boxed, workspace, z).solved());
    EXPECT_TRUE(gauss_seidel(sample.M, sample.q, linear, x).solved());
  });
}

TEST(NoMalloc, ContactSteppingDoesNotAllocate) {
  // A 20-box stack (240 contact rows: the Delassus product and Dantzig on the largest
  // problem here), and a ball dropped 5 cm with restitution 0.5 while sliding (its
  // contact count changes between 0 and 1 as it bounces, its friction rows sit at their
  // bounds, then it rolls): after the first step no step allocates, whatever its
  // contact count (the buffers hold the most contacts).
  for (const int case_index : {0, 1}) {
    samples::ContactScene scene = case_index == 0 ? samples::box_stack(20, 1.0, 10.0, 1.0, 0.5)
                                                  : samples::sphere_on_plane(0.2, 2.0, 0.25, 0.3, 0.5);
    ContactStepper stepper(*scene.model, scene.contacts, 80);
    Data data(*scene.model);
    VectorX q = scene.q, v = scene.v, tau = VectorX::Zero(scene.model->nv);
    if (case_index == 1) v[3] = 2.0;
    ASSERT_TRUE(stepper.step(data, 0.0, 1e-3, q, v, tau).ok());
    ForbidAllocation forbid;
    EXPECT_NO_THROW({
      for (int k = 1; k <= (case_index == 0 ? 50 : 300); ++k)
        EXPECT_TRUE(stepper.step(data, k * 1e-3, 1e-3, q, v, tau).ok());
    }) << "scene " << case_index;
  }
}

}  // namespace
}  // namespace heavesim
