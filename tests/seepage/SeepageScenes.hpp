#pragma once
// Columns for the implicit seepage tests: a one-element-wide Quad4 column with 2 x 2 points
// per element, materials initialised, and the material helpers.

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "../transfer/TestScenes.hpp"
#include "argine/physics/PointInitialisation.hpp"
#include "argine/seepage/ImplicitSeepageSolver.hpp"

namespace argine::test {

/// Saturated material with conductivity k (m/s) and liquid bulk modulus K_L (Pa).
inline MaterialSpec saturatedSoil(Real k, Real bulk_modulus, Real porosity = 0.4) {
  return elasticMaterial("soil", PhaseModel::Saturated, 1e7, 0.2, porosity, k, bulk_modulus);
}

/// The V3 soil (VERIFICATION.md V3, thesis Table 4.2): van Genuchten p_ref 3 kPa, lambda 0.7,
/// S_min 0.125, S_max 1, k = 1e-4 m/s constant, n = 0.4 (Table 4.2), K_L 2.2e9 Pa.
inline MaterialSpec infiltrationSoil() {
  MaterialSpec m = elasticMaterial("soil", PhaseModel::Unsaturated, 1e7, 0.2, 0.4, 1e-4, 2.2e9);
  m.retention.model = RetentionModel::VanGenuchten;
  m.retention.reference_pressure = 3000;
  m.retention.lambda = 0.7;
  m.retention.saturation_min = 0.125;
  m.retention.saturation_max = 1;
  return m;
}

struct SeepageColumn {
  Mesh mesh;
  MaterialPoints points;
  std::vector<MaterialSpec> materials;
  SeepageColumn(int rows, Real width, Real height, const MaterialSpec& material,
                Real initial_pressure = 0)
      : mesh(rectangleMesh(1, rows, width, height, ElementType::Quad4)),
        points(seedUniform(mesh)),
        materials{material} {
    materials[0].initial.liquid_pressure = initial_pressure;
    initialisePointState(materials, points);
  }
};

/// Nodes of a side set of the column (sorted, unique).
inline std::vector<int> sideNodes(const Mesh& mesh, const std::string& name) {
  return sideSetNodeLengths(mesh, *mesh.findSideSet(name)).nodes;
}

/// A uniform inflow q (m/s) through the column's top side set: nodal supplies q times each
/// node's tributary length, with the ponding switch on.
inline SeepageBoundaryConditions topInflow(const Mesh& mesh, Real q) {
  const SideSetNodes top = sideSetNodeLengths(mesh, *mesh.findSideSet("top"));
  std::vector<Real> rates;
  for (const Real length : top.lengths) rates.push_back(q * length);
  SeepageBoundaryConditions conditions;
  conditions.addSupplies(top.nodes, rates, true);
  return conditions;
}

/// p_L = base held at the column's bottom and a zero supply with the ponding switch at its
/// top (a seepage face there once the column is saturated up to it).
inline SeepageBoundaryConditions prescribedBaseOpenTop(const Mesh& mesh, Real base) {
  SeepageBoundaryConditions conditions;
  const std::vector<int> bottom = sideNodes(mesh, "bottom");
  const std::vector<int> top = sideNodes(mesh, "top");
  conditions.addPressures(bottom, std::vector<Real>(bottom.size(), base));
  conditions.addSupplies(top, std::vector<Real>(top.size(), 0.0), true);
  return conditions;
}

/// Largest |a - b| over the nodes and the largest |a| (the range it is measured against): a
/// 1-rank run against a run over all ranks (the *.OneAndAllRanks* tests).
struct NodalDifference {
  Real difference = 0, range = 0;
};
inline NodalDifference nodalDifference(const std::vector<Real>& a, const std::vector<Real>& b) {
  NodalDifference d;
  for (std::size_t i = 0; i < a.size(); ++i) {
    d.range = std::max(d.range, std::fabs(a[i]));
    d.difference = std::max(d.difference, std::fabs(a[i] - b[i]));
  }
  return d;
}

}  // namespace argine::test
