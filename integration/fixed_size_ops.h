// CVODE's vector and matrix operations for the walker's fixed sizes.
//
// CVODE does its per-step bookkeeping (the Nordsieck predictor, the Newton
// updates, error norms, the Newton matrix I - gamma*J) through the function
// pointers of its N_Vector and SUNMatrix objects. SUNDIALS' serial vector and
// dense matrix loop over a length known only at run time, behind a chain of
// calls; for our 18-element state and 18x18 matrix that bookkeeping was a
// third of an evaluation (docs/performance.md). The functions below replace
// those pointers with loops of compile-time length.
//
// They compute exactly what SUNDIALS 6.4's serial vector and dense matrix
// compute, operation for operation and in the same order (including
// N_VLinearSum's special cases such as c*(x + y) for a == b), so results are
// bit-identical with or without them; tests/integration/fixed_size_ops_test.cc
// checks every replaced operation against the library's on random data.
// The serial vector's fused operations stay disabled: the three CVODE uses
// (N_VScaleAddMulti, N_VScaleVectorArray, N_VLinearCombination) run
// SUNDIALS' own fallback loops over the operations above, only without its
// dispatch. Operations not replaced (masks, constraints, the other fused and
// array operations) keep the library's implementation. Clones inherit the
// replaced operations, so CVODE's internal vectors and its saved Jacobian get
// them too.
#pragma once

// SUNDIALS handle types, declared as in its headers (see schur_linear_solver.h)
struct _generic_N_Vector;
typedef struct _generic_N_Vector* N_Vector;
struct _generic_SUNMatrix;
typedef struct _generic_SUNMatrix* SUNMatrix;

namespace walkers {

constexpr int kFixedVectorLength = 18;  // the state y = (q, v)

// A serial N_Vector of length 18.
bool IsSerial18(N_Vector v);

// A dense 18x18 SUNMatrix with its 324 entries in one column-major array.
bool IsDense18(SUNMatrix A);

// Replaces the operations of a serial N_Vector of length 18. Returns false,
// changing nothing, for any other vector.
bool UseFixedSizeVectorOps(N_Vector v);

// Replaces copy, zero, scale-add-identity and clone of a dense 18x18
// SUNMatrix. Returns false, changing nothing, for any other matrix.
bool UseFixedSizeMatrixOps(SUNMatrix A);

}  // namespace walkers
