#pragma once
// Hand-built meshes, points and materials for the transfer, boundary and physics tests
// (no dependency on the mesh generators or the seeding room).

#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "argine/input/Deck.hpp"
#include "argine/mesh/Mesh.hpp"
#include "argine/mesh/ShapeFunctions.hpp"
#include "argine/points/MaterialPoints.hpp"

namespace argine::test {

/// A structured nx x ny mesh of [x0, x0 + width] x [y0, y0 + height]. Quad4: one quad per
/// cell; Tri3: each cell split along its (lower-left, upper-right) diagonal. Node sets and
/// side sets "left", "right", "bottom", "top"; one block "soil".
inline Mesh rectangleMesh(int nx, int ny, Real width, Real height, ElementType type, Real x0 = 0,
                          Real y0 = 0) {
  Mesh mesh;
  mesh.type = type;
  const int nodes = (nx + 1) * (ny + 1);
  const int per = type == ElementType::Quad4 ? 4 : 3;
  const int elements = type == ElementType::Quad4 ? nx * ny : 2 * nx * ny;
  mesh.coordinates = Kokkos::View<Real* [kDim], MemSpace>("coordinates", nodes);
  mesh.connectivity = Kokkos::View<int**, MemSpace>("connectivity", elements, per);
  mesh.element_block = Kokkos::View<int*, MemSpace>("element_block", elements);
  auto X = Kokkos::create_mirror_view(mesh.coordinates);
  auto C = Kokkos::create_mirror_view(mesh.connectivity);
  auto node = [&](int i, int j) { return j * (nx + 1) + i; };
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) {
      X(node(i, j), 0) = x0 + width * i / nx;
      X(node(i, j), 1) = y0 + height * j / ny;
    }
  ElementBlock block{"soil", 1, {}};
  SideSet left{"left", 1, {}, {}}, right{"right", 2, {}, {}}, bottom{"bottom", 3, {}, {}},
      top{"top", 4, {}, {}};
  int e = 0;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int a = node(i, j), b = node(i + 1, j), c = node(i + 1, j + 1), d = node(i, j + 1);
      if (type == ElementType::Quad4) {
        C(e, 0) = a, C(e, 1) = b, C(e, 2) = c, C(e, 3) = d;
        // sides: 0 = a-b (bottom), 1 = b-c (right), 2 = c-d (top), 3 = d-a (left)
        if (j == 0) bottom.elements.push_back(e), bottom.sides.push_back(0);
        if (i == nx - 1) right.elements.push_back(e), right.sides.push_back(1);
        if (j == ny - 1) top.elements.push_back(e), top.sides.push_back(2);
        if (i == 0) left.elements.push_back(e), left.sides.push_back(3);
        block.elements.push_back(e++);
      } else {
        // lower-right triangle a-b-c: sides 0 = a-b (bottom), 1 = b-c (right)
        C(e, 0) = a, C(e, 1) = b, C(e, 2) = c;
        if (j == 0) bottom.elements.push_back(e), bottom.sides.push_back(0);
        if (i == nx - 1) right.elements.push_back(e), right.sides.push_back(1);
        block.elements.push_back(e++);
        // upper-left triangle a-c-d: sides 1 = c-d (top), 2 = d-a (left)
        C(e, 0) = a, C(e, 1) = c, C(e, 2) = d;
        if (j == ny - 1) top.elements.push_back(e), top.sides.push_back(1);
        if (i == 0) left.elements.push_back(e), left.sides.push_back(2);
        block.elements.push_back(e++);
      }
    }
  Kokkos::deep_copy(mesh.coordinates, X);
  Kokkos::deep_copy(mesh.connectivity, C);
  mesh.blocks.push_back(block);
  NodeSet nleft{"left", 1, {}}, nright{"right", 2, {}}, nbottom{"bottom", 3, {}},
      ntop{"top", 4, {}};
  for (int j = 0; j <= ny; ++j)
    nleft.nodes.push_back(node(0, j)), nright.nodes.push_back(node(nx, j));
  for (int i = 0; i <= nx; ++i)
    nbottom.nodes.push_back(node(i, 0)), ntop.nodes.push_back(node(i, ny));
  mesh.node_sets = {nleft, nright, nbottom, ntop};
  mesh.side_sets = {left, right, bottom, top};
  return mesh;
}

