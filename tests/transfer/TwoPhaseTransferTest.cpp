// [2Phase][Transfer] P2G conservation, G2P reproduction of linear fields, internal forces.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <type_traits>
#include <vector>

#include "TestScenes.hpp"
#include "argine/core/Lanes.hpp"
#include "argine/mesh/PointLocator.hpp"
#include "argine/points/PointFields.hpp"
#include "argine/transfer/ActiveNodes.hpp"
#include "argine/transfer/AffineElementMaps.hpp"
#include "argine/transfer/GridFields.hpp"
#include "argine/transfer/NodeRecords.hpp"
#include "argine/transfer/PointRates.hpp"
#include "argine/transfer/PointShapes.hpp"
#include "argine/transfer/TwoPhaseTransfer.hpp"

namespace argine {
namespace {

using test::hostCopy;
using test::liquidFlags;

/// Random point masses, velocities and states; material 0 carries liquid, material 1 is dry
/// (every third point).
void randomise(MaterialPoints& points, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<Real> u(-1, 1);
  auto mass_solid = Kokkos::create_mirror_view(points.mass_solid);
  auto mass_liquid = Kokkos::create_mirror_view(points.mass_liquid);
  auto density = Kokkos::create_mirror_view(points.density_liquid);
  auto vs = Kokkos::create_mirror_view(points.velocity_solid);
  auto vl = Kokkos::create_mirror_view(points.velocity_liquid);
  auto material = Kokkos::create_mirror_view(points.material);
  auto porosity = Kokkos::create_mirror_view(points.porosity);
  auto saturation = Kokkos::create_mirror_view(points.saturation);
  auto conductivity = Kokkos::create_mirror_view(points.conductivity);
  for (int p = 0; p < points.count; ++p) {
    material(p) = p % 3 == 2 ? 1 : 0;
    mass_solid(p) = 2 + u(rng);
    mass_liquid(p) = material(p) == 0 ? 1 + 0.5 * u(rng) : 0;
    density(p) = material(p) == 0 ? 1000 + 10 * u(rng) : 0;
    porosity(p) = 0.4;
    saturation(p) = material(p) == 0 ? 1 : 0;
    conductivity(p) = 1e-3;
    for (int d = 0; d < kDim; ++d) {
      vs(p, d) = u(rng);
      vl(p, d) = material(p) == 0 ? u(rng) : 0;
    }
  }
  Kokkos::deep_copy(points.mass_solid, mass_solid);
  Kokkos::deep_copy(points.mass_liquid, mass_liquid);
  Kokkos::deep_copy(points.density_liquid, density);
  Kokkos::deep_copy(points.velocity_solid, vs);
  Kokkos::deep_copy(points.velocity_liquid, vl);
  Kokkos::deep_copy(points.material, material);
  Kokkos::deep_copy(points.porosity, porosity);
  Kokkos::deep_copy(points.saturation, saturation);
  Kokkos::deep_copy(points.conductivity, conductivity);
}

/// The nodes of the elements holding `points` (what the transfer kernels work on).
ActiveNodes activeNodesOf(const Mesh& mesh, const MaterialPoints& points) {
  ActiveNodes active(mesh.numNodes());
  active.rebuild(mesh, points);
  return active;
}

/// A rectangle of nx x ny cells with uniformly seeded, randomised points (randomise), their
/// shapes and an allocated grid.
struct RandomScene {
  Mesh mesh;
  MaterialPoints points;
  PointShapes shapes;
  GridFields grid;
};

RandomScene randomScene(int nx, int ny, Real width, Real height, ElementType type, unsigned seed) {
  RandomScene scene;
  scene.mesh = test::rectangleMesh(nx, ny, width, height, type);
  scene.points = test::seedUniform(scene.mesh);
  randomise(scene.points, seed);
  evaluatePointShapes(scene.mesh, scene.points, scene.shapes);
  scene.grid.allocate(scene.mesh.numNodes());
  return scene;
}

class TransferOnShape : public ::testing::TestWithParam<ElementType> {};

TEST_P(TransferOnShape, P2GConservesMassAndMomentumExactly) {
  auto [mesh, points, shapes, grid] = randomScene(3, 4, 1.5, 2.0, GetParam(), 7);
  NodeRecords records;
  mapPointsToGrid(points, shapes, liquidFlags(), 9.81, TransferSettings{},
                  activeNodesOf(mesh, points), records, grid);

  // Sums over points (host)...
  const auto ms = hostCopy(points.mass_solid), ml = hostCopy(points.mass_liquid);
  const auto rho = hostCopy(points.density_liquid), V = hostCopy(points.volume);
  const auto vs = hostCopy(points.velocity_solid), vl = hostCopy(points.velocity_liquid);
  Real m_s = 0, m_l = 0, m_t = 0, p_s[2] = {0, 0}, p_l[2] = {0, 0};
  for (int p = 0; p < points.count; ++p) {
    m_s += ms(p);
    m_l += ml(p);
    m_t += rho(p) * V(p);
    for (int d = 0; d < kDim; ++d) {
      p_s[d] += ms(p) * vs(p, d);
      p_l[d] += rho(p) * V(p) * vl(p, d);
    }
  }
  // ...equal the sums over nodes, since sum_a N_a = 1 (partition of unity).
  const auto gms = hostCopy(grid.mass_solid_i), gml = hostCopy(grid.mass_liquid_i);
  const auto gmt = hostCopy(grid.mass_liquid_intrinsic_i);
  const auto gps = hostCopy(grid.momentum_solid_i), gpl = hostCopy(grid.momentum_liquid_i);
  Real n_s = 0, n_l = 0, n_t = 0, q_s[2] = {0, 0}, q_l[2] = {0, 0};
  for (int i = 0; i < mesh.numNodes(); ++i) {
    n_s += gms(i);
    n_l += gml(i);
    n_t += gmt(i);
    for (int d = 0; d < kDim; ++d) {
      q_s[d] += gps(i, d);
      q_l[d] += gpl(i, d);
    }
  }
  EXPECT_NEAR(n_s, m_s, 1e-13 * m_s);
  EXPECT_NEAR(n_l, m_l, 1e-13 * m_l);
  EXPECT_NEAR(n_t, m_t, 1e-13 * m_t);
  for (int d = 0; d < kDim; ++d) {
    EXPECT_NEAR(q_s[d], p_s[d], 1e-12 * m_s);
    EXPECT_NEAR(q_l[d], p_l[d], 1e-12 * m_t);
  }
}

TEST_P(TransferOnShape, G2PReproducesLinearVelocityFieldAndItsGradient) {
  Mesh mesh = test::rectangleMesh(3, 3, 3.0, 3.0, GetParam());
  {  // distort the interior nodes: the field must still be reproduced exactly
    auto X = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), mesh.coordinates);
    X(5, 0) += 0.2, X(5, 1) -= 0.15, X(10, 0) -= 0.1, X(10, 1) += 0.2;
    Kokkos::deep_copy(mesh.coordinates, X);
  }
  MaterialPoints points = test::seedUniform(mesh);
  randomise(points, 3);
  PointShapes shapes;
  evaluatePointShapes(mesh, points, shapes);
  GridFields grid;
  grid.allocate(mesh.numNodes());

