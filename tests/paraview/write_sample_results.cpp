// Writes small sample results with ResultsWriter for the ParaView check:
//   write_sample_results DIR  ->  DIR/sample_grid.e, DIR/sample_points.e (+ .e-s0002)
// A 4 x 2 grid of 1 m quads (blocks "foundation" below, "embankment" above), 2 x 2 points
// per element (32 points: material "clay" in the foundation, "sand" in the embankment), a
// water table at y = 1.5 m, and three steps (t = 0, 0.5, 1 s) in which the embankment
// points slide to the right. The points are given in another order at each step, as after
// a sort, to exercise the id mapping. At t = 1.5 s the 4 points of the top-right element are
// removed (as if they left the grid), which starts the restart file sample_points.e-s0002.
#include <algorithm>
#include <exception>
#include <iostream>
#include <vector>

#include "argine/output/ResultsWriter.hpp"

using namespace argine;

namespace {

constexpr int kColumns = 4;
constexpr int kRows = 2;
constexpr double kWaterTable = 1.5;   // m
constexpr double kUnitWeight = 9810;  // rho_L g (N/m^3)

Mesh sampleMesh() {
  Mesh mesh;
  mesh.type = ElementType::Quad4;
  const int num_nodes = (kColumns + 1) * (kRows + 1);
  mesh.coordinates = Kokkos::View<Real* [kDim], MemSpace>("coordinates", num_nodes);
  mesh.connectivity = Kokkos::View<int**, MemSpace>("connectivity", kColumns * kRows, 4);
  mesh.element_block = Kokkos::View<int*, MemSpace>("element_block", kColumns * kRows);
  auto x = Kokkos::create_mirror_view(mesh.coordinates);
  auto conn = Kokkos::create_mirror_view(mesh.connectivity);
  auto block = Kokkos::create_mirror_view(mesh.element_block);
  for (int j = 0; j <= kRows; ++j)
    for (int i = 0; i <= kColumns; ++i) {
      x(j * (kColumns + 1) + i, 0) = i;
      x(j * (kColumns + 1) + i, 1) = j;
    }
  mesh.blocks = {{"foundation", 1, {}}, {"embankment", 2, {}}};
  for (int j = 0; j < kRows; ++j)
    for (int i = 0; i < kColumns; ++i) {
      const int e = j * kColumns + i;
      const int n0 = j * (kColumns + 1) + i;
      conn(e, 0) = n0;
      conn(e, 1) = n0 + 1;
      conn(e, 2) = n0 + kColumns + 2;
      conn(e, 3) = n0 + kColumns + 1;
      block(e) = j;
      mesh.blocks[j].elements.push_back(e);
    }
  Kokkos::deep_copy(mesh.coordinates, x);
  Kokkos::deep_copy(mesh.connectivity, conn);
  Kokkos::deep_copy(mesh.element_block, block);
  std::vector<int> base;
  for (int i = 0; i <= kColumns; ++i) base.push_back(i);
  mesh.node_sets = {{"base", 1, base}};
  mesh.side_sets = {{"riverside", 1, {0, kColumns}, {3, 3}}};
  return mesh;
}

// Fills the points at time t; `order` gives which point id goes to each array slot.
void setPoints(MaterialPoints& points, double t, const std::vector<int>& order) {
  auto id = Kokkos::create_mirror_view(points.id);
  auto material = Kokkos::create_mirror_view(points.material);
  auto position = Kokkos::create_mirror_view(points.position);
  auto displacement = Kokkos::create_mirror_view(points.displacement);
  auto velocity = Kokkos::create_mirror_view(points.velocity_solid);
  auto pressure = Kokkos::create_mirror_view(points.pressure_liquid);
  auto saturation = Kokkos::create_mirror_view(points.saturation);
  auto stress = Kokkos::create_mirror_view(points.stress_effective);
  auto porosity = Kokkos::create_mirror_view(points.porosity);
  auto volume = Kokkos::create_mirror_view(points.volume);
  for (int slot = 0; slot < points.count; ++slot) {
    const int i = order[slot];  // id = creation index: element e = i / 4, corner c = i % 4
    const int e = i / 4, c = i % 4;
    const double x0 = e % kColumns + 0.25 + 0.5 * (c % 2);
    const double y0 = e / kColumns + 0.25 + 0.5 * (c / 2);
    const double slide = y0 > 1.0 ? 0.4 * t * (y0 - 1.0) : 0.0;  // embankment slides right
    id(slot) = i;
    material(slot) = y0 > 1.0 ? 1 : 0;
    position(slot, 0) = x0 + slide;
    position(slot, 1) = y0;
    displacement(slot, 0) = slide;
    velocity(slot, 0) = 0.4 * (y0 > 1.0 ? y0 - 1.0 : 0.0);
    pressure(slot) = kUnitWeight * (kWaterTable - y0);  // hydrostatic, suction above
    saturation(slot) = pressure(slot) >= 0 ? 1.0 : 0.8;
    stress(slot, XX) = stress(slot, ZZ) = -0.5 * 18000 * (2.0 - y0);
    stress(slot, YY) = -18000 * (2.0 - y0);
    porosity(slot) = 0.35;
    volume(slot) = 0.25;
  }
  Kokkos::deep_copy(points.id, id);
  Kokkos::deep_copy(points.material, material);
  Kokkos::deep_copy(points.position, position);
  Kokkos::deep_copy(points.displacement, displacement);
  Kokkos::deep_copy(points.velocity_solid, velocity);
  Kokkos::deep_copy(points.pressure_liquid, pressure);
  Kokkos::deep_copy(points.saturation, saturation);
  Kokkos::deep_copy(points.stress_effective, stress);
  Kokkos::deep_copy(points.porosity, porosity);
  Kokkos::deep_copy(points.volume, volume);
}

std::vector<NodalField> gridFields(const Mesh& mesh, double t) {
  auto x = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), mesh.coordinates);
  Kokkos::View<Real*, MemSpace> head("total_head", mesh.numNodes());
  Kokkos::View<Real*, MemSpace> pressure("pressure_liquid", mesh.numNodes());
  auto h = Kokkos::create_mirror_view(head);
  auto p = Kokkos::create_mirror_view(pressure);
  for (int n = 0; n < mesh.numNodes(); ++n) {
    h(n) = kWaterTable + 0.1 * t;
    p(n) = kUnitWeight * (h(n) - x(n, 1));
  }
  Kokkos::deep_copy(head, h);
  Kokkos::deep_copy(pressure, p);
  return {{"total_head", head}, {"pressure_liquid", pressure}};
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: write_sample_results OUTPUT_DIRECTORY\n";
    return 2;
  }
  Kokkos::ScopeGuard kokkos(argc, argv);
  try {
    const Mesh mesh = sampleMesh();
    const int num_points = kColumns * kRows * 4;
    std::vector<int> order(num_points);
    for (int i = 0; i < num_points; ++i) order[i] = i;
    MaterialPoints points;
    points.allocate(num_points);
    setPoints(points, 0.0, order);
    ResultsWriter writer(argv[1], "sample", mesh, {"clay", "sand"},
                         {"total_head", "pressure_liquid"}, points);
    for (double t : {0.0, 0.5, 1.0}) {
      std::reverse(order.begin(), order.end());  // another order each step, as after a sort
      setPoints(points, t, order);
      writer.write(t, points, gridFields(mesh, t));
    }
    const int remaining = num_points - 4;  // ids 28..31 = element 7, top right
    std::vector<int> kept(remaining);
    for (int i = 0; i < remaining; ++i) kept[i] = remaining - 1 - i;
    MaterialPoints fewer;
    fewer.allocate(remaining);
    setPoints(fewer, 1.5, kept);
    writer.write(1.5, fewer, gridFields(mesh, 1.5));
    std::cout << writer.gridPath() << "\n" << writer.pointsPath() << "\n";
  } catch (const std::exception& error) {
    std::cerr << "write_sample_results: " << error.what() << "\n";
    return 1;
  }
  return 0;
}