/// The liquid flags of two materials (LiquidCarrying): material 0 carries liquid, material
/// 1 is dry.
inline Kokkos::View<const int*, MemSpace> liquidFlags() {
  Kokkos::View<int*, MemSpace> flags("liquid_m", 2);
  auto host = Kokkos::create_mirror_view(flags);
  host(0) = 1;
  host(1) = 0;
  Kokkos::deep_copy(flags, host);
  return flags;
}

/// rectangleMesh of quad4 as a structured grid of nx x ny cells (what generateRectangle
/// sets), with the transfers on the grid family `family` (GIMP, B-spline).
inline Mesh gridMesh(int nx, int ny, Real width, Real height, ShapeFamily family, Real x0 = 0,
                     Real y0 = 0) {
  Mesh mesh = rectangleMesh(nx, ny, width, height, ElementType::Quad4, x0, y0);
  mesh.structured.cells[0] = nx;
  mesh.structured.cells[1] = ny;
  mesh.structured.origin[0] = x0;
  mesh.structured.origin[1] = y0;
  mesh.structured.spacing[0] = width / nx;
  mesh.structured.spacing[1] = height / ny;
  mesh.shape_functions = family;
  return mesh;
}

/// Points at fixed local positions in every element (Quad4: the 2 x 2 points at xi = +-1/2;
/// Tri3: 3 points at (1/6, 1/6), (2/3, 1/6), (1/6, 2/3)), each with an equal share of the
/// element area as volume, material `material`, in the elements where `seeded(e)` holds (all
/// when null). Only identity, location and volume are set.
inline MaterialPoints seedUniform(const Mesh& mesh, int material = 0,
                                  const std::function<bool(int)>& seeded = nullptr) {
  const int all_elements = mesh.numElements();
  std::vector<int> chosen;
  for (int e = 0; e < all_elements; ++e)
    if (!seeded || seeded(e)) chosen.push_back(e);
  const int elements = static_cast<int>(chosen.size());
  const bool quad = mesh.type == ElementType::Quad4;
  const int per = quad ? 4 : 3;
  const Real quad_xi[4][2] = {{-0.5, -0.5}, {0.5, -0.5}, {0.5, 0.5}, {-0.5, 0.5}};
  const Real tri_xi[3][2] = {{1.0 / 6, 1.0 / 6}, {2.0 / 3, 1.0 / 6}, {1.0 / 6, 2.0 / 3}};
  MaterialPoints points;
  points.allocate(elements * per);
  auto id = Kokkos::create_mirror_view(points.id);
  auto element = Kokkos::create_mirror_view(points.element);
  auto local = Kokkos::create_mirror_view(points.local);
  auto position = Kokkos::create_mirror_view(points.position);
  auto initial = Kokkos::create_mirror_view(points.initial_position);
  auto mat = Kokkos::create_mirror_view(points.material);
  auto volume = Kokkos::create_mirror_view(points.volume);
  auto volume0 = Kokkos::create_mirror_view(points.initial_volume);
  const auto X = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), mesh.coordinates);
  const auto C = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), mesh.connectivity);
  int p = 0;
  for (const int e : chosen) {
    Real Xe[4][kDim];
    for (int a = 0; a < per; ++a)
      for (int d = 0; d < kDim; ++d) Xe[a][d] = X(C(e, a), d);
    const Real area = quad ? elementArea<Quad4>(Xe) : elementArea<Tri3>(Xe);
    for (int k = 0; k < per; ++k, ++p) {
      const Real* xi = quad ? quad_xi[k] : tri_xi[k];
      Real x[kDim];
      if (quad)
        mapToPhysical<Quad4>(Xe, xi, x);
      else
        mapToPhysical<Tri3>(Xe, xi, x);
      id(p) = p;
      element(p) = e;
      local(p, 0) = xi[0];
      local(p, 1) = xi[1];
      for (int d = 0; d < kDim; ++d) position(p, d) = initial(p, d) = x[d];
      mat(p) = material;
      volume(p) = volume0(p) = area / per;
    }
  }
  Kokkos::deep_copy(points.id, id);
  Kokkos::deep_copy(points.element, element);
  Kokkos::deep_copy(points.local, local);
  Kokkos::deep_copy(points.position, position);
  Kokkos::deep_copy(points.initial_position, initial);
  Kokkos::deep_copy(points.material, mat);
  Kokkos::deep_copy(points.volume, volume);
  Kokkos::deep_copy(points.initial_volume, volume0);
  return points;
}