  // v(x) = A x + b at every node.
  const Real A[2][2] = {{0.3, -0.7}, {1.1, 0.25}}, b[2] = {0.5, -2.0};
  const auto X = hostCopy(mesh.coordinates);
  auto vs = Kokkos::create_mirror_view(grid.velocity_solid_i);
  for (int i = 0; i < mesh.numNodes(); ++i)
    for (int d = 0; d < kDim; ++d) vs(i, d) = A[d][0] * X(i, 0) + A[d][1] * X(i, 1) + b[d];
  Kokkos::deep_copy(grid.velocity_solid_i, vs);
  Kokkos::deep_copy(grid.velocity_liquid_i, vs);  // no relative flow

  const Real dt = 0.01;
  PointRates rates;
  NodeRecords records;
  interpolateVelocityGradients(points, shapes, liquidFlags(), activeNodesOf(mesh, points), grid,
                               records, dt, rates);
  const auto x = hostCopy(points.position);
  const auto du = hostCopy(rates.displacement_increment_p);
  const auto de = hostCopy(rates.strain_increment_p);
  const auto div = hostCopy(rates.liquid_divergence_increment_p);
  const auto mat = hostCopy(points.material);
  for (int p = 0; p < points.count; ++p) {
    for (int d = 0; d < kDim; ++d)
      EXPECT_NEAR(du(p, d), dt * (A[d][0] * x(p, 0) + A[d][1] * x(p, 1) + b[d]), 1e-14);
    EXPECT_NEAR(de(p, XX), dt * A[0][0], 1e-14);
    EXPECT_NEAR(de(p, YY), dt * A[1][1], 1e-14);
    EXPECT_NEAR(de(p, ZZ), 0, 1e-14);
    EXPECT_NEAR(de(p, XY), dt * 0.5 * (A[0][1] + A[1][0]), 1e-14);
    if (mat(p) == 0) {
      EXPECT_NEAR(div(p), dt * (A[0][0] + A[1][1]), 1e-14);
    }
  }
}

