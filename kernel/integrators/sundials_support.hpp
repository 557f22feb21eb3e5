#pragma once
// Glue between Eigen vectors and SUNDIALS serial N_Vectors, and an owning context.
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>

#include <exception>

#include "kernel/spatial/types.hpp"

namespace heavesim::sundials {

inline Eigen::Map<VectorX> map(N_Vector v) {
  return Eigen::Map<VectorX>(N_VGetArrayPointer(v), N_VGetLength(v));
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

}  // namespace heavesim::sundials
