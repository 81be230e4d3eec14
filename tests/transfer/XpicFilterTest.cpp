// [2Phase][Transfer][XPIC] The extended PIC update XPIC(m) (Hammerquist and Nairn 2017):
// filterNodalVelocitiesXpic and the FLIP update with both PIC shares 1 give each phase's
// point velocities [I - (I - P)^m] v_p, P = S+ S the PIC round trip with lumped masses,
// computed here densely and as a product (not as the code's binomial series), on the
// linear and the grid shape families; the momentum is kept, the points' own velocities
// are left as they were, and a smooth field is kept better with every order.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <random>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "TestScenes.hpp"
#include "argine/transfer/ActiveNodes.hpp"
#include "argine/transfer/GridFields.hpp"
#include "argine/transfer/NodeRecords.hpp"
#include "argine/transfer/PointShapes.hpp"
#include "argine/transfer/TwoPhaseTransfer.hpp"
#include "argine/transfer/XpicFilter.hpp"

namespace argine {
namespace {

using test::hostCopy;
using test::liquidFlags;

/// Each point's nodes and shape values, read from its shapes (linear records, or the
/// grid's tensor stencil: node line_x + row line_y, N = value_x value_y; folded lines
/// repeat a node, whose weights then add).
using Weights = std::vector<std::vector<std::pair<int, Real>>>;

Weights weightsOf(const PointShapes& shapes, int count, int per) {
  Weights w(count);
  if (shapes.onGrid()) {
    const auto grid = hostCopy(shapes.grid_p);
    for (int p = 0; p < count; ++p)
      for (int ay = 0; ay < kGridStencil; ++ay)
        for (int ax = 0; ax < kGridStencil; ++ax)
          w[p].push_back({grid(p).line[0][ax] + grid(p).line[1][ay] * shapes.grid_row,
                          grid(p).value[0][ax] * grid(p).value[1][ay]});
    return w;
  }
  const auto stored = hostCopy(shapes.stored_p);
  for (int p = 0; p < count; ++p)
    for (int a = 0; a < per; ++a) w[p].push_back({stored(p).node[a], stored(p).value[a]});
  return w;
}

/// [I - R(P)] v of one phase with point masses m (points of m = 0 take no part), P v = S+ S v:
/// nodal momenta and lumped masses, their ratio interpolated back. R(P) = (I - P)^m for the
/// binomial series; for Chebyshev's on [a, 1], (I - P)^j s_k(P)^2 with s_k(P) = T_k((theta I -
/// P) / delta) / T_k(theta / delta), theta = (1 + a) / 2, delta = (1 - a) / 2, k = (m - 1) / 2,
/// j = m - 2k, T_k by its three-term recurrence (not the code's Chebyshev iteration).
std::vector<Real> xpicReference(const Weights& w, const std::vector<Real>& m,
                                const std::vector<Real>& v, int nodes,
                                const XpicPolynomial& polynomial) {
  const int count = static_cast<int>(v.size());
  const auto pic = [&](const std::vector<Real>& x) {
    std::vector<Real> momentum(nodes, 0.0), mass(nodes, 0.0), out(count, 0.0);
    for (int p = 0; p < count; ++p)
      for (const auto& [i, N] : w[p]) {
        momentum[i] += N * m[p] * x[p];
        mass[i] += N * m[p];
      }
    for (int p = 0; p < count; ++p)
      for (const auto& [i, N] : w[p]) out[p] += mass[i] > 0 ? N * momentum[i] / mass[i] : 0;
    return out;
  };
  const Real a = polynomial.lower_eigenvalue;
  const int k = a > 0 ? (polynomial.order - 1) / 2 : 0;
  std::vector<Real> rest = v;                         // R(P) v
  for (int twice = 0; twice < 2 && k > 0; ++twice) {  // s_k(P) rest, twice
    const Real theta = (1 + a) / 2, delta = (1 - a) / 2, sigma = theta / delta;
    const auto shifted = [&](const std::vector<Real>& x) {  // (theta I - P) x / delta
      const std::vector<Real> picked = pic(x);
      std::vector<Real> out(count);
      for (int p = 0; p < count; ++p) out[p] = (theta * x[p] - picked[p]) / delta;
      return out;
    };
    std::vector<Real> before = rest, now = shifted(rest);  // T_0 rest, T_1 rest
    Real t_before = 1, t_now = sigma;                      // T_0(sigma), T_1(sigma)
    for (int n = 1; n < k; ++n) {
      const std::vector<Real> x_now = shifted(now);
      for (int p = 0; p < count; ++p) {
        const Real next = 2 * x_now[p] - before[p];
        before[p] = now[p];
        now[p] = next;
      }
      const Real t_next = 2 * sigma * t_now - t_before;
      t_before = t_now;
      t_now = t_next;
    }
    for (int p = 0; p < count; ++p) rest[p] = now[p] / t_now;
  }
  for (int step = 0; step < polynomial.order - 2 * k; ++step) {  // (I - P)^j
    const std::vector<Real> picked = pic(rest);
    for (int p = 0; p < count; ++p) rest[p] -= picked[p];
  }
  std::vector<Real> kept(count);
  for (int p = 0; p < count; ++p) kept[p] = v[p] - rest[p];
  return kept;
}

using Shapes = std::tuple<ElementType, ShapeFamily>;

/// 4 x 3 cells of 0.5 m, points seeded uniformly, every third dry, random masses and
/// liquid densities; the velocities `velocity(x, y, p)` for both phases (the liquid's
/// turned by a phase shift).
struct XpicScene {
  Mesh mesh;
  MaterialPoints points;
  PointShapes shapes;
  GridFields grid;
  ActiveNodes active;
  int per = 0;
};

template <class Velocity>
XpicScene makeScene(const Shapes& s, unsigned seed, const Velocity& velocity) {
  const auto [type, family] = s;
  XpicScene scene;
  scene.mesh = family == ShapeFamily::Linear ? test::rectangleMesh(4, 3, 2.0, 1.5, type)
                                             : test::gridMesh(4, 3, 2.0, 1.5, family);
  scene.per = type == ElementType::Quad4 ? 4 : 3;
  scene.points = test::seedUniform(scene.mesh);
  MaterialPoints& points = scene.points;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<Real> u(-1, 1);
  auto material = hostCopy(points.material);
  auto ms = hostCopy(points.mass_solid), ml = hostCopy(points.mass_liquid);
  auto rho = hostCopy(points.density_liquid);
  auto vs = hostCopy(points.velocity_solid), vl = hostCopy(points.velocity_liquid);
  const auto x = hostCopy(points.position);
  for (int p = 0; p < points.count; ++p) {
    material(p) = p % 3 == 2 ? 1 : 0;
    ms(p) = 2 + u(rng);
    ml(p) = material(p) == 0 ? 1 + 0.5 * u(rng) : 0;
    rho(p) = material(p) == 0 ? 1000 + 10 * u(rng) : 0;
    for (int d = 0; d < kDim; ++d) {
      vs(p, d) = velocity(x(p, 0), x(p, 1), p, d);
      vl(p, d) = material(p) == 0 ? velocity(x(p, 1), x(p, 0), p + 1, d) : 0;
    }
  }
  Kokkos::deep_copy(points.material, material);
  Kokkos::deep_copy(points.mass_solid, ms);
  Kokkos::deep_copy(points.mass_liquid, ml);
  Kokkos::deep_copy(points.density_liquid, rho);
  Kokkos::deep_copy(points.velocity_solid, vs);
  Kokkos::deep_copy(points.velocity_liquid, vl);
  evaluatePointShapes(scene.mesh, points, scene.shapes);
  scene.grid.allocate(scene.mesh.numNodes());
  scene.active = ActiveNodes(scene.mesh.numNodes());
  scene.active.rebuild(scene.mesh, points);
  return scene;
}

/// One XPIC(order) velocity update without forces: the P2G of t^k, the filter, the FLIP
/// update with both shares 1 (the step's order). Returns whether the filter left the
/// points' velocities as they were, bit for bit.
bool xpicUpdate(XpicScene& s, const XpicPolynomial& polynomial) {
  NodeRecords records;
  s.grid.zero(s.active);
  mapPointsToGrid(s.points, s.shapes, liquidFlags(), 0.0, TransferSettings{}, s.active, records,
                  s.grid);
  computeNodalVelocities(s.active, s.grid);
  Kokkos::deep_copy(s.grid.acceleration_solid_i, 0.0);
  Kokkos::deep_copy(s.grid.acceleration_liquid_i, 0.0);
  const auto vs = hostCopy(s.points.velocity_solid), vl = hostCopy(s.points.velocity_liquid);
  XpicScratch scratch;
  filterNodalVelocitiesXpic(polynomial, s.shapes, liquidFlags(), s.active, s.points, records,
                            s.grid, scratch, nullptr, {});
  const auto vs_after = hostCopy(s.points.velocity_solid);
  const auto vl_after = hostCopy(s.points.velocity_liquid);
  bool kept = true;
  for (int p = 0; p < s.points.count; ++p)
    for (int d = 0; d < kDim; ++d)
      kept = kept && vs_after(p, d) == vs(p, d) && vl_after(p, d) == vl(p, d);
  TransferSettings xpic;
  xpic.scheme = TransferScheme::Xpic;
  xpic.blend = VelocityBlend{1, 1};
  updatePointVelocitiesAndMapMomenta(s.shapes, liquidFlags(), s.active, 1e-3, xpic, s.points,
                                     records, s.grid);
  return kept;
}

class XpicOnShapes : public ::testing::TestWithParam<Shapes> {};

/// Every point velocity of both phases against the dense reference, and the momentum kept.
void expectPolynomialOfThePicRoundTrip(const Shapes& shapes, const XpicPolynomial& polynomial) {
  const auto random = [](unsigned seed) {
    return [rng = std::make_shared<std::mt19937>(seed)](Real, Real, int, int) {
      return std::uniform_real_distribution<Real>(-1, 1)(*rng);
    };
  };
  {
    XpicScene s = makeScene(shapes, 31, random(32));
    const int count = s.points.count, nodes = s.mesh.numNodes();
    const Weights w = weightsOf(s.shapes, count, s.per);
    const auto ms = hostCopy(s.points.mass_solid), rho = hostCopy(s.points.density_liquid);
    const auto volume = hostCopy(s.points.volume);
    const auto material = hostCopy(s.points.material);
    const auto vs0 = hostCopy(s.points.velocity_solid), vl0 = hostCopy(s.points.velocity_liquid);
    std::vector<Real> solid_mass(count), liquid_mass(count);
    for (int p = 0; p < count; ++p) {
      solid_mass[p] = ms(p);
      liquid_mass[p] = material(p) == 0 ? rho(p) * volume(p) : 0;  // as the nodal v_L of t^k
    }
    EXPECT_TRUE(xpicUpdate(s, polynomial)) << "the filter changed the points' velocities";
    const auto vs = hostCopy(s.points.velocity_solid), vl = hostCopy(s.points.velocity_liquid);
    for (int d = 0; d < kDim; ++d) {
      std::vector<Real> solid(count), liquid(count);
      Real momentum0 = 0, momentum = 0, liquid_momentum0 = 0, liquid_momentum = 0, scale = 0;
      for (int p = 0; p < count; ++p) {
        solid[p] = vs0(p, d);
        liquid[p] = vl0(p, d);
        momentum0 += solid_mass[p] * vs0(p, d);
        momentum += solid_mass[p] * vs(p, d);
        liquid_momentum0 += liquid_mass[p] * vl0(p, d);
        liquid_momentum += liquid_mass[p] * vl(p, d);
        scale += solid_mass[p] + liquid_mass[p];
      }
      const std::vector<Real> solid_ref = xpicReference(w, solid_mass, solid, nodes, polynomial);
      const std::vector<Real> liquid_ref = xpicReference(w, liquid_mass, liquid, nodes, polynomial);
      for (int p = 0; p < count; ++p) {
        EXPECT_NEAR(vs(p, d), solid_ref[p], 1e-12) << "solid, point " << p;
        if (material(p) == 0) {
          EXPECT_NEAR(vl(p, d), liquid_ref[p], 1e-12) << "liquid, point " << p;
        }
      }
      EXPECT_NEAR(momentum, momentum0, 1e-12 * scale);
      EXPECT_NEAR(liquid_momentum, liquid_momentum0, 1e-12 * scale);
    }
  }
}

TEST_P(XpicOnShapes, KeepsTheTruncatedSeriesOfThePicRoundTripAndTheMomentum) {
  for (const int order : {1, 2, 3, 5}) {
    SCOPED_TRACE("XPIC(" + std::to_string(order) + ")");
    expectPolynomialOfThePicRoundTrip(GetParam(), XpicPolynomial{order, 0.0});
  }
}

TEST_P(XpicOnShapes, KeepsChebyshevsPolynomialOfThePicRoundTripAndTheMomentum) {
  // odd and even orders (j = 1, 2), k from 0 (the binomial's m = 2) to 8
  for (const auto& [order, a] : std::vector<std::pair<int, Real>>{
           {2, 0.1}, {3, 0.1}, {4, 0.05}, {5, 0.2}, {9, 0.05}, {17, 0.02}}) {
    SCOPED_TRACE("Chebyshev XPIC(" + std::to_string(order) + "), a = " + std::to_string(a));
    expectPolynomialOfThePicRoundTrip(GetParam(), XpicPolynomial{order, a});
  }
}

TEST_P(XpicOnShapes, KeepsASmoothFieldBetterWithEveryOrder) {
  // P is self-adjoint and positive semi-definite in the points' mass inner product with
  // spectral radius <= 1, so |(I - P)^m v| falls with m: the loss of one update, the mass-
  // weighted norm of v - v_new, is PIC's at m = 1 and smaller at every order after it.
  const auto smooth = [](Real x, Real y, int, int d) {
    return d == 0 ? std::sin(1.3 * x + 0.4) * std::cos(0.9 * y) : std::cos(0.7 * x - 1.1 * y);
  };
  Real last = 0;
  for (const int order : {1, 2, 3, 5}) {
    XpicScene s = makeScene(GetParam(), 41, smooth);
    const auto ms = hostCopy(s.points.mass_solid);
    const auto v0 = hostCopy(s.points.velocity_solid);
    xpicUpdate(s, XpicPolynomial{order, 0.0});
    const auto v = hostCopy(s.points.velocity_solid);
    Real loss = 0;
    for (int p = 0; p < s.points.count; ++p)
      for (int d = 0; d < kDim; ++d) loss += ms(p) * (v(p, d) - v0(p, d)) * (v(p, d) - v0(p, d));
    loss = std::sqrt(loss);
    if (order == 1) {
      EXPECT_GT(loss, 1e-3) << "PIC smooths the field";
    } else {
      EXPECT_LT(loss, last) << "XPIC(" << order << ")";
    }
    last = loss;
  }
}

INSTANTIATE_TEST_SUITE_P(Shapes, XpicOnShapes,
                         ::testing::Values(Shapes{ElementType::Quad4, ShapeFamily::Linear},
                                           Shapes{ElementType::Tri3, ShapeFamily::Linear},
                                           Shapes{ElementType::Quad4, ShapeFamily::Gimp},
                                           Shapes{ElementType::Quad4, ShapeFamily::BSpline}),
                         [](const auto& info) {
                           const ElementType type = std::get<0>(info.param);
                           const ShapeFamily family = std::get<1>(info.param);
                           return std::string(family == ShapeFamily::Gimp      ? "Gimp"
                                              : family == ShapeFamily::BSpline ? "BSpline"
                                              : type == ElementType::Tri3      ? "Tri3"
                                                                               : "Quad4");
                         });

}  // namespace
}  // namespace argine