TEST_P(TransferOnShape, UniformStressAndPressureGiveNoForceAtInteriorNodes) {
  // A uniform stress field has zero divergence: the internal force at a node whose support
  // is full of points integrates exactly to zero (points at these positions integrate the
  // linear/bilinear shape-function gradients exactly); over all nodes the forces sum to 0.
  const Mesh mesh = test::rectangleMesh(4, 4, 2.0, 2.0, GetParam());
  MaterialPoints points = test::seedUniform(mesh);
  randomise(points, 5);
  Kokkos::deep_copy(points.material, 0);
  Kokkos::deep_copy(points.saturation, 1.0);
  Kokkos::deep_copy(points.pressure_liquid, 3e4);
  auto stress = Kokkos::create_mirror_view(points.stress_effective);
  for (int p = 0; p < points.count; ++p)
    stress(p, XX) = -1e4, stress(p, YY) = -2e4, stress(p, ZZ) = -1e4, stress(p, XY) = 5e3;
  Kokkos::deep_copy(points.stress_effective, stress);
  PointShapes shapes;
  evaluatePointShapes(mesh, points, shapes);
  GridFields grid;
  grid.allocate(mesh.numNodes());
  NodeRecords records;
  mapPointsToGrid(points, shapes, liquidFlags(), 0.0, TransferSettings{},
                  activeNodesOf(mesh, points), records, grid);
  const auto fm = hostCopy(grid.force_mixture_i), fl = hostCopy(grid.force_liquid_i);
  Real sum[4] = {0, 0, 0, 0};
  for (int i = 0; i < mesh.numNodes(); ++i) {
    for (int d = 0; d < kDim; ++d) sum[d] += fm(i, d), sum[2 + d] += fl(i, d);
    const int ix = i % 5, iy = i / 5;
    if (ix == 0 || ix == 4 || iy == 0 || iy == 4) continue;
    for (int d = 0; d < kDim; ++d) {
      EXPECT_NEAR(fm(i, d), 0, 1e-9) << "node " << i;
      EXPECT_NEAR(fl(i, d), 0, 1e-9) << "node " << i;
    }
  }
  for (const Real s : sum) EXPECT_NEAR(s, 0, 1e-8);
  // A boundary node does feel the stress: top-right corner of the quad mesh gets
  // -sigma . n over its share of the boundary (hand value for Quad4: the corner's support is
  // one element of size 0.5 x 0.5; f_x = -(sxx - p)*0.25 - sxy*0.25 with the total
  // sxx = -1e4 - 3e4 = -4e4: f_x = 1e4 - 1.25e3 = 8.75e3).
  if (GetParam() == ElementType::Quad4) {
    EXPECT_NEAR(fm(24, 0), 8750.0, 1e-8);
  }
}

/// Random nodal velocities and accelerations of both phases.
void randomiseGrid(GridFields& grid, int nodes, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<Real> u(-1, 1);
  for (auto field : {grid.velocity_solid_i, grid.velocity_liquid_i, grid.acceleration_solid_i,
                     grid.acceleration_liquid_i}) {
    auto host = Kokkos::create_mirror_view(field);
    for (int i = 0; i < nodes; ++i)
      for (int d = 0; d < kDim; ++d) host(i, d) = u(rng);
    Kokkos::deep_copy(field, host);
  }
}

TEST_P(TransferOnShape, VelocityBlendIsFlipAtZeroAndTakesTheGridVelocitiesAtOne) {
  auto [mesh, points, shapes, grid] = randomScene(3, 2, 1.5, 1.0, GetParam(), 11);
  randomiseGrid(grid, mesh.numNodes(), 12);
  ActiveNodes active(mesh.numNodes());
  active.rebuild(mesh, points);
  const Real dt = 0.01;
  const auto vs0 = hostCopy(points.velocity_solid), vl0 = hostCopy(points.velocity_liquid);
  const auto shape = hostCopy(shapes.stored_p);
  const auto mat = hostCopy(points.material);
  const auto gvs = hostCopy(grid.velocity_solid_i), gvl = hostCopy(grid.velocity_liquid_i);
  const auto gas = hostCopy(grid.acceleration_solid_i);
  const auto gal = hostCopy(grid.acceleration_liquid_i);
  const int per = GetParam() == ElementType::Quad4 ? 4 : 3;
  auto interpolate = [&](const auto& field, int p, int d) {
    Real sum = 0;
    for (int a = 0; a < per; ++a) sum += shape(p).value[a] * field(shape(p).node[a], d);
    return sum;
  };
  struct Case {
    VelocityBlend blend;
    const char* name;
  };
  for (const Case& c : {Case{{0, 0}, "FLIP"}, Case{{1, 1}, "PIC"}, Case{{0, 1}, "relative"},
                        Case{{0.3, 0.6}, "blend"}}) {
    Kokkos::deep_copy(points.velocity_solid, vs0);
    Kokkos::deep_copy(points.velocity_liquid, vl0);
    NodeRecords records;
    updatePointVelocitiesAndMapMomenta(shapes, liquidFlags(), active, dt,
                                       TransferSettings{TransferScheme::Flip, c.blend, {}}, points,
                                       records, grid);
    const auto vs = hostCopy(points.velocity_solid), vl = hostCopy(points.velocity_liquid);
    for (int p = 0; p < points.count; ++p)
      for (int d = 0; d < kDim; ++d) {
        // hand formulas of the VelocityBlend comment
        const Real as = interpolate(gas, p, d), al = interpolate(gal, p, d);
        const Real solid_flip = vs0(p, d) + dt * as;
        const Real solid_pic = interpolate(gvs, p, d) + dt * as;
        const Real solid = (1 - c.blend.solid) * solid_flip + c.blend.solid * solid_pic;
        EXPECT_NEAR(vs(p, d), solid, 1e-14) << c.name << " point " << p;
        if (mat(p) != 0) continue;
        const Real liquid_flip = vl0(p, d) + dt * al;
        const Real liquid_relative =
            solid + interpolate(gvl, p, d) - interpolate(gvs, p, d) + dt * (al - as);
        EXPECT_NEAR(vl(p, d), (1 - c.blend.liquid) * liquid_flip + c.blend.liquid * liquid_relative,
                    1e-14)
            << c.name << " point " << p;
        if (c.blend.solid == 1 && c.blend.liquid == 1) {  // both PIC: sum N (v_L,i + dt a_L,i)
          EXPECT_NEAR(vl(p, d), interpolate(gvl, p, d) + dt * al, 1e-14);
        }
      }
  }
}

