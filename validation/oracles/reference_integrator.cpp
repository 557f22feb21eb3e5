#include "validation/oracles/reference_integrator.hpp"

#include <cstdio>

#include <arkode/arkode_erkstep.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>

#include <stdexcept>

namespace heavesim::oracle {
namespace {

int call_rhs(double t, N_Vector y, N_Vector ydot, void* user_data) {
  const Rhs& rhs = *static_cast<const Rhs*>(user_data);
  const Eigen::VectorXd state = Eigen::Map<Eigen::VectorXd>(N_VGetArrayPointer(y), N_VGetLength(y));
  Eigen::VectorXd derivative(state.size());
  rhs(t, state, derivative);
  Eigen::Map<Eigen::VectorXd>(N_VGetArrayPointer(ydot), N_VGetLength(ydot)) = derivative;
  return 0;
}

}  // namespace

std::vector<Eigen::VectorXd> integrate_reference(const Rhs& rhs, double t0, const Eigen::VectorXd& y0,
                                                 const std::vector<double>& times, double relative_tolerance,
                                                 double absolute_tolerance) {
  SUNContext context = nullptr;
  SUNContext_Create(nullptr, &context);
  N_Vector y = N_VNew_Serial(y0.size(), context);
  Eigen::Map<Eigen::VectorXd>(N_VGetArrayPointer(y), y0.size()) = y0;
  void* arkode = ERKStepCreate(call_rhs, t0, y, context);
  ERKStepSetUserData(arkode, const_cast<Rhs*>(&rhs));
  ERKStepSetTableNum(arkode, ARKODE_FEHLBERG_13_7_8);
  ERKStepSStolerances(arkode, relative_tolerance, absolute_tolerance);
  ERKStepSetMaxNumSteps(arkode, 10000000);
  // A stiff reference (the A05 governor's spring-dampers) keeps an explicit method's step on
  // its stability boundary, where the controller may overshoot several times in a row;
  // ARKODE's default of 7 consecutive error-test failures then aborts a run that succeeds
  // with more retries. Runs that never reach 7 failures are unchanged.
  ERKStepSetMaxErrTestFails(arkode, 100);

  std::vector<Eigen::VectorXd> result;
  result.reserve(times.size());
  double t_reached = t0;
  for (double t : times) {
    if (t > t_reached) {
      const int flag = ERKStepEvolve(arkode, t, y, &t_reached, ARK_NORMAL);
      if (flag < 0) {
        ERKStepFree(&arkode);
        N_VDestroy(y);
        SUNContext_Free(&context);
        throw std::runtime_error("reference integration failed");
      }
    }
    result.emplace_back(Eigen::Map<Eigen::VectorXd>(N_VGetArrayPointer(y), y0.size()));
  }
  ERKStepFree(&arkode);
  N_VDestroy(y);
  SUNContext_Free(&context);
  return result;
}

}  // namespace heavesim::oracle
