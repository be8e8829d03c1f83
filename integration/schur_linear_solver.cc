#include "integration/schur_linear_solver.h"

#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sundials/sundials_linearsolver.h>
#include <sundials/sundials_matrix.h>
#include <sundials/sundials_nvector.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <Eigen/Core>

#include <cmath>
#include <new>
#include <type_traits>

#include "integration/block_matrix18.h"
#include "dynamics/coords.h"
#include "integration/fixed_size_ops.h"
#include "integration/lu_solve9.h"

namespace walkers {
namespace {

static_assert(std::is_same<sunrealtype, double>::value, "the solver maps SUNDIALS data as double");

constexpr int kBlock = kNumCoords;      // q and v each
constexpr int kSize = 2 * kNumCoords;  // y = (q, v)
static_assert(kSize == kFixedVectorLength);

using Mat9 = Eigen::Matrix<double, kBlock, kBlock>;
using Vec9 = Eigen::Matrix<double, kBlock, 1>;

// How far M11 and M12 may be from I and -gamma*I. The algebra uses their
// actual diagonals, so these only decide whether the structure is present.
// CVODE's difference-quotient Jacobian puts relative errors up to a few 1e-8
// on the unit diagonal of J's upper-right block ((v_j + inc) - v_j with
// inc ~ sqrt(eps)*|v_j|, then scaled by 1/inc) but exact zeros elsewhere in
// J's upper half, hence a loose diagonal and a tight off-diagonal tolerance.
constexpr double kDiagonalTolerance = 1e-6;      // relative to 1 and to gamma
constexpr double kOffDiagonalTolerance = 1e-12;  // relative to 1 and to gamma

// Everything the solver keeps between setup and solve: fixed-size Eigen types
// only, so setup and solve never allocate.
struct Content {
  Lu9 schur_lu;                        // P*S = L*U, S = M22 - M21*M11^{-1}*M12
  Mat9 m21;                            // lower-left block of M
  Vec9 inverse_d11;                    // 1 / diag(M11)
  Vec9 ratio;                          // diag(M12) / diag(M11)
  bool factored = false;               // the fields above belong to the last setup
  sunindextype last_flag = SUNLS_SUCCESS;
};

Content* ContentOf(SUNLinearSolver S) { return S ? static_cast<Content*>(S->content) : nullptr; }

// the data of a serial vector of length 18 (the kind the solver was made
// for, MakeSchurLinearSolver), else nullptr
double* Data18(N_Vector v) { return IsSerial18(v) ? NV_DATA_S(v) : nullptr; }

SUNLinearSolver_Type GetType(SUNLinearSolver /*S*/) { return SUNLINEARSOLVER_DIRECT; }

SUNLinearSolver_ID GetId(SUNLinearSolver /*S*/) { return SUNLINEARSOLVER_CUSTOM; }

int Initialize(SUNLinearSolver S) {
  Content* c = ContentOf(S);
  if (!c) return SUNLS_MEM_NULL;
  c->factored = false;
  c->last_flag = SUNLS_SUCCESS;
  return SUNLS_SUCCESS;
}

// Reads the blocks of a dense M, checking that M11 = I and M12 = -gamma*I up
// to the tolerances (false if not). The diagonals are returned as they are:
// the algebra uses them, not 1 and -gamma.
bool ReadDenseBlocks(SUNMatrix A, Vec9* d11, Vec9* d12, Mat9* m21, Mat9* m22) {
  // gamma from M12 = -gamma*I: minus the mean of its diagonal (column-major,
  // M12(i, i) = M(i, 9 + i))
  double gamma = 0.0;
  for (int i = 0; i < kBlock; ++i) gamma -= SUNDenseMatrix_Column(A, kBlock + i)[i];
  gamma /= kBlock;
  if (!std::isfinite(gamma)) return false;

  // column by column; written as !(error <= bound) so that NaN fails too
  const double abs_gamma = std::fabs(gamma);
  for (int j = 0; j < kBlock; ++j) {
    const double* left = SUNDenseMatrix_Column(A, j);            // column j of [M11; M21]
    const double* right = SUNDenseMatrix_Column(A, kBlock + j);  // column j of [M12; M22]
    for (int i = 0; i < kBlock; ++i) {
      const bool diagonal = i == j;
      const double m11_error = diagonal ? left[i] - 1.0 : left[i];
      const double m12_error = diagonal ? right[i] + gamma : right[i];
      const double tolerance = diagonal ? kDiagonalTolerance : kOffDiagonalTolerance;
      if (!(std::fabs(m11_error) <= tolerance) || !(std::fabs(m12_error) <= tolerance * abs_gamma)) return false;
    }
    (*d11)(j) = left[j];
    (*d12)(j) = right[j];
    m21->col(j) = Eigen::Map<const Vec9>(left + kBlock);
    m22->col(j) = Eigen::Map<const Vec9>(right + kBlock);
  }
  return true;
}

// Factors the Schur complement of M = [[diag(d11), diag(d12)], [m21, m22]]
// into c, which keeps what the solves need.
int FactorSchurComplement(const Vec9& d11, const Vec9& d12, const Mat9& m21, const Mat9& m22, Content* c) {
  // with D11 = diag(M11), D12 = diag(M12) the first block row
  //   D11 x1 + D12 x2 = b1  gives  x1 = D11^{-1} (b1 - D12 x2)
  // and substituting it into the second, M21 x1 + M22 x2 = b2, gives
  //   (M22 - M21 D11^{-1} D12) x2 = b2 - M21 D11^{-1} b1,
  // i.e. S = M22 - M21 diag(d12 / d11) = M22 + gamma*M21 for D11 = I, D12 = -gamma*I
  c->inverse_d11 = d11.cwiseInverse();
  c->ratio = d12.cwiseProduct(c->inverse_d11);
  // S goes straight where it is factored, and M21 is kept for the solves, in
  // one unrolled pass (Eigen would loop over each 9x9 behind a call)
  Mat9& schur = c->schur_lu.lu;
  #pragma GCC unroll 9
  for (int j = 0; j < kBlock; ++j) {
    c->m21.col(j) = m21.col(j);
    schur.col(j) = m22.col(j) - m21.col(j) * c->ratio(j);
  }

  // a non-finite Jacobian (e.g. an overflowing right-hand side) may go away
  // with a smaller step: recoverable
  if (!schur.allFinite()) return static_cast<int>(c->last_flag = SUNLS_PACKAGE_FAIL_REC);

  // factor S with row pivoting; like SUNLinSol_Dense, report the 1-based
  // column of the first zero pivot, here a column of the full matrix
  // (x2 = v part, 10..18), with the recoverable SUNLS_LUFACT_FAIL
  FactorLu9(&c->schur_lu);
  if (c->schur_lu.first_zero_pivot >= 0) {
    c->last_flag = kBlock + c->schur_lu.first_zero_pivot + 1;
    return SUNLS_LUFACT_FAIL;
  }
  if (!c->schur_lu.lu.allFinite()) return static_cast<int>(c->last_flag = SUNLS_PACKAGE_FAIL_REC);

  c->factored = true;
  c->last_flag = SUNLS_SUCCESS;
  return SUNLS_SUCCESS;
}

int Setup(SUNLinearSolver S, SUNMatrix A) {
  Content* c = ContentOf(S);
  if (!c) return SUNLS_MEM_NULL;
  c->factored = false;
  if (!A) return static_cast<int>(c->last_flag = SUNLS_MEM_NULL);

  // a block matrix has the structure by construction
  if (const Blocks18* blocks = BlocksOf(A)) {
    return FactorSchurComplement(blocks->d11, blocks->d12, blocks->m21, blocks->m22, c);
  }
  if (!IsDense18(A)) return static_cast<int>(c->last_flag = SUNLS_ILL_INPUT);
  Vec9 d11, d12;
  Mat9 m21, m22;
  if (!ReadDenseBlocks(A, &d11, &d12, &m21, &m22)) return static_cast<int>(c->last_flag = SUNLS_PACKAGE_FAIL_UNREC);
  return FactorSchurComplement(d11, d12, m21, m22, c);
}

// The matrix argument is not read: the factorization and the blocks needed
// come from the last setup, as with SUNLinSol_Dense (which solves with the LU
// factors it left in A). x and b may be the same vector.
int Solve(SUNLinearSolver S, SUNMatrix /*A*/, N_Vector x, N_Vector b, sunrealtype /*tol*/) {
  Content* c = ContentOf(S);
  if (!c) return SUNLS_MEM_NULL;
  if (!x || !b) return static_cast<int>(c->last_flag = SUNLS_MEM_NULL);
  double* x_data = Data18(x);
  const double* b_data = Data18(b);
  if (!x_data || !b_data) return static_cast<int>(c->last_flag = SUNLS_ILL_INPUT);
  // no factorization to solve with: setup never ran or failed
  if (!c->factored) return static_cast<int>(c->last_flag = SUNLS_ILL_INPUT);

  // read b completely before writing x, in case they alias
  const Vec9 b1 = Eigen::Map<const Vec9>(b_data);
  const Vec9 b2 = Eigen::Map<const Vec9>(b_data + kBlock);

  // w = D11^{-1} b1; second block row: S x2 = b2 - M21 w
  const Vec9 w = c->inverse_d11.cwiseProduct(b1);
  Vec9 rhs = b2;
  SubtractProduct(c->m21, w, &rhs);
  const Vec9 x2 = SolveLu9(c->schur_lu, rhs);

  // back substitution into the first block row: x1 = D11^{-1} (b1 - D12 x2)
  // = w - (d12 / d11) x2, which is b1 + gamma*x2 for D11 = I, D12 = -gamma*I
  Eigen::Map<Vec9> x1_out(x_data), x2_out(x_data + kBlock);
  x1_out = w - c->ratio.cwiseProduct(x2);
  x2_out = x2;

  c->last_flag = SUNLS_SUCCESS;
  return SUNLS_SUCCESS;
}

sunindextype LastFlag(SUNLinearSolver S) {
  const Content* c = ContentOf(S);
  return c ? c->last_flag : SUNLS_MEM_NULL;
}

// workspace in realtype and integer words: the LU factors, M21 and two
// diagonals; the row permutation (twice: transpositions and permutation)
int Space(SUNLinearSolver S, long int* lenrw, long int* leniw) {
  if (!ContentOf(S) || !lenrw || !leniw) return SUNLS_MEM_NULL;
  *lenrw = 2 * kBlock * kBlock + 2 * kBlock;
  *leniw = 2 * kBlock + 2;
  return SUNLS_SUCCESS;
}

int Free(SUNLinearSolver S) {
  if (!S) return SUNLS_SUCCESS;
  delete ContentOf(S);
  S->content = nullptr;
  SUNLinSolFreeEmpty(S);  // the ops table and the object itself
  return SUNLS_SUCCESS;
}

}  // namespace

SUNLinearSolver MakeSchurLinearSolver(N_Vector y_template, SUNMatrix A, SUNContext context) {
  if (!context || !(IsDense18(A) || BlocksOf(A)) || !IsSerial18(y_template)) return nullptr;

  SUNLinearSolver S = SUNLinSolNewEmpty(context);
  if (!S) return nullptr;
  S->ops->gettype = GetType;
  S->ops->getid = GetId;
  S->ops->initialize = Initialize;
  S->ops->setup = Setup;
  S->ops->solve = Solve;
  S->ops->lastflag = LastFlag;
  S->ops->space = Space;
  S->ops->free = Free;

  S->content = new (std::nothrow) Content();
  if (!S->content) {
    SUNLinSolFreeEmpty(S);
    return nullptr;
  }
  return S;
}

}  // namespace walkers
