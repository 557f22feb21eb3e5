#pragma once
// Glue between Eigen vectors and SUNDIALS serial N_Vectors, and an owning context.
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>

#include <cstdlib>
#include <exception>
#include <string>

#include "kernel/system/ode_system.hpp"

namespace heavesim::sundials {

/// The components of a serial N_Vector (every vector the integrators make or receive is
/// one: ours or IDA's and ARKODE's clones of ours). Read through the serial content, not
/// N_VGetArrayPointer and N_VGetLength: Debian's SUNDIALS is built without optimization
/// (serial_vector.hpp), and those two dispatches cost ~50 instructions a map, several maps
/// per residual and per vector operation.
inline Eigen::Map<VectorX> map(N_Vector v) { return Eigen::Map<VectorX>(NV_DATA_S(v), NV_LENGTH_S(v)); }

/// The text of a SUNDIALS *GetReturnFlagName result, which the caller must free().
inline std::string take_flag_name(char* name) {
  std::string text = name ? name : "unknown flag";
  std::free(name);
  return text;
}

/// "; largest local error in the <component>" for the component with the largest
/// |error * weight| among those with a nonzero `counted` entry (all when null), from a
/// solver's last step attempt; "" when every weighted error is zero. Error path only.
inline std::string largest_local_error(const FailureDiagnosis& system, N_Vector errors, N_Vector weights,
                                       N_Vector counted = nullptr) {
  VectorX weighted = map(errors).cwiseProduct(map(weights)).cwiseAbs();
  if (counted) weighted = weighted.cwiseProduct(map(counted));
  int worst = 0;
  if (weighted.size() == 0 || !(weighted.maxCoeff(&worst) > 0.0)) return "";
  return "; largest local error in the " + system.describe_component(worst);
}

/// Owns a SUNContext for one integrator instance.
class Context {
 public:
  Context() { SUNContext_Create(nullptr, &context_); }
  ~Context() { SUNContext_Free(&context_); }
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;
  operator SUNContext() const { return context_; }

 private:
  SUNContext context_ = nullptr;
};

/// Exceptions must not cross the C callbacks: a callback stores the exception here
/// and returns a failure code; the integrator rethrows after the SUNDIALS call.
struct CallbackError {
  std::exception_ptr exception;
  void rethrow_if_set() {
    if (exception) {
      std::exception_ptr e = exception;
      exception = nullptr;
      std::rethrow_exception(e);
    }
  }
};

/// Runs a SUNDIALS callback body so that exceptions never cross into C. A
/// NumericalError is recoverable (return 1: the integrator retries with a smaller
/// step, and the error is rethrown if it keeps failing); anything else is fatal (-1).
template <class Body>
int guarded(CallbackError& error, Body&& body) {
  try {
    body();
    return 0;
  } catch (const NumericalError&) {
    error.exception = std::current_exception();
    return 1;
  } catch (...) {
    error.exception = std::current_exception();
    return -1;
  }
}

}  // namespace heavesim::sundials
