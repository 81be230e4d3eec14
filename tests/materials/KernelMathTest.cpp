// kmath::fmin and fmax (written out for speed) against the C99 rules they replace,
// kmath::logNearOne against the library's log and a long double reference, and kmath::powKnown
// against pow.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>

#include "argine/materials/KernelMath.hpp"

namespace argine {
namespace {

TEST(KernelMath, FminFmaxOrderedValues) {
  EXPECT_EQ(kmath::fmax(1.5, -2.0), 1.5);
  EXPECT_EQ(kmath::fmax(-2.0, 1.5), 1.5);
  EXPECT_EQ(kmath::fmin(1.5, -2.0), -2.0);
  EXPECT_EQ(kmath::fmin(-2.0, 1.5), -2.0);
  EXPECT_EQ(kmath::fmax(3.0, 3.0), 3.0);
  const Real inf = std::numeric_limits<Real>::infinity();
  EXPECT_EQ(kmath::fmax(-inf, 7.0), 7.0);
  EXPECT_EQ(kmath::fmin(inf, 7.0), 7.0);
}

TEST(KernelMath, FminFmaxIgnoreOneNaN) {  // C99 7.12.12: a NaN argument gives the other
  const Real nan = std::numeric_limits<Real>::quiet_NaN();
  EXPECT_EQ(kmath::fmax(nan, 2.0), 2.0);
  EXPECT_EQ(kmath::fmax(2.0, nan), 2.0);
  EXPECT_EQ(kmath::fmin(nan, -2.0), -2.0);
  EXPECT_EQ(kmath::fmin(-2.0, nan), -2.0);
  EXPECT_TRUE(std::isnan(kmath::fmax(nan, nan)));
  EXPECT_TRUE(std::isnan(kmath::fmin(nan, nan)));
}

TEST(KernelMath, FminFmaxAgreeWithTheLibrary) {
  const Real values[] = {-1e300, -3.25, -1e-310, 0.0, 1e-310, 0.5, 4.0, 1e300};
  for (Real x : values)
    for (Real y : values) {
      EXPECT_EQ(kmath::fmax(x, y), std::fmax(x, y)) << x << " " << y;
      EXPECT_EQ(kmath::fmin(x, y), std::fmin(x, y)) << x << " " << y;
    }
}

/// |a - b| in units in the last place of b.
Real ulpsApart(Real a, long double b) {
  const Real rounded = static_cast<Real>(b);
  const Real ulp = std::nextafter(std::fabs(rounded), std::numeric_limits<Real>::infinity()) -
                   std::fabs(rounded);
  return static_cast<Real>(std::fabs(static_cast<long double>(a) - b) / ulp);
}

TEST(KernelMath, LogNearOneIsWithinOneUlpOnItsIntervalAndTheLibraryLogOutside) {
  std::mt19937_64 random(11);
  std::uniform_real_distribution<Real> interval(std::sqrt(0.5), std::sqrt(2.0));
  Real worst = 0, worst_library = 0;
  int differ = 0, samples = 0;
  const auto check = [&](Real x) {
    const Real ours = kmath::logNearOne(x), library = std::log(x);
    const long double reference = std::log(static_cast<long double>(x));
    worst = std::max(worst, ulpsApart(ours, reference));
    worst_library = std::max(worst_library, ulpsApart(library, reference));
    differ += ours != library;
    ++samples;
  };
  for (int i = 0; i < 200000; ++i) check(interval(random));
  for (int k = 2; k <= 50; k += 4) {  // ln x ~ x - 1 down to 2^-50 from 1
    std::uniform_real_distribution<Real> near(-std::ldexp(1.0, -k), std::ldexp(1.0, -k));
    for (int i = 0; i < 20000; ++i) check(1 + near(random));
  }
  EXPECT_LE(worst, 1.0) << "library: " << worst_library;
  EXPECT_LT(differ, samples / 10);  // mostly the library's bits; never more than 1 ulp off
  EXPECT_EQ(kmath::logNearOne(1.0), 0.0);
  // Outside [sqrt(1/2), sqrt(2)] the library's log itself.
  for (Real x : {0.5, 0.7, 1.5, 2.0, 1e-300, 1e300, 0.0}) {
    const Real ours = kmath::logNearOne(x), library = std::log(x);
    EXPECT_EQ(std::memcmp(&ours, &library, sizeof ours), 0) << x;
  }
  EXPECT_TRUE(std::isnan(kmath::logNearOne(-1.0)));
  EXPECT_TRUE(std::isnan(kmath::logNearOne(std::nan(""))));
}

TEST(KernelMath, LogNearOneGivesEachLaneTheOneValueBits) {
  const Lanes inside = {1.0 + 1e-9, 0.8, 1.3, 1.0 - 3e-5};
  const Lanes mixed = {1.0 + 4.5e-5, 3.0, 0.75, -2.0};  // two lanes outside: library calls
  for (const Lanes& x : {inside, mixed}) {
    const Lanes lanes = kmath::logNearOne(x);
    for (int l = 0; l < kLanes; ++l) {
      const Real one = kmath::logNearOne(x[l]);
      EXPECT_EQ(std::memcmp(&one, &lanes[l], sizeof one), 0) << l;
    }
  }
}

// expNearZero: within 1 ulp of e^x (long double reference) on |x| <= 2^-8, down to 2^-60, and
// the library's exp to the bit outside; each lane gets the one-value bits.
TEST(KernelMath, ExpNearZeroIsWithinOneUlpOnItsIntervalAndTheLibraryExpOutside) {
  std::mt19937_64 random(13);
  Real worst = 0, worst_library = 0;
  int differ = 0, samples = 0;
  for (int k = 8; k <= 60; k += 4) {
    std::uniform_real_distribution<Real> near(-std::ldexp(1.0, -k), std::ldexp(1.0, -k));
    for (int i = 0; i < 20000; ++i) {
      const Real x = near(random);
      const Real ours = kmath::expNearZero(x), library = std::exp(x);
      const long double reference = std::exp(static_cast<long double>(x));
      worst = std::max(worst, ulpsApart(ours, reference));
      worst_library = std::max(worst_library, ulpsApart(library, reference));
      differ += ours != library;
      ++samples;
    }
  }
  EXPECT_LE(worst, 1.0) << "library: " << worst_library;
  EXPECT_LT(differ, samples / 10);
  EXPECT_EQ(kmath::expNearZero(0.0), 1.0);
  for (Real x : {0.00390625, -0.00390625})  // the interval's ends
    EXPECT_LE(ulpsApart(kmath::expNearZero(x), std::exp(static_cast<long double>(x))), 1.0);
  for (Real x : {0.0039063, -0.0039063, 0.5, -3.0, 700.0, -800.0}) {
    const Real ours = kmath::expNearZero(x), library = std::exp(x);
    EXPECT_EQ(std::memcmp(&ours, &library, sizeof ours), 0) << x;
  }
  EXPECT_TRUE(std::isnan(kmath::expNearZero(std::nan(""))));
  const Lanes mixed = {1e-5, -2.0, -3e-4, 0.25};
  const Lanes lanes = kmath::expNearZero(mixed);
  for (int l = 0; l < kLanes; ++l) {
    const Real one = kmath::expNearZero(mixed[l]);
    EXPECT_EQ(std::memcmp(&one, &lanes[l], sizeof one), 0) << l;
  }
}

// powKnown: the exponents taken without pow agree with pow within 1 ulp (x * x and sqrt to the
// bit) over 12 decades, at 0, -0 and infinity; any other exponent is pow itself.
TEST(KernelMath, PowKnownAgreesWithPow) {
  std::mt19937_64 random(7);
  std::uniform_real_distribution<Real> decade(-6, 6);
  auto ulps = [](Real a, Real b) {
    return std::fabs(a - b) / (std::nextafter(std::fabs(b), 2 * std::fabs(b) + 1) - std::fabs(b));
  };
  for (int k = 0; k < 100000; ++k) {
    const Real x = std::pow(10.0, decade(random));
    EXPECT_EQ(kmath::powKnown(x, 2.0), x * x);
    EXPECT_EQ(kmath::powKnown(x, 0.5), std::sqrt(x));
    EXPECT_LE(ulps(kmath::powKnown(x, 2.0), std::pow(x, 2.0)), 0.0) << x;
    EXPECT_LE(ulps(kmath::powKnown(x, 0.5), std::pow(x, 0.5)), 1.0) << x;
    EXPECT_LE(ulps(kmath::powKnown(x, -0.5), std::pow(x, -0.5)), 1.0) << x;
    EXPECT_LE(ulps(kmath::powKnown(x, -2.0), std::pow(x, -2.0)), 1.0) << x;
    EXPECT_EQ(kmath::powKnown(x, 1.0), x);
    EXPECT_EQ(kmath::powKnown(x, 0.63), std::pow(x, 0.63));
    EXPECT_EQ(kmath::powKnown(x, 1 / (1 - 0.63)), std::pow(x, 1 / (1 - 0.63)));
  }
  const Real inf = std::numeric_limits<Real>::infinity();
  for (const Real e : {2.0, 0.5, -0.5, -2.0}) {
    for (const Real x : {0.0, -0.0, inf}) {
      const Real expected = std::pow(x, e), got = kmath::powKnown(x, e);
      EXPECT_EQ(got, expected) << x << "^" << e;
      EXPECT_EQ(std::signbit(got), std::signbit(expected)) << x << "^" << e;
    }
  }
}

}  // namespace
}  // namespace argine
