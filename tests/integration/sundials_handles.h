// Owning handles for SUNDIALS objects in tests that drive SUNDIALS directly,
// and Eigen views of the walker's 18-element state vectors and 18x18 dense
// matrices.
#pragma once

#include <memory>
#include <type_traits>

#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sundials/sundials_linearsolver.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <Eigen/Core>

#include "integration/fixed_size_ops.h"

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

// the state y = (q, v) and CVODE's 18x18 matrices, in blocks of 9
constexpr int kN = kFixedVectorLength;
constexpr int kHalf = kN / 2;
using Mat18 = Eigen::Matrix<double, kN, kN>;
using Vec18 = Eigen::Matrix<double, kN, 1>;

// a dense 18x18 SUNMatrix's entries (column-major, as Eigen's)
inline void Store(const Mat18& m, SUNMatrix a) { Eigen::Map<Mat18>(SUNDenseMatrix_Data(a)) = m; }
inline Mat18 Load(SUNMatrix a) { return Eigen::Map<const Mat18>(SUNDenseMatrix_Data(a)); }

// a serial N_Vector of length 18
inline void Store(const Vec18& v, N_Vector n) { Eigen::Map<Vec18>(N_VGetArrayPointer(n)) = v; }
inline Vec18 Load(N_Vector n) { return Eigen::Map<const Vec18>(N_VGetArrayPointer(n)); }

}  // namespace walkers
