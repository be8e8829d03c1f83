// An 18x18 SUNMatrix stored as four 9x9 blocks, the upper two diagonal:
//   A = [[diag(d11), diag(d12)], [M21, M22]].
// The walker's Jacobian J = [[0, I], [A_q, A_v]] has this form, and so has
// every Newton matrix CVODE makes of it, M = I - gamma*J (SUNMatScaleAddI).
// Given to CVODE with the analytic Jacobian and the Schur solver
// (integration/schur_linear_solver.h), it spares the 144 upper entries that are
// known zeros: CVODE's copies of its saved Jacobian and its scale-and-shift
// touch 180 numbers instead of 324, and the solver reads the blocks instead of
// checking the structure of a dense matrix (docs/performance.md).
//
// Each stored entry is computed with the arithmetic of SUNDIALS' dense matrix
// (c*a, then + 1 on the diagonal), so CVODE's results are bit-identical with
// this matrix or a dense one (tests/integration/block_matrix18_test.cc).
//
// Operations: getid (SUNMATRIX_CUSTOM), clone, destroy, zero, copy,
// scaleaddi, matvec and space; scaleadd (A = c*A + B) is left out, as CVODE's
// direct solvers never call it. Nothing allocates after MakeBlockMatrix18 and
// clone, and there is no shared mutable state: matrices on different threads
// are independent.
#pragma once

#include "dynamics/coords.h"

// SUNDIALS handle types, declared as in its headers (see schur_linear_solver.h)
struct _generic_SUNMatrix;
typedef struct _generic_SUNMatrix* SUNMatrix;
struct _SUNContext;
typedef struct _SUNContext* SUNContext;

namespace walkers {

struct Blocks18 {
  Vec9 d11 = Vec9::Zero();  // diagonal of the upper-left block
  Vec9 d12 = Vec9::Zero();  // diagonal of the upper-right block
  Mat9 m21 = Mat9::Zero();  // lower-left block
  Mat9 m22 = Mat9::Zero();  // lower-right block
};

// A new zero matrix; nullptr when out of memory. Free it with SUNMatDestroy.
SUNMatrix MakeBlockMatrix18(SUNContext context);

// The blocks of a matrix made by MakeBlockMatrix18 (or cloned from one);
// nullptr for any other matrix.
Blocks18* BlocksOf(SUNMatrix A);

// Writes the walker's Jacobian J = [[0, I], [da_dq, da_dv]] into A, a block
// matrix or a dense 18x18 SUNMatrix (column-major). False, writing nothing,
// for any other matrix.
bool StoreWalkerJacobian(const Mat9& da_dq, const Mat9& da_dv, SUNMatrix A);

}  // namespace walkers
