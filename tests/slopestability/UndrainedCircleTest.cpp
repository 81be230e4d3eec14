// phi' = 0 (undrained, c only) on a dry homogeneous slope: for a circle the moment equilibrium
// about the centre is exact, F = c L R / (W d) (L the arc length, W the weight of the sliding
// mass, d the horizontal distance from the centre to its centroid; e.g. Duncan & Wright 2005,
// Sec. 6.1, the Swedish circle). Bishop and the ordinary method both reduce to
// sum c l / sum W sin(alpha), the slice sums of the same two integrals, so they must agree with
// each other to round-off and with the exact value as the slices get narrow. The exact value is
// evaluated here independently of the slicing code: entry and exit by bisection, area and
// centroid of the mass by the shoelace formula on a polygon with a finely divided arc.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "argine/slopestability/Bishop.hpp"
#include "argine/slopestability/CircularSlip.hpp"

namespace argine {
namespace {

struct Point {
  Real x, y;
};

Real bisect(const std::function<Real(Real)>& f, Real a, Real b) {
  Real fa = f(a);
  for (int i = 0; i < 200; ++i) {
    const Real m = 0.5 * (a + b);
    const Real fm = f(m);
    if ((fm > 0) == (fa > 0)) {
      a = m;
      fa = fm;
    } else {
      b = m;
    }
  }
  return 0.5 * (a + b);
}

TEST(UndrainedCircle, BishopEqualsOrdinaryEqualsExactMomentEquilibrium) {
  // Ground: toe bench y = 0 to x = 10, a 2:1 face to (30, 10), crest to x = 60.
  const std::vector<Real> gx = {0, 10, 30, 60}, gy = {0, 0, 10, 10};
  const Real gamma = 18e3, c = 20e3;
  SlopeSection s;
  s.ground = Polyline(gx, gy);
  s.layers.push_back({"clay", s.ground, gamma, c, 0});
  const Real xc = 22, yc = 22, r = 23;

  // Independent geometry.
  const auto ground = [&](Real x) { return s.ground.at(x); };
  const auto arc = [&](Real x) { return yc - std::sqrt(r * r - (x - xc) * (x - xc)); };
  const auto gap = [&](Real x) { return ground(x) - arc(x); };
  const Real x_entry = bisect(gap, xc - r + 1e-9, xc);  // arc below ground to its right
  const Real x_exit = bisect(gap, xc, xc + r - 1e-9);
  std::vector<Point> poly;
  poly.push_back({x_entry, ground(x_entry)});
  for (std::size_t i = 0; i < gx.size(); ++i) {
    if (gx[i] > x_entry && gx[i] < x_exit) poly.push_back({gx[i], gy[i]});
  }
  poly.push_back({x_exit, ground(x_exit)});
  const Real t_exit = std::atan2(ground(x_exit) - yc, x_exit - xc);
  const Real t_entry = std::atan2(ground(x_entry) - yc, x_entry - xc);
  const int n_arc = 200000;
  for (int i = 1; i < n_arc; ++i) {  // back along the lower arc, exit -> entry
    const Real t = t_exit + (t_entry - t_exit) * i / n_arc;
    poly.push_back({xc + r * std::cos(t), yc + r * std::sin(t)});
  }
  Real area2 = 0, cx6 = 0;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const Point& p = poly[i];
    const Point& q = poly[(i + 1) % poly.size()];
    const Real cross = p.x * q.y - q.x * p.y;
    area2 += cross;
    cx6 += (p.x + q.x) * cross;
  }
  const Real area = 0.5 * std::abs(area2);
  const Real centroid_x = cx6 / (3 * area2);
  const Real arc_length = r * std::abs(t_exit - t_entry);
  const Real exact = c * arc_length * r / (gamma * area * (centroid_x - xc));

  for (const int n : {50, 400}) {
    const SlipMass mass = sliceCircle(s, SlipCircle{xc, yc, r}, n);
    ASSERT_TRUE(mass.valid) << mass.reason;
    EXPECT_NEAR(mass.entry_x, x_entry, 1e-9);
    EXPECT_NEAR(mass.exit_x, x_exit, 1e-9);
    const FactorOfSafety bishop = bishopSimplified(mass.slices);
    const FactorOfSafety ordinary = ordinaryMethodOfSlices(mass.slices);
    ASSERT_TRUE(bishop.admissible);
    EXPECT_NEAR(bishop.value, ordinary.value, 1e-12 * exact);
    // Midpoint sums of smooth integrands: error ~ 1/n^2 (0.1 % at 50 slices).
    EXPECT_NEAR(bishop.value, exact, (n == 50 ? 1e-3 : 2e-5) * exact)
        << "n = " << n << ", exact " << exact;
  }
}

}  // namespace
}  // namespace argine
