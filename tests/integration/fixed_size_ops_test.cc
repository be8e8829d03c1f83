#include "integration/fixed_size_ops.h"

#include <cstring>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tests/integration/sundials_handles.h"

namespace walkers {
namespace {

// The same operation on SUNDIALS' serial vectors and on vectors with the
// fixed-size operations, from identical data; results must match bit for bit.
class FixedSizeVectorOpsTest : public ::testing::Test {
 protected:
  static constexpr int kVectors = 3;

  void SetUp() override {
    ASSERT_NE(context_, nullptr);
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> unit(-2.0, 2.0);
    for (int k = 0; k < kVectors; ++k) {
      library_.emplace_back(N_VNew_Serial(kN, context_.get()));
      fixed_.emplace_back(N_VNew_Serial(kN, context_.get()));
      ASSERT_TRUE(UseFixedSizeVectorOps(fixed_.back().get()));
      for (int i = 0; i < kN; ++i) {
        // awkward values on purpose: small, large, exact zeros
        const double value = i % 7 == 3 ? 0.0 : unit(rng) * (i % 2 ? 1e-7 : 1e3);
        N_VGetArrayPointer(library_[k].get())[i] = value;
        N_VGetArrayPointer(fixed_[k].get())[i] = value;
      }
    }
  }

  N_Vector Library(int k) { return library_[k].get(); }
  N_Vector Fixed(int k) { return fixed_[k].get(); }

  void ExpectSameVectors(const std::string& what) {
    for (int k = 0; k < kVectors; ++k) {
      EXPECT_EQ(std::memcmp(N_VGetArrayPointer(Library(k)), N_VGetArrayPointer(Fixed(k)), kN * sizeof(double)), 0)
          << what << ": vector " << k << " differs";
    }
  }

  static void ExpectSameBits(double library, double fixed, const std::string& what) {
    EXPECT_EQ(std::memcmp(&library, &fixed, sizeof(double)), 0) << what << ": " << library << " vs " << fixed;
  }

