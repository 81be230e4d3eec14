// Reproducible node sums (binned sums): exact bin by bin, and the folded sum depends neither
// on the order of the terms nor on how they are split into partial sums (ranks).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <random>
#include <vector>

#include "argine/transfer/CompensatedSum.hpp"

namespace argine {
namespace {

/// The sum of `terms`, added in the given order.
CompensatedReal sumOf(const std::vector<Real>& terms) {
  CompensatedReal sum;
  for (Real t : terms) sum.add(t);
  return sum;
}

/// The same bits (EXPECT_EQ takes -0 for +0).
bool sameBits(Real a, Real b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

/// The TwoSum pair hi + lo, lo summed in double, folded once (the reproducible sums of
/// 8761221 and before): for the data of the tests below.
Real pairSum(const std::vector<std::vector<Real>>& ranks) {
  Real total_hi = 0, total_lo = 0;
  const auto two_sum = [](Real& hi, Real& lo, Real v) {
    const Real sum = hi + v, v_part = sum - hi;
    lo += (hi - (sum - v_part)) + (v - v_part);
    hi = sum;
  };
  for (const auto& terms : ranks) {
    Real hi = 0, lo = 0;
    for (Real t : terms) two_sum(hi, lo, t);
    two_sum(total_hi, total_lo, hi);
    total_lo += lo;
  }
  return total_hi + total_lo;
}

TEST(CompensatedSum, KeepsWhatPlainSumsLose) {
  EXPECT_EQ(sumOf({1e16, 1.0, -1e16}).value(), 1.0);  // a plain running sum gives 0
  EXPECT_EQ(sumOf({0.1, 0.2}).value(), 0.1 + 0.2);    // one rounding, as the plain sum's
  EXPECT_EQ(sumOf({3.0, -3.0}).value(), 0.0);
  EXPECT_TRUE(sameBits(sumOf({3.0, -3.0}).value(), 0.0));  // +0, as 3 + -3
  EXPECT_TRUE(sameBits(sumOf({-0.0}).value(), 0.0));       // as +0 + -0
  EXPECT_TRUE(sameBits(CompensatedReal{}.value(), 0.0));
  // 112 bits and more below the largest term are kept: here 1e-30 to 2^-126
  EXPECT_NEAR(sumOf({1.0, 1e-30, -1.0}).value(), 1e-30, 0x1p-126);
  EXPECT_EQ(sumOf({0x1p-1074, 0x1p-1074, 0x1p-1060}).value(), 0x1p-1060 + 0x1p-1073);
  EXPECT_EQ(sumOf({1.5e308, 1.5e308, -1.5e308}).value(), HUGE_VAL);  // a bin overflows
  EXPECT_EQ(sumOf({1.0, HUGE_VAL, 2.0}).value(), HUGE_VAL);
  EXPECT_TRUE(std::isnan(sumOf({1.0, HUGE_VAL, -HUGE_VAL}).value()));
}

TEST(CompensatedSum, OrderAndSplitDoNotChangeTheFoldedSum) {
  // 2,000 terms of mixed sign over 12 decades, partly cancelling (as forces at a node in
  // equilibrium): every order and every split into "rank" partial sums merged in rank
  // order (NodalExchange::sumCompensated) gives the same parts and the same double; plain
  // sums do not.
  std::mt19937 random(4242);
  std::uniform_real_distribution<Real> mantissa(-1, 1);
  std::uniform_int_distribution<int> decade(-6, 6);
  std::vector<Real> terms;
  for (int k = 0; k < 1000; ++k) {
    const Real t = mantissa(random) * std::pow(10.0, decade(random));
    terms.push_back(t);
    terms.push_back(-t * (1 + 1e-9 * mantissa(random)));
  }
  const CompensatedReal reference = sumOf(terms);
  int plain_differs = 0;
  Real plain_reference = 0;
  for (Real t : terms) plain_reference += t;
  for (int trial = 0; trial < 50; ++trial) {
    std::shuffle(terms.begin(), terms.end(), random);
    const CompensatedReal shuffled = sumOf(terms);
    for (int k = 0; k < kSumParts; ++k)
      EXPECT_TRUE(sameBits(shuffled.part[k], reference.part[k])) << "order " << trial;
    // Split into 2..5 partial sums, merged as the nodal exchange does.
    const int parts = 2 + trial % 4;
    CompensatedReal total;
    for (int r = 0; r < parts; ++r) {
      CompensatedReal partial;
      for (std::size_t k = r; k < terms.size(); k += parts) partial.add(terms[k]);
      total.add(partial);
    }
    EXPECT_TRUE(sameBits(total.value(), reference.value())) << parts << " parts";
    Real plain = 0;
    for (Real t : terms) plain += t;
    if (plain != plain_reference) ++plain_differs;
  }
  EXPECT_GT(plain_differs, 0) << "the plain sums should depend on the order here";
}

// The mixture force in x at node (80, 2) of the uGIMP + APIC Mohr-Coulomb block of
// benchmark_schemes_two_ranks in its step 14 (2 warm-up steps and 12), on the ranks' cut x = 8
// m: its 36 terms in one rank's order, and in each of two ranks' orders. The exact sum,
// 6.42e-8 N from terms of up to 144 N, lies 4.9e-30 N below the midpoint between
// 0x1.13d2544293d8ap-24 and 0x1.13d2544293d8bp-24; rounded correctly it is the latter.
// clang-format off
const std::vector<Real> kBlockForceOneRank = {
    0x0p+0, 0x0p+0, 0x0p+0, 0x0p+0, 0x0p+0, 0x0p+0, 0x0p+0, 0x1.b01db47e2d16p-43,
    0x1.8019ffe4ae2e1p+5, 0x1.8019ffe4ae29ap+5, 0x1.2013cda924aecp+7, 0x1.2013cda924a8fp+7,
    -0x1.8019ffe444dc9p+5, -0x1.8019ffe4450ep+5, -0x1.2013cda973356p+7, -0x1.2013cda973436p+7,
    -0x1.8019ffe5803e3p-43, -0x1.2013cda973801p-41, 0x0p+0, 0x1.baab641f3d986p-45,
    0x1.baaa09ec77a9fp+6, 0x1.baaa09ec77b8ap+6, 0x1.271ced6a2949cp+5, 0x1.271ced6a295a2p+5,
    -0x1.baaa09ea01f1fp+6, -0x1.baaa09ea01e38p+6, -0x1.271ced69572b4p+5, -0x1.271ced6a91e0ap+5,
    -0x1.baaa09ea01f68p-42, -0x1.271ced69bff7dp-43, 0x0p+0, 0x1.59635381358d8p-29,
    0x1.596353a506892p-29, -0x1.5963531d891c8p-29, -0x1.5963536f8ed77p-29, -0x1.596353a36387fp-77};
const std::vector<Real> kBlockForceRank0 = {
    0x0p+0, 0x0p+0, 0x0p+0, 0x0p+0, 0x1.b01db47e2d16p-43, 0x1.8019ffe4ae2e1p+5,
    0x1.8019ffe4ae29ap+5, 0x1.2013cda924aecp+7, 0x1.2013cda924a8fp+7, 0x0p+0,
    0x1.baab641f3d986p-45, 0x1.baaa09ec77a9fp+6, 0x1.baaa09ec77b8ap+6, 0x1.271ced6a2949cp+5,
    0x1.271ced6a295a2p+5, 0x0p+0, 0x1.59635381358d8p-29, 0x1.596353a506892p-29};
const std::vector<Real> kBlockForceRank1 = {
    0x0p+0, 0x0p+0, 0x0p+0, -0x1.8019ffe444dc9p+5, -0x1.8019ffe4450ep+5, -0x1.2013cda973356p+7,
    -0x1.2013cda973436p+7, -0x1.8019ffe5803e3p-43, -0x1.2013cda973801p-41, -0x1.baaa09ea01f1fp+6,
    -0x1.baaa09ea01e38p+6, -0x1.271ced69572b4p+5, -0x1.271ced6a91e0ap+5, -0x1.baaa09ea01f68p-42,
    -0x1.271ced69bff7dp-43, -0x1.5963531d891c8p-29, -0x1.5963536f8ed77p-29,
    -0x1.596353a36387fp-77};
// clang-format on

TEST(CompensatedSum, ANearTieOfTheGimpApicBlockRoundsAsOnOneRank) {
  // The TwoSum pairs rounded it to either side on one rank and on two (the block's
  // fingerprints differed): the data still shows it.
  ASSERT_NE(pairSum({kBlockForceOneRank}), pairSum({kBlockForceRank0, kBlockForceRank1}));
  const Real expected = 0x1.13d2544293d8bp-24;
  EXPECT_TRUE(sameBits(sumOf(kBlockForceOneRank).value(), expected));
  CompensatedReal two_ranks = sumOf(kBlockForceRank0);
  two_ranks.add(sumOf(kBlockForceRank1));
  EXPECT_TRUE(sameBits(two_ranks.value(), expected));
  std::vector<Real> terms = kBlockForceOneRank;
  std::mt19937 random(7);
  for (int trial = 0; trial < 200; ++trial) {
    std::shuffle(terms.begin(), terms.end(), random);
    const std::size_t cut = random() % (terms.size() + 1);
    CompensatedReal first, second;
    for (std::size_t k = 0; k < terms.size(); ++k) (k < cut ? first : second).add(terms[k]);
    second.add(first);  // the higher rank first: the merge's order does not matter either
    EXPECT_TRUE(sameBits(second.value(), expected)) << trial;
  }
}

TEST(CompensatedSum, GimpTiesAreRoundedByTheirRoundOffTerms) {
  // The drag at node (23, 1) of the uGIMP Mohr-Coulomb block in its first step: 30 terms
  // of dyadic masses times uGIMP weights plus their round-off, and two terms of 1e-28 from
  // weights that are 0 in exact arithmetic. Without those two the sum is the midpoint
  // between 0x1.329000000000cp+15 and 0x1.329000000000dp+15; with them it lies above it, so
  // the exact sum rounds to the latter. A pair's low part (4e-12 here) drops them, and the
  // pair ties to the even neighbour.
  // clang-format off
  const std::vector<Real> terms = {
      0x0p+0, 0x0p+0, 0x1.328ffffffffffp+9, 0x1.cbd8000000025p+10, 0x1.cbd7ffffffff8p+10,
      0x1.58e2000000017p+12, 0x1.cbd800000001p+10, 0x1.329000000000bp+9, 0x1.58e2000000007p+12,
      0x1.cbd8000000009p+10, 0x0p+0, 0x0p+0, 0x0p+0, 0x0p+0, 0x1.cbd8p+10, 0x1.58e200000001ap+12,
      0x1.328ffffffffffp+9, 0x1.cbd800000001dp+10, 0x1.58e200000000ep+12, 0x1.cbd800000001p+10,
      0x1.cbd800000001p+10, 0x1.3290000000001p+9, 0x0p+0, 0x0p+0, 0x0p+0, 0x0p+0, 0x0p+0,
      0x1.cbd800000000bp-92, 0x1.3290000000007p-93, 0x0p+0};
  // clang-format on
  EXPECT_EQ(pairSum({terms}), 0x1.329000000000cp+15);
  EXPECT_EQ(sumOf(terms).value(), 0x1.329000000000dp+15);
  std::vector<Real> without_round_off;
  for (Real t : terms)
    if (std::abs(t) > 1e-20) without_round_off.push_back(t);
  EXPECT_EQ(sumOf(without_round_off).value(), 0x1.329000000000cp+15);  // the tie, to even
}

}  // namespace
}  // namespace argine
