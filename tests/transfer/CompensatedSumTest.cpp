// Compensated node sums (reproducible sums): TwoSum is exact, and the folded sum does not
// depend on the order of the terms or on how they are split into partial sums.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "argine/transfer/CompensatedSum.hpp"

namespace argine {
namespace {

TEST(CompensatedSum, TwoSumKeepsTheRoundingError) {
  Real hi = 1e16, lo = 0;
  addCompensated(hi, lo, 1.0);  // 1e16 + 1 is not a double: the 1 goes to lo
  EXPECT_EQ(hi, 1e16);
  EXPECT_EQ(lo, 1.0);
  addCompensated(hi, lo, -1e16);
  EXPECT_EQ(hi + lo, 1.0);  // a plain running sum gives 0 here
  hi = 0.1, lo = 0;
  addCompensated(hi, lo, 0.2);
  // hi + lo is 0.1 + 0.2 exactly: hi the rounded sum, lo what rounding dropped.
  EXPECT_EQ(hi, 0.1 + 0.2);
  EXPECT_EQ(lo, -2.7755575615628914e-17);
}

/// Sum of `terms` compensated in the given order, folded.
Real compensatedSum(const std::vector<Real>& terms) {
  Real hi = 0, lo = 0;
  for (Real t : terms) addCompensated(hi, lo, t);
  return hi + lo;
}

TEST(CompensatedSum, OrderAndSplitDoNotChangeTheFoldedSum) {
  // 2,000 terms of mixed sign over 12 decades, partly cancelling (as forces at a node in
  // equilibrium): every order and every split into "rank" partial sums combined in rank
  // order (NodalExchange::sumCompensated) folds to the same double; plain sums do not.
  std::mt19937 random(4242);
  std::uniform_real_distribution<Real> mantissa(-1, 1);
  std::uniform_int_distribution<int> decade(-6, 6);
  std::vector<Real> terms;
  for (int k = 0; k < 1000; ++k) {
    const Real t = mantissa(random) * std::pow(10.0, decade(random));
    terms.push_back(t);
    terms.push_back(-t * (1 + 1e-9 * mantissa(random)));
  }
  const Real reference = compensatedSum(terms);
  int plain_differs = 0;
  Real plain_reference = 0;
  for (Real t : terms) plain_reference += t;
  for (int trial = 0; trial < 50; ++trial) {
    std::shuffle(terms.begin(), terms.end(), random);
    EXPECT_EQ(compensatedSum(terms), reference) << "order " << trial;
    // Split into 2..5 partial sums, combined as the nodal exchange does.
    const int parts = 2 + trial % 4;
    Real total_hi = 0, total_lo = 0;
    for (int r = 0; r < parts; ++r) {
      Real hi = 0, lo = 0;
      for (std::size_t k = r; k < terms.size(); k += parts) addCompensated(hi, lo, terms[k]);
      addCompensated(total_hi, total_lo, hi);
      total_lo += lo;
    }
    EXPECT_EQ(total_hi + total_lo, reference) << parts << " parts";
    Real plain = 0;
    for (Real t : terms) plain += t;
    if (plain != plain_reference) ++plain_differs;
  }
  EXPECT_GT(plain_differs, 0) << "the plain sums should depend on the order here";
}

}  // namespace
}  // namespace argine
