#include "integration/fixed_size_ops.h"

#include <nvector/nvector_serial.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <cmath>

namespace walkers {
namespace {

constexpr int kN = kFixedVectorLength;
constexpr int kMatrixSize = kN * kN;

inline double* Data(N_Vector v) { return NV_DATA_S(v); }

// ---- vector operations: each mirrors the serial N_Vector's formula ----

// y <- a*x + y
void Axpy(double a, N_Vector x, N_Vector y) {
  const double* xd = Data(x);
  double* yd = Data(y);
  if (a == 1.0) {
    for (int i = 0; i < kN; ++i) yd[i] += xd[i];
  } else if (a == -1.0) {
    for (int i = 0; i < kN; ++i) yd[i] -= xd[i];
  } else {
    for (int i = 0; i < kN; ++i) yd[i] += a * xd[i];
  }
}

// z = a*x + b*y, with the serial vector's special cases (they round differently)
void LinearSum(double a, N_Vector x, double b, N_Vector y, N_Vector z) {
  if (b == 1.0 && z == y) return Axpy(a, x, y);
  if (a == 1.0 && z == x) return Axpy(b, y, x);
  const double* xd = Data(x);
  const double* yd = Data(y);
  double* zd = Data(z);
  if (a == 1.0 && b == 1.0) {
    for (int i = 0; i < kN; ++i) zd[i] = xd[i] + yd[i];
  } else if (a == 1.0 && b == -1.0) {
    for (int i = 0; i < kN; ++i) zd[i] = xd[i] - yd[i];
  } else if (a == -1.0 && b == 1.0) {
    for (int i = 0; i < kN; ++i) zd[i] = yd[i] - xd[i];
  } else if (a == 1.0) {  // b*y + x
    for (int i = 0; i < kN; ++i) zd[i] = (b * yd[i]) + xd[i];
  } else if (b == 1.0) {  // a*x + y
    for (int i = 0; i < kN; ++i) zd[i] = (a * xd[i]) + yd[i];
  } else if (a == -1.0) {  // b*y - x
    for (int i = 0; i < kN; ++i) zd[i] = (b * yd[i]) - xd[i];
  } else if (b == -1.0) {  // a*x - y
    for (int i = 0; i < kN; ++i) zd[i] = (a * xd[i]) - yd[i];
  } else if (a == b) {
    for (int i = 0; i < kN; ++i) zd[i] = a * (xd[i] + yd[i]);
  } else if (a == -b) {
    for (int i = 0; i < kN; ++i) zd[i] = a * (xd[i] - yd[i]);
  } else {
    for (int i = 0; i < kN; ++i) zd[i] = (a * xd[i]) + (b * yd[i]);
  }
}

void Const(double c, N_Vector z) {
  double* zd = Data(z);
  for (int i = 0; i < kN; ++i) zd[i] = c;
}

void Prod(N_Vector x, N_Vector y, N_Vector z) {
  const double* xd = Data(x);
  const double* yd = Data(y);
  double* zd = Data(z);
  for (int i = 0; i < kN; ++i) zd[i] = xd[i] * yd[i];
}

void Div(N_Vector x, N_Vector y, N_Vector z) {
  const double* xd = Data(x);
  const double* yd = Data(y);
  double* zd = Data(z);
  for (int i = 0; i < kN; ++i) zd[i] = xd[i] / yd[i];
}

void Scale(double c, N_Vector x, N_Vector z) {
  const double* xd = Data(x);
  double* zd = Data(z);
  if (z == x) {
    for (int i = 0; i < kN; ++i) zd[i] *= c;
  } else if (c == 1.0) {
    for (int i = 0; i < kN; ++i) zd[i] = xd[i];
  } else if (c == -1.0) {
    for (int i = 0; i < kN; ++i) zd[i] = -xd[i];
  } else {
    for (int i = 0; i < kN; ++i) zd[i] = c * xd[i];
  }
}

void Abs(N_Vector x, N_Vector z) {
  const double* xd = Data(x);
  double* zd = Data(z);
  for (int i = 0; i < kN; ++i) zd[i] = std::fabs(xd[i]);
}

void Inv(N_Vector x, N_Vector z) {
  const double* xd = Data(x);
  double* zd = Data(z);
  for (int i = 0; i < kN; ++i) zd[i] = 1.0 / xd[i];
}

void AddConst(N_Vector x, double b, N_Vector z) {
  const double* xd = Data(x);
  double* zd = Data(z);
  for (int i = 0; i < kN; ++i) zd[i] = xd[i] + b;
}

double DotProd(N_Vector x, N_Vector y) {
  const double* xd = Data(x);
  const double* yd = Data(y);
  double sum = 0.0;
  for (int i = 0; i < kN; ++i) sum += xd[i] * yd[i];
  return sum;
}

double MaxNorm(N_Vector x) {
  const double* xd = Data(x);
  double max = 0.0;
  for (int i = 0; i < kN; ++i) {
    if (std::fabs(xd[i]) > max) max = std::fabs(xd[i]);
  }
  return max;
}

// sum of (x_i w_i)^2, in index order
double WSqrSum(N_Vector x, N_Vector w) {
  const double* xd = Data(x);
  const double* wd = Data(w);
  double sum = 0.0;
  for (int i = 0; i < kN; ++i) {
    const double p = xd[i] * wd[i];
    sum += p * p;
  }
  return sum;
}

double WrmsNorm(N_Vector x, N_Vector w) {
  const double mean = WSqrSum(x, w) / kN;
  return mean <= 0.0 ? 0.0 : std::sqrt(mean);
}

double Min(N_Vector x) {
  const double* xd = Data(x);
  double min = xd[0];
  for (int i = 1; i < kN; ++i) {
    if (xd[i] < min) min = xd[i];
  }
  return min;
}

void Compare(double c, N_Vector x, N_Vector z) {
  const double* xd = Data(x);
  double* zd = Data(z);
  for (int i = 0; i < kN; ++i) zd[i] = std::fabs(xd[i]) >= c ? 1.0 : 0.0;
}

// ---- fused operations: SUNDIALS' own fallbacks, without the dispatch ----
// The serial vector's fused operations are disabled, so N_VScaleAddMulti and
// its kind loop over the ops above through function pointers. These run the
// same loops over the same operations, in the same order.

// Z[i] = a[i]*x + Y[i], i = 0..nvec-1 in turn (CVODE's Nordsieck correction)
int ScaleAddMulti(int nvec, double* a, N_Vector x, N_Vector* Y, N_Vector* Z) {
  for (int i = 0; i < nvec; ++i) LinearSum(a[i], x, 1.0, Y[i], Z[i]);
  return 0;
}

// Z[i] = c[i]*X[i], i = 0..nvec-1 in turn (CVODE's rescaling of the history)
int ScaleVectorArray(int nvec, double* c, N_Vector* X, N_Vector* Z) {
  for (int i = 0; i < nvec; ++i) Scale(c[i], X[i], Z[i]);
  return 0;
}

// z = c[0]*X[0], then z = c[i]*X[i] + z for i = 1..nvec-1
int LinearCombination(int nvec, double* c, N_Vector* X, N_Vector z) {
  Scale(c[0], X[0], z);
  for (int i = 1; i < nvec; ++i) LinearSum(c[i], X[i], 1.0, z, z);
  return 0;
}

// ---- dense matrix operations ----

inline double* Data(SUNMatrix A) { return SM_DATA_D(A); }

int MatrixZero(SUNMatrix A) {
  double* a = Data(A);
  for (int k = 0; k < kMatrixSize; ++k) a[k] = 0.0;
  return SUNMAT_SUCCESS;
}

// B = A
int MatrixCopy(SUNMatrix A, SUNMatrix B) {
  if (!IsDense18(B)) return SUNMAT_ILL_INPUT;
  const double* a = Data(A);
  double* b = Data(B);
  for (int k = 0; k < kMatrixSize; ++k) b[k] = a[k];
  return SUNMAT_SUCCESS;
}

// A = c*A + I
int MatrixScaleAddI(double c, SUNMatrix A) {
  double* a = Data(A);
  for (int k = 0; k < kMatrixSize; ++k) a[k] *= c;
  for (int j = 0; j < kN; ++j) a[j * kN + j] += 1.0;
  return SUNMAT_SUCCESS;
}

SUNMatrix MatrixClone(SUNMatrix A) {
  SUNMatrix B = SUNMatClone_Dense(A);
  if (B) UseFixedSizeMatrixOps(B);
  return B;
}

}  // namespace

bool IsSerial18(N_Vector v) {
  // the serial vector's own getvectorid, compared rather than called: the
  // Schur solver asks this of two vectors at every solve
  return v && v->ops && v->ops->nvgetvectorid == N_VGetVectorID_Serial && v->content && NV_LENGTH_S(v) == kN;
}

bool IsDense18(SUNMatrix A) {
  return A && A->ops && A->ops->getid && A->content && SUNMatGetID(A) == SUNMATRIX_DENSE && SM_ROWS_D(A) == kN &&
         SM_COLUMNS_D(A) == kN && SM_LDATA_D(A) == kMatrixSize && SM_DATA_D(A);
}

bool UseFixedSizeVectorOps(N_Vector v) {
  if (!IsSerial18(v)) return false;
  N_Vector_Ops ops = v->ops;
  ops->nvlinearsum = LinearSum;
  ops->nvconst = Const;
  ops->nvprod = Prod;
  ops->nvdiv = Div;
  ops->nvscale = Scale;
  ops->nvabs = Abs;
  ops->nvinv = Inv;
  ops->nvaddconst = AddConst;
  ops->nvdotprod = DotProd;
  ops->nvdotprodlocal = DotProd;
  ops->nvmaxnorm = MaxNorm;
  ops->nvmaxnormlocal = MaxNorm;
  ops->nvwrmsnorm = WrmsNorm;
  ops->nvwsqrsumlocal = WSqrSum;
  ops->nvmin = Min;
  ops->nvminlocal = Min;
  ops->nvcompare = Compare;
  ops->nvscaleaddmulti = ScaleAddMulti;
  ops->nvscalevectorarray = ScaleVectorArray;
  ops->nvlinearcombination = LinearCombination;
  return true;
}

bool UseFixedSizeMatrixOps(SUNMatrix A) {
  if (!IsDense18(A)) return false;
  A->ops->zero = MatrixZero;
  A->ops->copy = MatrixCopy;
  A->ops->scaleaddi = MatrixScaleAddI;
  A->ops->clone = MatrixClone;
  return true;
}

}  // namespace walkers
