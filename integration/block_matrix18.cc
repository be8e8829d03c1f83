#include "integration/block_matrix18.h"

#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sundials/sundials_matrix.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <new>

#include "integration/fixed_size_ops.h"

namespace walkers {
namespace {

constexpr int kBlock = kNumCoords;
static_assert(2 * kBlock == kFixedVectorLength);

SUNMatrix_ID GetId(SUNMatrix /*A*/) { return SUNMATRIX_CUSTOM; }

// the content of a matrix known to be ours (BlocksOf checks)
Blocks18& Content(SUNMatrix A) { return *static_cast<Blocks18*>(A->content); }

void Destroy(SUNMatrix A) {
  if (!A) return;
  delete static_cast<Blocks18*>(A->content);
  A->content = nullptr;
  SUNMatFreeEmpty(A);  // the ops table and the object itself
}

SUNMatrix Clone(SUNMatrix A) { return A ? MakeBlockMatrix18(A->sunctx) : nullptr; }

int Zero(SUNMatrix A) {
  Blocks18* a = BlocksOf(A);
  if (!a) return SUNMAT_ILL_INPUT;
  *a = Blocks18{};
  return SUNMAT_SUCCESS;
}

// B = A
int Copy(SUNMatrix A, SUNMatrix B) {
  const Blocks18* a = BlocksOf(A);
  Blocks18* b = BlocksOf(B);
  if (!a || !b) return SUNMAT_ILL_INPUT;
  b->d11 = a->d11;
  b->d12 = a->d12;
  // column by column: Eigen unrolls nine-element columns, but a whole 9x9 is
  // a loop behind a call (here and in ScaleAddI)
  #pragma GCC unroll 9
  for (int j = 0; j < kBlock; ++j) {
    b->m21.col(j) = a->m21.col(j);
    b->m22.col(j) = a->m22.col(j);
  }
  return SUNMAT_SUCCESS;
}

// A = c*A + I, entry by entry as SUNDIALS' dense matrix computes it: every
// entry times c, then 1 added to the diagonal (d11 and M22's). The upper
// blocks' off-diagonal zeros, not stored, stay zeros.
int ScaleAddI(sunrealtype c, SUNMatrix A) {
  Blocks18* a = BlocksOf(A);
  if (!a) return SUNMAT_ILL_INPUT;
  a->d11 *= c;
  a->d12 *= c;
  #pragma GCC unroll 9
  for (int j = 0; j < kBlock; ++j) {
    a->m21.col(j) *= c;
    a->m22.col(j) *= c;
  }
  a->d11.array() += 1.0;
  a->m22.diagonal().array() += 1.0;
  return SUNMAT_SUCCESS;
}

// y = A x for serial vectors of length 18 (x and y distinct)
int Matvec(SUNMatrix A, N_Vector x, N_Vector y) {
  const Blocks18* a = BlocksOf(A);
  if (!a || !IsSerial18(x) || !IsSerial18(y) || x == y) return SUNMAT_ILL_INPUT;
  const Eigen::Map<const Vec9> x1(NV_DATA_S(x)), x2(NV_DATA_S(x) + kBlock);
  Eigen::Map<Vec9> y1(NV_DATA_S(y)), y2(NV_DATA_S(y) + kBlock);
  y1 = a->d11.cwiseProduct(x1) + a->d12.cwiseProduct(x2);
  y2.noalias() = a->m21 * x1;
  y2.noalias() += a->m22 * x2;
  return SUNMAT_SUCCESS;
}

// storage in realtype and integer words: two diagonals and two 9x9 blocks
int Space(SUNMatrix A, long int* lenrw, long int* leniw) {
  if (!BlocksOf(A) || !lenrw || !leniw) return SUNMAT_ILL_INPUT;
  *lenrw = 2 * kBlock + 2 * kBlock * kBlock;
  *leniw = 0;
  return SUNMAT_SUCCESS;
}

}  // namespace

SUNMatrix MakeBlockMatrix18(SUNContext context) {
  if (!context) return nullptr;
  SUNMatrix A = SUNMatNewEmpty(context);
  if (!A) return nullptr;
  A->ops->getid = GetId;
  A->ops->clone = Clone;
  A->ops->destroy = Destroy;
  A->ops->zero = Zero;
  A->ops->copy = Copy;
  A->ops->scaleaddi = ScaleAddI;
  A->ops->matvec = Matvec;
  A->ops->space = Space;
  A->content = new (std::nothrow) Blocks18();
  if (!A->content) {
    SUNMatFreeEmpty(A);
    return nullptr;
  }
  return A;
}

Blocks18* BlocksOf(SUNMatrix A) {
  // our own getid marks the matrix as ours: SUNMATRIX_CUSTOM alone would not
  if (!A || !A->ops || A->ops->getid != GetId || !A->content) return nullptr;
  return &Content(A);
}

bool StoreWalkerJacobian(const Mat9& da_dq, const Mat9& da_dv, SUNMatrix A) {
  if (Blocks18* blocks = BlocksOf(A)) {
    blocks->d11.setZero();
    blocks->d12.setOnes();
    blocks->m21 = da_dq;
    blocks->m22 = da_dv;
    return true;
  }
  if (!IsDense18(A)) return false;
  Eigen::Map<Eigen::Matrix<double, 2 * kBlock, 2 * kBlock>> J(SUNDenseMatrix_Data(A));
  J.setZero();
  J.topRightCorner<kBlock, kBlock>().setIdentity();
  J.bottomLeftCorner<kBlock, kBlock>() = da_dq;
  J.bottomRightCorner<kBlock, kBlock>() = da_dv;
  return true;
}

}  // namespace walkers