/// Solves the dense system A x = b in place (Gaussian elimination, partial pivoting).
std::vector<Real> solveDense(std::vector<std::vector<Real>> A, std::vector<Real> b) {
  const int n = static_cast<int>(b.size());
  for (int k = 0; k < n; ++k) {
    int pivot = k;
    for (int r = k + 1; r < n; ++r)
      if (std::abs(A[r][k]) > std::abs(A[pivot][k])) pivot = r;
    std::swap(A[k], A[pivot]);
    std::swap(b[k], b[pivot]);
    for (int r = k + 1; r < n; ++r) {
      const Real f = A[r][k] / A[k][k];
      for (int c = k; c < n; ++c) A[r][c] -= f * A[k][c];
      b[r] -= f * b[k];
    }
  }
  std::vector<Real> x(n);
  for (int k = n - 1; k >= 0; --k) {
    Real sum = b[k];
    for (int c = k + 1; c < n; ++c) sum -= A[k][c] * x[c];
    x[k] = sum / A[k][k];
  }
  return x;
}

TEST_P(TransferOnShape, PicShareRemovesTheVelocityNoiseTheGridCannotSeeAndKeepsMomentum) {
  // Noise the grid cannot see: point velocities whose P2G momenta are zero at every node
  // (there are more points than nodes). Built from random velocities by removing their
  // grid-representable part (the mass-weighted projection onto fields sum N v_i), plus a
  // uniform velocity u. Without forces FLIP keeps the noise for ever; the PIC share alpha
  // removes exactly a fraction alpha of it per step (its PIC velocity is 0), and keeps u and
  // the momentum (sum_p m_p sum_i N_ip v_i = sum_i m_i v_i = sum_p m_p v_p).
  auto [mesh, points, shapes, grid] = randomScene(4, 3, 2.0, 1.5, GetParam(), 21);
  Kokkos::deep_copy(points.material, 1);  // dry: the solid phase alone
  ActiveNodes active(mesh.numNodes());
  active.rebuild(mesh, points);
  const int per = GetParam() == ElementType::Quad4 ? 4 : 3, nodes = mesh.numNodes();
  const auto shape = hostCopy(shapes.stored_p);
  const auto ms = hostCopy(points.mass_solid);
  auto v = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), points.velocity_solid);
  std::vector<std::vector<Real>> mass(nodes, std::vector<Real>(nodes, 0.0));  // consistent
  for (int p = 0; p < points.count; ++p)
    for (int a = 0; a < per; ++a)
      for (int b = 0; b < per; ++b)
        mass[shape(p).node[a]][shape(p).node[b]] += ms(p) * shape(p).value[a] * shape(p).value[b];
  const Real u[kDim] = {0.3, -0.2};
  for (int d = 0; d < kDim; ++d) {
    std::vector<Real> momentum(nodes, 0.0);
    for (int p = 0; p < points.count; ++p)
      for (int a = 0; a < per; ++a)
        momentum[shape(p).node[a]] += shape(p).value[a] * ms(p) * v(p, d);
    const std::vector<Real> field = solveDense(mass, momentum);
    for (int p = 0; p < points.count; ++p) {
      for (int a = 0; a < per; ++a) v(p, d) -= shape(p).value[a] * field[shape(p).node[a]];
      v(p, d) += u[d];
    }
  }
  Kokkos::deep_copy(points.velocity_solid, v);
  auto noise = [&] {  // mass-weighted norm of v - u, and the momentum
    const auto now = hostCopy(points.velocity_solid);
    Real sum = 0;
    for (int p = 0; p < points.count; ++p)
      for (int d = 0; d < kDim; ++d) sum += ms(p) * (now(p, d) - u[d]) * (now(p, d) - u[d]);
    return std::sqrt(sum);
  };
  auto momentum = [&](int d) {
    const auto now = hostCopy(points.velocity_solid);
    Real sum = 0;
    for (int p = 0; p < points.count; ++p) sum += ms(p) * now(p, d);
    return sum;
  };
  NodeRecords records;
  auto run = [&](VelocityBlend blend, int steps) {
    for (int n = 0; n < steps; ++n) {
      grid.zero(active);
      mapPointsToGrid(points, shapes, liquidFlags(), 0.0, TransferSettings{}, active, records,
                      grid);
      computeNodalVelocities(active, grid);
      Kokkos::deep_copy(grid.acceleration_solid_i, 0.0);
      updatePointVelocitiesAndMapMomenta(shapes, liquidFlags(), active, 1e-3,
                                         TransferSettings{TransferScheme::Flip, blend, {}}, points,
                                         records, grid);
    }
  };
  const Real noise0 = noise(), momentum0[kDim] = {momentum(0), momentum(1)};
  ASSERT_GT(noise0, 0.1);
  run({0, 0}, 100);
  EXPECT_NEAR(noise(), noise0, 1e-12 * noise0);  // FLIP without forces: nothing changes
  const Real alpha = 0.05;
  run({alpha, 0}, 100);
  EXPECT_NEAR(noise(), std::pow(1 - alpha, 100) * noise0, 1e-10 * noise0);
  for (int d = 0; d < kDim; ++d) EXPECT_NEAR(momentum(d), momentum0[d], 1e-12);
}

