#pragma once
// Tiny hand-built mesh and material points for the output tests.
#include <filesystem>
#include <string>
#include <vector>

#include "argine/mesh/Mesh.hpp"
#include "argine/points/MaterialPoints.hpp"

namespace argine::test {

/// Two unit quads side by side:  3---4---5
///                               | 0 | 1 |
///                               0---1---2
/// blocks "left" {0} and "right" {1}, node set "base" {0,1,2}, side set "bottom".
inline Mesh twoQuadMesh() {
  Mesh mesh;
  mesh.type = ElementType::Quad4;
  mesh.coordinates = Kokkos::View<Real* [kDim], MemSpace>("coordinates", 6);
  mesh.connectivity = Kokkos::View<int**, MemSpace>("connectivity", 2, 4);
  mesh.element_block = Kokkos::View<int*, MemSpace>("element_block", 2);
  auto x = Kokkos::create_mirror_view(mesh.coordinates);
  auto c = Kokkos::create_mirror_view(mesh.connectivity);
  auto b = Kokkos::create_mirror_view(mesh.element_block);
  const double xy[6][2] = {{0, 0}, {1, 0}, {2, 0}, {0, 1}, {1, 1}, {2, 1}};
  for (int n = 0; n < 6; ++n) x(n, 0) = xy[n][0], x(n, 1) = xy[n][1];
  const int conn[2][4] = {{0, 1, 4, 3}, {1, 2, 5, 4}};
  for (int e = 0; e < 2; ++e)
    for (int k = 0; k < 4; ++k) c(e, k) = conn[e][k];
  b(0) = 0;
  b(1) = 1;
  Kokkos::deep_copy(mesh.coordinates, x);
  Kokkos::deep_copy(mesh.connectivity, c);
  Kokkos::deep_copy(mesh.element_block, b);
  mesh.blocks = {{"left", 1, {0}}, {"right", 2, {1}}};
  mesh.node_sets = {{"base", 1, {0, 1, 2}}};
  mesh.side_sets = {{"bottom", 1, {0, 1}, {0, 0}}};
  return mesh;
}

/// One material point as the tests describe it (fields are set from these numbers).
struct PointSpec {
  int id;
  int material;
  double x, y;
};

/// Points with known fields, all derived from id i (so each can be checked after sorting):
/// velocity_solid = (i, -i), velocity_liquid = (2i, 3i), p_L = 1000 i - 3000,
/// S_L = 0.1 i, k = 1e-6 i, n = 0.3 + 0.01 i, sigma' = (-10i, -20i, -30i, 5i),
/// deviatoric = 0.01 i, plastic = 0.001 i, state = i % 3, V = 0.25 + i,
/// displacement = (0.5 i, -0.5 i).
inline MaterialPoints makePoints(const std::vector<PointSpec>& specs) {
  MaterialPoints points;
  points.allocate(static_cast<int>(specs.size()));
  auto id = Kokkos::create_mirror_view(points.id);
  auto material = Kokkos::create_mirror_view(points.material);
  auto position = Kokkos::create_mirror_view(points.position);
  auto displacement = Kokkos::create_mirror_view(points.displacement);
  auto vs = Kokkos::create_mirror_view(points.velocity_solid);
  auto vl = Kokkos::create_mirror_view(points.velocity_liquid);
  auto pl = Kokkos::create_mirror_view(points.pressure_liquid);
  auto sl = Kokkos::create_mirror_view(points.saturation);
  auto k = Kokkos::create_mirror_view(points.conductivity);
  auto n = Kokkos::create_mirror_view(points.porosity);
  auto sigma = Kokkos::create_mirror_view(points.stress_effective);
  auto dev = Kokkos::create_mirror_view(points.deviatoric_strain);
  auto plastic = Kokkos::create_mirror_view(points.plastic_strain);
  auto state = Kokkos::create_mirror_view(points.plastic_state);
  auto volume = Kokkos::create_mirror_view(points.volume);
  for (std::size_t p = 0; p < specs.size(); ++p) {
    const int i = specs[p].id;
    id(p) = i;
    material(p) = specs[p].material;
    position(p, 0) = specs[p].x;
    position(p, 1) = specs[p].y;
    displacement(p, 0) = 0.5 * i;
    displacement(p, 1) = -0.5 * i;
    vs(p, 0) = i;
    vs(p, 1) = -i;
    vl(p, 0) = 2.0 * i;
    vl(p, 1) = 3.0 * i;
    pl(p) = 1000.0 * i - 3000.0;
    sl(p) = 0.1 * i;
    k(p) = 1e-6 * i;
    n(p) = 0.3 + 0.01 * i;
    sigma(p, XX) = -10.0 * i;
    sigma(p, YY) = -20.0 * i;
    sigma(p, ZZ) = -30.0 * i;
    sigma(p, XY) = 5.0 * i;
    dev(p) = 0.01 * i;
    plastic(p) = 0.001 * i;
    state(p) = i % 3;
    volume(p) = 0.25 + i;
  }
  Kokkos::deep_copy(points.id, id);
  Kokkos::deep_copy(points.material, material);
  Kokkos::deep_copy(points.position, position);
  Kokkos::deep_copy(points.displacement, displacement);
  Kokkos::deep_copy(points.velocity_solid, vs);
  Kokkos::deep_copy(points.velocity_liquid, vl);
  Kokkos::deep_copy(points.pressure_liquid, pl);
  Kokkos::deep_copy(points.saturation, sl);
  Kokkos::deep_copy(points.conductivity, k);
  Kokkos::deep_copy(points.porosity, n);
  Kokkos::deep_copy(points.stress_effective, sigma);
  Kokkos::deep_copy(points.deviatoric_strain, dev);
  Kokkos::deep_copy(points.plastic_strain, plastic);
  Kokkos::deep_copy(points.plastic_state, state);
  Kokkos::deep_copy(points.volume, volume);
  return points;
}

/// A fresh, empty directory for one test under the build tree.
inline std::string freshDirectory(const std::string& name) {
  const auto dir = std::filesystem::path(ARGINE_BINARY_DIR) / "tests" / "output_files" / name;
  std::filesystem::remove_all(dir);
  return dir.string();
}

/// A nodal field view holding `values`.
inline Kokkos::View<const Real*, MemSpace> nodalValues(const std::vector<double>& values) {
  Kokkos::View<Real*, MemSpace> view("nodal", values.size());
  auto host = Kokkos::create_mirror_view(view);
  for (std::size_t i = 0; i < values.size(); ++i) host(i) = values[i];
  Kokkos::deep_copy(view, host);
  return view;
}

}  // namespace argine::test
