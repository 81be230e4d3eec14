#pragma once
// Columns for the implicit seepage tests: a one-element-wide Quad4 column with 2 x 2 points
// per element, materials initialised, and the material helpers.

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

}  // namespace argine::test