TEST_P(TransferOnShape, CompensatedP2GDoesNotDependOnThePointOrder) {
  // Reproducible sums: the P2G of the points in reverse order gives the same nodal sums bit
  // for bit once folded, and the plain P2G's to round-off.
  auto [mesh, points, shapes, grid] = randomScene(3, 4, 1.5, 2.0, GetParam(), 11);
  GridFields reversed_grid, plain;
  LowParts<GridFields> lo, reversed_lo;
  for (GridFields* g : {&reversed_grid, &plain}) g->allocate(mesh.numNodes());
  for (int k = 0; k < kLowParts; ++k) {
    lo[k].allocate(mesh.numNodes());
    reversed_lo[k].allocate(mesh.numNodes());
  }
  ActiveNodes active(mesh.numNodes());
  active.rebuild(mesh, points);
  NodeRecords records;
  mapPointsToGrid(points, shapes, liquidFlags(), 9.81, TransferSettings{}, active, records, grid,
                  &lo);
  foldCompensatedGridSums(active, grid, lo);
  mapPointsToGrid(points, shapes, liquidFlags(), 9.81, TransferSettings{}, active, records, plain);

  MaterialPoints reversed;  // the same points, last first
  reversed.allocate(points.count);
  forEachPointField(points, [&](const char* name, const auto& field) {
    forEachPointField(reversed, [&](const char* other, auto& target) {
      if constexpr (std::is_same_v<std::decay_t<decltype(field)>, std::decay_t<decltype(target)>>)
        if (std::string(name) == other)
          for (int p = 0; p < points.count; ++p) {
            if constexpr (std::decay_t<decltype(field)>::rank == 1)
              target(points.count - 1 - p) = field(p);
            else
              for (std::size_t c = 0; c < field.extent(1); ++c)
                target(points.count - 1 - p, c) = field(p, c);
          }
    });
  });
  PointShapes reversed_shapes;
  evaluatePointShapes(mesh, reversed, reversed_shapes);
  mapPointsToGrid(reversed, reversed_shapes, liquidFlags(), 9.81, TransferSettings{}, active,
                  records, reversed_grid, &reversed_lo);
  foldCompensatedGridSums(active, reversed_grid, reversed_lo);

  const auto a = hostCopy(grid.force_mixture_i), b = hostCopy(reversed_grid.force_mixture_i);
  const auto c = hostCopy(plain.force_mixture_i);
  const auto ma = hostCopy(grid.mass_liquid_i), mb = hostCopy(reversed_grid.mass_liquid_i);
  Real scale = 0;
  for (int i = 0; i < mesh.numNodes(); ++i) scale = std::max(scale, std::abs(c(i, 1)));
  for (int i = 0; i < mesh.numNodes(); ++i) {
    EXPECT_EQ(ma(i), mb(i)) << i;
    for (int d = 0; d < kDim; ++d) {
      EXPECT_EQ(a(i, d), b(i, d)) << i << " " << d;
      EXPECT_NEAR(a(i, d), c(i, d), 1e-14 * scale) << i << " " << d;
    }
  }
}

/// The points of `points` in the order `from` gives (from[r] = the point at r), where -1 puts
/// a point outside the mesh (element -1, the fields of point 0).
MaterialPoints rearranged(const MaterialPoints& points, const std::vector<int>& from) {
  MaterialPoints out;
  out.allocate(static_cast<int>(from.size()));
  forEachPointField(points, [&](const char* name, const auto& field) {
    forEachPointField(out, [&](const char* other, auto& target) {
      if constexpr (std::is_same_v<std::decay_t<decltype(field)>, std::decay_t<decltype(target)>>)
        if (std::string(name) == other)
          for (std::size_t r = 0; r < from.size(); ++r) {
            const int q = from[r] < 0 ? 0 : from[r];
            if constexpr (std::decay_t<decltype(field)>::rank == 1)
              target(r) = field(q);
            else
              for (std::size_t c = 0; c < field.extent(1); ++c) target(r, c) = field(q, c);
          }
    });
  });
  for (std::size_t r = 0; r < from.size(); ++r)
    if (from[r] < 0) out.element(r) = -1;
  return out;
}

/// The results of the three transfer kernels on one set of points.
struct TransferRun {
  MaterialPoints points;
  PointShapes shapes;
  GridFields grid;
  LowParts<GridFields> lo;
  PointRates rates;
};