/// A linear-elastic material of the given phase model (saturated conductivity k in m/s).
inline MaterialSpec elasticMaterial(const std::string& name, PhaseModel phase, Real young,
                                    Real poisson, Real porosity, Real conductivity = 1e-3,
                                    Real bulk_modulus = 2.2e9) {
  MaterialSpec m;
  m.name = name;
  m.block = "soil";
  m.phase = phase;
  m.porosity = porosity;
  m.solid_density = 2650;
  m.solid.model = SolidModel::LinearElastic;
  m.solid.youngs_modulus = young;
  m.solid.poisson_ratio = poisson;
  m.liquid.density = 1000;
  m.liquid.bulk_modulus = bulk_modulus;
  m.conductivity.model = ConductivityModel::Constant;
  m.conductivity.saturated_conductivity = conductivity;
  return m;
}

/// `material` on van Genuchten's retention curve (Eq. 4.28): p_ref (Pa), lambda, S_min, S_max.
inline MaterialSpec withVanGenuchten(MaterialSpec material, Real reference_pressure, Real lambda,
                                     Real saturation_min, Real saturation_max) {
  material.retention.model = RetentionModel::VanGenuchten;
  material.retention.reference_pressure = reference_pressure;
  material.retention.lambda = lambda;
  material.retention.saturation_min = saturation_min;
  material.retention.saturation_max = saturation_max;
  return material;
}

inline BoundarySpec solidFixity(const std::string& name, const std::string& set, bool x, bool y) {
  BoundarySpec b;
  b.name = name;
  b.kind = BoundaryKind::SolidFixity;
  b.node_set = set;
  b.fix_x = x;
  b.fix_y = y;
  return b;
}

inline BoundarySpec impermeable(const std::string& name, const std::string& side_set) {
  BoundarySpec b;
  b.name = name;
  b.kind = BoundaryKind::LiquidFixity;
  b.side_set = side_set;
  return b;
}

inline BoundarySpec traction(const std::string& name, const std::string& side_set, Real tx,
                             Real ty) {
  BoundarySpec b;
  b.name = name;
  b.kind = BoundaryKind::Traction;
  b.side_set = side_set;
  b.traction = {tx, ty};
  return b;
}

inline BoundarySpec liquidPressure(const std::string& name, const std::string& side_set,
                                   Real pressure) {
  BoundarySpec b;
  b.name = name;
  b.kind = BoundaryKind::LiquidPressure;
  b.side_set = side_set;
  b.pressure = pressure;
  return b;
}

/// Rollers on the sides (solid x fixed, impermeable), fixed impermeable base.
inline std::vector<BoundarySpec> columnBoundaries() {
  return {solidFixity("base", "bottom", true, true),
          solidFixity("left roller", "left", true, false),
          solidFixity("right roller", "right", true, false),
          impermeable("base seal", "bottom"),
          impermeable("left seal", "left"),
          impermeable("right seal", "right")};
}

/// A host COPY of a View (a snapshot: on the Serial backend create_mirror_view_and_copy would
/// return the View itself, which keeps changing).
template <class View>
auto hostCopy(const View& view) {
  auto copy = Kokkos::create_mirror(Kokkos::HostSpace(), view);
  Kokkos::deep_copy(copy, view);
  return copy;
}

}  // namespace argine::test