  ContextPtr context_ = NewContext();
  std::vector<VectorPtr> library_, fixed_;
};

TEST_F(FixedSizeVectorOpsTest, LinearSumMatchesEveryCaseOfTheSerialVector) {
  // N_VLinearSum_Serial rounds differently in its special cases (a*(x + y)
  // for a == b, axpy in place, ...): all of them, out of place and in place
  const double other = 0.37, another = -1.9;
  const std::vector<std::pair<double, double>> coefficients = {
      {1.0, 1.0},   {1.0, -1.0},    {-1.0, 1.0},  {1.0, other}, {other, 1.0},   {-1.0, other},
      {other, -1.0}, {other, other}, {other, -other}, {other, another}, {-1.0, -1.0}, {0.0, other}};
  for (const auto& [a, b] : coefficients) {
    for (int out = 0; out < 3; ++out) {  // z is a third vector, x, or y
      const int z = out == 0 ? 2 : out == 1 ? 0 : 1;
      N_VLinearSum(a, Library(0), b, Library(1), Library(z));
      N_VLinearSum(a, Fixed(0), b, Fixed(1), Fixed(z));
      ExpectSameVectors("LinearSum(" + std::to_string(a) + ", " + std::to_string(b) + ") into " +
                        std::to_string(z));
    }
  }
}

TEST_F(FixedSizeVectorOpsTest, ElementwiseOperationsMatch) {
  for (double c : {1.0, -1.0, 0.25, -3.5}) {
    N_VScale(c, Library(0), Library(2));
    N_VScale(c, Fixed(0), Fixed(2));
    ExpectSameVectors("Scale out of place by " + std::to_string(c));
    N_VScale(c, Library(1), Library(1));
    N_VScale(c, Fixed(1), Fixed(1));
    ExpectSameVectors("Scale in place by " + std::to_string(c));
  }
  N_VProd(Library(0), Library(1), Library(2));
  N_VProd(Fixed(0), Fixed(1), Fixed(2));
  ExpectSameVectors("Prod");
  N_VDiv(Library(0), Library(1), Library(2));
  N_VDiv(Fixed(0), Fixed(1), Fixed(2));
  ExpectSameVectors("Div");
  N_VAbs(Library(0), Library(2));
  N_VAbs(Fixed(0), Fixed(2));
  ExpectSameVectors("Abs");
  N_VInv(Library(2), Library(2));
  N_VInv(Fixed(2), Fixed(2));
  ExpectSameVectors("Inv");
  N_VAddConst(Library(0), 0.125, Library(2));
  N_VAddConst(Fixed(0), 0.125, Fixed(2));
  ExpectSameVectors("AddConst");
  N_VCompare(1e-3, Library(0), Library(2));
  N_VCompare(1e-3, Fixed(0), Fixed(2));
  ExpectSameVectors("Compare");
  N_VConst(-0.5, Library(2));
  N_VConst(-0.5, Fixed(2));
  ExpectSameVectors("Const");
}

TEST_F(FixedSizeVectorOpsTest, FusedOperationsMatchTheLibrarysFallbacks) {
  // coefficient pairs that take LinearSum's and Scale's special cases
  const std::vector<std::pair<double, double>> coefficients = {{1.0, -1.0}, {-1.0, 1.0}, {0.37, -1.9}, {0.5, 0.5}};
  for (auto [first, second] : coefficients) {
    const std::string which = " with " + std::to_string(first) + ", " + std::to_string(second);
    double c[] = {first, second};
    // in place, as CVODE corrects its history: Y = Z
    N_Vector library_y[] = {Library(1), Library(2)};
    N_Vector fixed_y[] = {Fixed(1), Fixed(2)};
    N_VScaleAddMulti(2, c, Library(0), library_y, library_y);
    N_VScaleAddMulti(2, c, Fixed(0), fixed_y, fixed_y);
    ExpectSameVectors("ScaleAddMulti in place" + which);
    // out of place
    N_Vector library_z[] = {Library(2)}, fixed_z[] = {Fixed(2)};
    N_VScaleAddMulti(1, c, Library(0), library_y, library_z);
    N_VScaleAddMulti(1, c, Fixed(0), fixed_y, fixed_z);
    ExpectSameVectors("ScaleAddMulti out of place" + which);

    N_Vector library_x[] = {Library(0), Library(1)}, fixed_x[] = {Fixed(0), Fixed(1)};
    N_VScaleVectorArray(2, c, library_x, library_x);
    N_VScaleVectorArray(2, c, fixed_x, fixed_x);
    ExpectSameVectors("ScaleVectorArray in place" + which);
    N_VScaleVectorArray(1, c, library_x, library_z);
    N_VScaleVectorArray(1, c, fixed_x, fixed_z);
    ExpectSameVectors("ScaleVectorArray out of place" + which);

    N_VLinearCombination(2, c, library_x, Library(2));
    N_VLinearCombination(2, c, fixed_x, Fixed(2));
    ExpectSameVectors("LinearCombination" + which);
  }
  // the library's vectors still take its fallbacks, ours do not
  EXPECT_EQ(Library(0)->ops->nvscaleaddmulti, nullptr);
  EXPECT_NE(Fixed(0)->ops->nvscaleaddmulti, nullptr);
}

TEST_F(FixedSizeVectorOpsTest, ReductionsMatch) {
  ExpectSameBits(N_VWrmsNorm(Library(0), Library(1)), N_VWrmsNorm(Fixed(0), Fixed(1)), "WrmsNorm");
  ExpectSameBits(N_VWSqrSumLocal(Library(0), Library(1)), N_VWSqrSumLocal(Fixed(0), Fixed(1)), "WSqrSumLocal");
  ExpectSameBits(N_VDotProd(Library(0), Library(1)), N_VDotProd(Fixed(0), Fixed(1)), "DotProd");
  ExpectSameBits(N_VMaxNorm(Library(0)), N_VMaxNorm(Fixed(0)), "MaxNorm");
  ExpectSameBits(N_VMin(Library(0)), N_VMin(Fixed(0)), "Min");
  N_VConst(0.0, Library(2));
  N_VConst(0.0, Fixed(2));
  ExpectSameBits(N_VWrmsNorm(Library(2), Library(1)), N_VWrmsNorm(Fixed(2), Fixed(1)), "WrmsNorm of zero");
}

TEST_F(FixedSizeVectorOpsTest, ClonesInheritTheOperations) {
  VectorPtr clone(N_VClone(Fixed(0)));
  ASSERT_NE(clone, nullptr);
  EXPECT_EQ(clone->ops->nvlinearsum, Fixed(0)->ops->nvlinearsum);
  EXPECT_EQ(clone->ops->nvwrmsnorm, Fixed(0)->ops->nvwrmsnorm);
  EXPECT_NE(clone->ops->nvlinearsum, Library(0)->ops->nvlinearsum);
}

TEST(FixedSizeOpsTest, RejectsOtherSizesAndLeavesThemAlone) {
  ContextPtr context = NewContext();
  ASSERT_NE(context, nullptr);
  VectorPtr short_vector(N_VNew_Serial(kN - 1, context.get()));
  const auto before = short_vector->ops->nvlinearsum;
  EXPECT_FALSE(UseFixedSizeVectorOps(short_vector.get()));
  EXPECT_EQ(short_vector->ops->nvlinearsum, before);
  EXPECT_FALSE(UseFixedSizeVectorOps(nullptr));

  MatrixPtr rectangular(SUNDenseMatrix(kN, kN - 1, context.get()));
  EXPECT_FALSE(UseFixedSizeMatrixOps(rectangular.get()));
  EXPECT_FALSE(UseFixedSizeMatrixOps(nullptr));
}

TEST(FixedSizeMatrixOpsTest, MatchSunmatrixDenseBitForBit) {
  ContextPtr context = NewContext();
  ASSERT_NE(context, nullptr);
  MatrixPtr library(SUNDenseMatrix(kN, kN, context.get())), fixed(SUNDenseMatrix(kN, kN, context.get()));
  ASSERT_TRUE(UseFixedSizeMatrixOps(fixed.get()));
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> unit(-1e4, 1e4);
  for (int k = 0; k < kN * kN; ++k) SM_DATA_D(library.get())[k] = SM_DATA_D(fixed.get())[k] = unit(rng);
  const auto expect_same = [&](SUNMatrix a, SUNMatrix b, const char* what) {
    EXPECT_EQ(std::memcmp(SM_DATA_D(a), SM_DATA_D(b), kN * kN * sizeof(double)), 0) << what;
  };

  // CVODE's Newton matrix: A = -gamma*J + I
  ASSERT_EQ(SUNMatScaleAddI(-0.0123, library.get()), SUNMAT_SUCCESS);
  ASSERT_EQ(SUNMatScaleAddI(-0.0123, fixed.get()), SUNMAT_SUCCESS);
  expect_same(library.get(), fixed.get(), "ScaleAddI");

  // the saved Jacobian is a clone that must copy with the same operations
  MatrixPtr clone(SUNMatClone(fixed.get()));
  ASSERT_NE(clone, nullptr);
  EXPECT_EQ(clone->ops->copy, fixed->ops->copy);
  ASSERT_EQ(SUNMatCopy(fixed.get(), clone.get()), SUNMAT_SUCCESS);
  expect_same(library.get(), clone.get(), "Copy");

  ASSERT_EQ(SUNMatZero(clone.get()), SUNMAT_SUCCESS);
  MatrixPtr zero(SUNDenseMatrix(kN, kN, context.get()));
  ASSERT_EQ(SUNMatZero(zero.get()), SUNMAT_SUCCESS);
  expect_same(zero.get(), clone.get(), "Zero");

  // a copy into a matrix of another size is refused, not overrun
  MatrixPtr small(SUNDenseMatrix(kN - 1, kN - 1, context.get()));
  EXPECT_NE(SUNMatCopy(fixed.get(), small.get()), SUNMAT_SUCCESS);
}

}  // namespace
}  // namespace walkers