/// The P2G, the velocity update with its remap and the strain increments on r.points with
/// r.shapes (the grid's velocities and accelerations in between as a solve would leave them,
/// randomiseGrid), with compensated sums or the packed ones.
void runTransfers(const Mesh& mesh, TransferRun& r, bool compensated) {
  r.grid.allocate(mesh.numNodes());
  for (int k = 0; k < kLowParts; ++k) r.lo[k].allocate(mesh.numNodes());
  const ActiveNodes active = activeNodesOf(mesh, r.points);
  NodeRecords records;
  const LowParts<GridFields>* compensation = compensated ? &r.lo : nullptr;
  mapPointsToGrid(r.points, r.shapes, liquidFlags(), 9.81, TransferSettings{}, active, records,
                  r.grid, compensation);
  if (compensated) foldCompensatedGridSums(active, r.grid, r.lo);  // the remap needs lo = 0
  randomiseGrid(r.grid, mesh.numNodes(), 5);
  updatePointVelocitiesAndMapMomenta(r.shapes, liquidFlags(), active, 1e-3,
                                     TransferSettings{TransferScheme::Flip, {0.25, 0.5}, {}},
                                     r.points, records, r.grid, compensation);
  interpolateVelocityGradients(r.points, r.shapes, liquidFlags(), active, r.grid, records, 1e-3,
                               r.rates);
}

/// Expects the nodal sums of a and b, and the results of a's point p and b's point
/// in_b[p], to be the same bits.
void expectSameBits(const TransferRun& a, const TransferRun& b, int nodes,
                    const std::vector<int>& in_b) {
  for (auto field :
       {&GridFields::mass_solid_i, &GridFields::mass_liquid_i, &GridFields::mass_liquid_intrinsic_i,
        &GridFields::drag_i, &GridFields::volume_liquid_i}) {
    const auto x = hostCopy(a.grid.*field), y = hostCopy(b.grid.*field);
    for (int i = 0; i < nodes; ++i) EXPECT_EQ(x(i), y(i)) << i;
  }
  for (auto field : {&GridFields::momentum_solid_i, &GridFields::momentum_liquid_i,
                     &GridFields::force_mixture_i, &GridFields::force_liquid_i}) {
    const auto x = hostCopy(a.grid.*field), y = hostCopy(b.grid.*field);
    for (int i = 0; i < nodes; ++i)
      for (int d = 0; d < kDim; ++d) EXPECT_EQ(x(i, d), y(i, d)) << i << " " << d;
  }
  for (int p = 0; p < a.points.count; ++p) {
    const int r = in_b[p];
    for (int d = 0; d < kDim; ++d) {
      EXPECT_EQ(a.points.velocity_solid(p, d), b.points.velocity_solid(r, d)) << p;
      EXPECT_EQ(a.points.velocity_liquid(p, d), b.points.velocity_liquid(r, d)) << p;
      EXPECT_EQ(a.rates.displacement_increment_p(p, d), b.rates.displacement_increment_p(r, d));
    }
    for (int c = 0; c < kStressComponents; ++c)
      EXPECT_EQ(a.rates.strain_increment_p(p, c), b.rates.strain_increment_p(r, c)) << p;
    EXPECT_EQ(a.rates.spin_increment_p(p), b.rates.spin_increment_p(r)) << p;
    EXPECT_EQ(a.rates.liquid_divergence_increment_p(p), b.rates.liquid_divergence_increment_p(r));
    EXPECT_EQ(a.rates.content_flux_divergence_increment_p(p),
              b.rates.content_flux_divergence_increment_p(r));
  }
}

TEST_P(TransferOnShape, LanesGiveTheOnePointResultsBitForBit) {
  // The kernels take kLanes points at once where they can (all located, all wet or all dry)
  // and one at a time otherwise; both must give the same bits. Run A: every fourth point
  // onwards dry in blocks of kLanes, so every chunk takes the lanes. Run B: the same points
  // in the same order with a point outside the mesh after every third, so no chunk does.
  auto scene = randomScene(5, 4, 2.5, 2.0, GetParam(), 23);
  const Mesh& mesh = scene.mesh;
  MaterialPoints& points = scene.points;
  for (int p = 0; p < points.count; ++p) points.material(p) = (p / kLanes) % 3 == 2 ? 1 : 0;
  std::vector<int> same(points.count), spread, in_spread;
  for (int p = 0; p < points.count; ++p) {
    same[p] = p;
    in_spread.push_back(static_cast<int>(spread.size()));
    spread.push_back(p);
    if (p % 3 == 2) spread.push_back(-1);
  }
  auto run = [&](const std::vector<int>& from, bool compensated) {
    TransferRun r;
    r.points = rearranged(points, from);
    evaluatePointShapes(mesh, r.points, r.shapes);
    runTransfers(mesh, r, compensated);
    return r;
  };
  for (const bool compensated : {false, true}) {
    const TransferRun a = run(same, compensated), b = run(spread, compensated);
    expectSameBits(a, b, mesh.numNodes(), in_spread);
    // Something happened: the velocities changed, but not a dry point's liquid one.
    EXPECT_NE(a.points.velocity_solid(0, 0), points.velocity_solid(0, 0));
    EXPECT_EQ(a.points.velocity_liquid(2 * kLanes, 0), points.velocity_liquid(2 * kLanes, 0));
  }
}

