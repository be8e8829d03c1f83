// A SUNDIALS linear solver for CVODE's Newton systems that uses the block
// structure of the walker's ODE. With y = (q, v) and y' = (v, a(q, v)) the
// Jacobian is J = [[0, I], [A_q, A_v]] (9x9 blocks), so CVODE's Newton matrix
//   M = I - gamma*J = [[I, -gamma*I], [-gamma*A_q, I - gamma*A_v]]
// is solved by factoring only the 9x9 Schur complement
//   S = M22 - M21*M11^{-1}*M12 = M22 + gamma*M21
// instead of the whole 18x18 matrix. It takes either of two matrices:
// - the block matrix of integration/block_matrix18.h, which stores the upper
//   blocks as diagonals and so has the structure by construction (CVODE then
//   needs the analytic Jacobian: its difference quotients fill dense or band
//   matrices only);
// - the standard dense SUNMatrix that CVODE fills itself (its own or the
//   user's Jacobian, then SUNMatScaleAddI); gamma is read off M12, and the
//   solver is then a drop-in replacement for SUNLinSol_Dense:
//   SUNMatrix A = SUNDenseMatrix(18, 18, ctx);
//   SUNLinearSolver LS = walkers::MakeSchurLinearSolver(y, A, ctx);
//   CVodeSetLinearSolver(cvode_mem, LS, A);
//   ...
//   SUNLinSolFree(LS);  // after CVodeFree, like any SUNLinearSolver
// Both give bit-identical solutions for the same M.
//
// The solver is exact for any M whose M11 and M12 blocks are diagonal (it uses
// their actual diagonals, not 1 and -gamma), so the difference-quotient noise
// CVODE's own Jacobian leaves on the diagonal of J's upper-right identity block
// (relative ~1e-8) costs no accuracy. Setup rejects a dense matrix without the
// structure with SUNLS_PACKAGE_FAIL_UNREC (an unrecoverable CVODE setup
// failure: a smaller step cannot bring the structure back) and reports an
// exactly singular S like SUNLinSol_Dense, with the recoverable
// SUNLS_LUFACT_FAIL and the 1-based column (10..18) of the zero pivot as the
// last flag. Setup and solve allocate nothing; the solver keeps no global or
// static mutable state, so solvers on different threads are independent (one
// solver is used by one thread at a time, like every SUNDIALS object).
#pragma once

// The SUNDIALS handle types, declared exactly as the SUNDIALS 6.4 headers
// declare them (sundials_linearsolver.h, sundials_nvector.h,
// sundials_matrix.h, sundials_context.h), so that users of this header do not
// pull in the SUNDIALS C headers. An identical typedef may be repeated in C++,
// so the SUNDIALS headers can be included before or after this one; the .cc
// includes them after it, so a mismatch would not compile.
struct _generic_SUNLinearSolver;
typedef struct _generic_SUNLinearSolver* SUNLinearSolver;
struct _generic_N_Vector;
typedef struct _generic_N_Vector* N_Vector;
struct _generic_SUNMatrix;
typedef struct _generic_SUNMatrix* SUNMatrix;
struct _SUNContext;
typedef struct _SUNContext* SUNContext;

namespace walkers {

// Creates the solver (SUNLINEARSOLVER_DIRECT, SUNLINEARSOLVER_CUSTOM) for
// 18x18 systems: y_template must be a serial N_Vector of length 18 and A a
// dense 18x18 SUNMatrix or a block matrix (MakeBlockMatrix18), the one later
// passed to CVodeSetLinearSolver.
// Returns nullptr on bad input or when out of memory. Free the result with
// SUNLinSolFree.
SUNLinearSolver MakeSchurLinearSolver(N_Vector y_template, SUNMatrix A, SUNContext context);

}  // namespace walkers
