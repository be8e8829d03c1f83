// Owning handles for SUNDIALS objects in tests that drive SUNDIALS directly.
#pragma once

#include <memory>
#include <type_traits>

#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sundials/sundials_linearsolver.h>
#include <sunmatrix/sunmatrix_dense.h>

namespace walkers {

struct ContextFree {
  void operator()(SUNContext c) const { SUNContext_Free(&c); }
};
struct MatrixFree {
  void operator()(SUNMatrix m) const { SUNMatDestroy(m); }
};
struct VectorFree {
  void operator()(N_Vector v) const { N_VDestroy(v); }
};
struct SolverFree {
  void operator()(SUNLinearSolver s) const { SUNLinSolFree(s); }
};
using ContextPtr = std::unique_ptr<std::remove_pointer_t<SUNContext>, ContextFree>;
using MatrixPtr = std::unique_ptr<std::remove_pointer_t<SUNMatrix>, MatrixFree>;
using VectorPtr = std::unique_ptr<std::remove_pointer_t<N_Vector>, VectorFree>;
using SolverPtr = std::unique_ptr<std::remove_pointer_t<SUNLinearSolver>, SolverFree>;

inline ContextPtr NewContext() {
  SUNContext c = nullptr;
  if (SUNContext_Create(nullptr, &c) != 0) return nullptr;
  return ContextPtr(c);
}

}  // namespace walkers