TEST_P(TransferOnShape, ShapesComputedInAffineElementsGiveTheRecordBitsAndNoRecordIsRead) {
  // A chunk of kLanes points in one affine element, relocated with AffineElementMaps, has no
  // records (PointShapes::computed_c): the kernels compute N and dN/dx from the points'
  // local coordinates and the element's J^-1, four at once (AffineShapesAt) or, in a chunk
  // of wet and dry points, one by one (PointShapes::of). Run A: the maps, with every record
  // NaN before the relocation, so that writing or reading one shows; run B: records holding
  // what PointShapes::of gives, read (no maps). The bits must be the same. Every chunk lies in
  // one element: the Quad4 points as seeded (four an element), the Tri3 ones with an
  // element's last point repeated.
  auto scene = randomScene(5, 4, 2.5, 2.0, GetParam(), 29);
  const Mesh& mesh = scene.mesh;
  const int per = mesh.type == ElementType::Quad4 ? 4 : 3;
  std::vector<int> from, same;
  for (int e = 0; e < mesh.numElements(); ++e)
    for (int k = 0; k < kLanes; ++k) {
      same.push_back(static_cast<int>(from.size()));
      from.push_back(e * per + std::min(k, per - 1));
    }
  const PointLocator locator(mesh);
  const AffineElementMaps maps(mesh);
  auto run = [&](bool computed, bool compensated) {
    TransferRun r;
    r.points = rearranged(scene.points, from);
    // Dry chunks, wet chunks, and chunks of both (point by point).
    for (int p = 0; p < r.points.count; ++p)
      r.points.material(p) = (p / kLanes) % 3 == 2 || ((p / kLanes) % 5 == 1 && p % 2 == 0);
    r.shapes.allocate(r.points.count);
    for (int p = 0; p < r.points.count; ++p)
      for (int a = 0; a < kMaxElementNodes; ++a) {
        PointShape& shape = r.shapes.stored_p(p);
        shape.value[a] = shape.gradient[a][0] = shape.gradient[a][1] = std::nan("");
      }
    const RelocationCounts found =
        relocateAndEvaluateShapes(mesh, locator, maps, r.points, r.shapes);
    EXPECT_EQ(found.lost, 0);
    EXPECT_TRUE(r.shapes.fromAffineMaps());
    for (int p = 0; p < r.points.count; ++p) {
      EXPECT_EQ(r.points.element(p), r.points.element(p - p % kLanes)) << p;
      EXPECT_TRUE(std::isnan(r.shapes.stored_p(p).value[0])) << "record written: " << p;
      EXPECT_EQ(r.shapes.computed_c(p / kLanes), 1) << p;
    }
    if (!computed) {  // every point's record as PointShapes::of computes it, read
      Kokkos::deep_copy(r.shapes.stored_p, everyPointShape(r.shapes, r.points));
      Kokkos::deep_copy(r.shapes.computed_c, 0);
      r.shapes.affine_e = {};
      r.shapes.inverse_jacobian_e = {};
      r.shapes.connectivity = {};
    }
    runTransfers(mesh, r, compensated);
    return r;
  };
  for (const bool compensated : {false, true}) {
    const TransferRun a = run(true, compensated), b = run(false, compensated);
    expectSameBits(a, b, mesh.numNodes(), same);
    EXPECT_TRUE(std::isfinite(a.rates.strain_increment_p(0, XX)));
    EXPECT_NE(a.rates.strain_increment_p(0, XX), 0.0);
  }
}

INSTANTIATE_TEST_SUITE_P(Shapes, TransferOnShape,
                         ::testing::Values(ElementType::Quad4, ElementType::Tri3));

TEST(ActiveNodes, ListsOnlyNodesOfOccupiedElements) {
  const Mesh mesh = test::rectangleMesh(3, 1, 3.0, 1.0, ElementType::Quad4);
  MaterialPoints points = test::seedUniform(mesh);
  // Move all points of element 2 out of the mesh and those of element 1 into element 0.
  auto element = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), points.element);
  for (int p = 0; p < points.count; ++p) element(p) = element(p) == 2 ? -1 : 0;
  Kokkos::deep_copy(points.element, element);
  ActiveNodes active(mesh.numNodes());
  active.rebuild(mesh, points);
  // Element 0 has nodes 0, 1 (bottom) and 5, 4 (top) in the 4 x 2 node grid.
  ASSERT_EQ(active.count(), 4);
  const auto nodes = hostCopy(active.nodes());
  EXPECT_EQ(nodes(0), 0);
  EXPECT_EQ(nodes(1), 1);
  EXPECT_EQ(nodes(2), 4);
  EXPECT_EQ(nodes(3), 5);
  // Rebuilding after the points spread out lists the new nodes (flags were cleared).
  for (int p = 0; p < points.count; ++p) element(p) = 1;
  Kokkos::deep_copy(points.element, element);
  active.rebuild(mesh, points);
  ASSERT_EQ(active.count(), 4);
  const auto again = hostCopy(active.nodes());
  EXPECT_EQ(again(0), 1);
  EXPECT_EQ(again(3), 6);
}

TEST(GridFields, ZeroClearsOnlyListedNodes) {
  const Mesh mesh = test::rectangleMesh(2, 1, 2.0, 1.0, ElementType::Quad4);
  GridFields grid;
  grid.allocate(mesh.numNodes());
  Kokkos::deep_copy(grid.mass_solid_i, 1.0);
  Kokkos::deep_copy(grid.velocity_liquid_i, 2.0);
  MaterialPoints points = test::seedUniform(mesh);
  auto element = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), points.element);
  for (int p = 0; p < points.count; ++p) element(p) = 0;
  Kokkos::deep_copy(points.element, element);
  ActiveNodes active(mesh.numNodes());
  active.rebuild(mesh, points);
  grid.zero(active);
  const auto m = hostCopy(grid.mass_solid_i);
  const auto v = hostCopy(grid.velocity_liquid_i);
  // element 0 = nodes 0, 1, 4, 3; nodes 2 and 5 untouched
  for (const int i : {0, 1, 3, 4}) {
    EXPECT_EQ(m(i), 0.0);
    EXPECT_EQ(v(i, 1), 0.0);
  }
  for (const int i : {2, 5}) {
    EXPECT_EQ(m(i), 1.0);
    EXPECT_EQ(v(i, 0), 2.0);
  }
}

TEST(NodeRecords, SumsGoToTheirGridFieldsAtListedNodesAndAreZeroedThere) {
  const Mesh mesh = test::rectangleMesh(2, 1, 2.0, 1.0, ElementType::Quad4);
  MaterialPoints points = test::seedUniform(mesh);
  Kokkos::deep_copy(points.element, 0);  // element 0: nodes 0, 1, 3, 4
  const ActiveNodes active = activeNodesOf(mesh, points);
  GridFields grid;
  grid.allocate(mesh.numNodes());
  Kokkos::deep_copy(grid.mass_solid_i, 0.5);
  NodeRecords records;
  records.allocate(mesh.numNodes());
  auto sums = Kokkos::create_mirror_view(records.sums_i);
  for (int i = 0; i < mesh.numNodes(); ++i)
    for (int slot = 0; slot < kNodeSumRow; ++slot) sums(i, slot) = 100 * i + slot + 1;
  Kokkos::deep_copy(records.sums_i, sums);
  addNodeSumsToGrid(active, records, grid);
  const auto ms = hostCopy(grid.mass_solid_i), drag = hostCopy(grid.drag_i);
  const auto ps = hostCopy(grid.momentum_solid_i), fl = hostCopy(grid.force_liquid_i);
  const auto after = hostCopy(records.sums_i);
  for (const int i : {0, 1, 3, 4}) {
    EXPECT_EQ(ms(i), 0.5 + 100 * i + kSumMassSolid + 1);  // added to what was there
    EXPECT_EQ(drag(i), 100 * i + kSumDrag + 1);
    EXPECT_EQ(ps(i, 1), 100 * i + kSumMomentumSolid + 2);
    EXPECT_EQ(fl(i, 0), 100 * i + kSumForceLiquid + 1);
    for (int slot = 0; slot < kSumSlotCount; ++slot) EXPECT_EQ(after(i, slot), 0.0);
  }
  for (const int i : {2, 5}) {  // not listed: neither added nor cleared
    EXPECT_EQ(ms(i), 0.5);
    EXPECT_EQ(after(i, kSumMassSolid), 100 * i + 1);
  }

  // G2P rows: each slot holds its field's value.
  auto vs = Kokkos::create_mirror_view(grid.velocity_solid_i);
  auto al = Kokkos::create_mirror_view(grid.acceleration_liquid_i);
  for (int i = 0; i < mesh.numNodes(); ++i) vs(i, 0) = i + 0.25, vs(i, 1) = -i, al(i, 1) = 7 * i;
  Kokkos::deep_copy(grid.velocity_solid_i, vs);
  Kokkos::deep_copy(grid.acceleration_liquid_i, al);
  Kokkos::deep_copy(grid.liquid_content_i, 990.0);
  readVelocityUpdateValues(active, grid, records);
  auto values = hostCopy(records.values_i);
  EXPECT_EQ(values(4, kReadVelocitySolid), 4.25);
  EXPECT_EQ(values(4, kReadVelocitySolid + 1), -4.0);
  EXPECT_EQ(values(3, kReadAccelerationLiquid + 1), 21.0);
  readStrainValues(active, grid, {}, records);
  values = hostCopy(records.values_i);
  EXPECT_EQ(values(1, kReadStrainVelocitySolid), 1.25);
  EXPECT_EQ(values(1, kReadStrainLiquidContent), 990.0);
  EXPECT_EQ(values(2, kReadStrainLiquidContent), 0.0);  // not listed
}

}  // namespace
}  // namespace argine
