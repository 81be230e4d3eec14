#pragma once
/// @file BenchmarkScenes.hpp
/// The scenes of the throughput benchmark, built in code (no files): a block of soil under
/// gravity on a structured background mesh, fixed base, rollers and impermeable sides,
/// each with >= 1e5 material points.
///
///   quad4-saturated     160 x 160 quads of 0.1 m, 2 x 2 points each: 102,400 points
///   tri3-saturated      130 x 130 cells of 0.1 m, two triangles each, 3 points per
///                       triangle: 101,400 points
///   quad4-empty-mesh    the quad4-saturated block in the lower-left corner of a
///                       320 x 320 mesh: 3/4 of the elements (and nodes) hold no points
///   quad4-dry           quad4-saturated with a dry material (the one-phase-like step)
///   quad4-unsaturated   quad4-saturated with a van Genuchten material (p_ref 10 kPa,
///                       lambda 0.5, S_min 0.05) and Mualem HCC at 20 kPa suction: the
///                       SWRC, HCC and Newton pressure update at every point
///   quad4-mohr-coulomb  quad4-saturated with Mohr-Coulomb (c' 5 kPa, phi' 30 deg, psi 0):
///                       the return mapping at every point (not in the default list)
///   quad4-tiny          2 x 2 quads of points in a 4 x 4 mesh (16 points): the fixed cost
///                       of a step (not in the default list)
///   quad4-mohr-coulomb-<shapes>-<transfer>
///                       quad4-mohr-coulomb with the transfers on <shapes> = linear, gimp or
///                       bspline (the mesh then a StructuredGrid) and <transfer> = flip,
///                       apic or tpic: what each scheme costs (issue P9 item 8; "schemes" on
///                       the command line names all nine; not in the default list).
///                       quad4-mohr-coulomb-linear-flip is quad4-mohr-coulomb, bit for bit
///
/// Materials: linear elastic, E = 10 MPa, nu = 0.3, n = 0.4, rho_S = 2650 kg/m^3,
/// k_sat = 1e-3 m/s, K_L = 2.2 GPa. Time step: the deck defaults (automatic, Mieremet and
/// consolidation criteria, safety factor 0.5, recomputed every step); the unsaturated scene
/// adds the infiltration and coupled criteria, without which it goes unstable (the coupled
/// step is about half the Mieremet one there).

#include <string>
#include <vector>

#include "argine/input/Deck.hpp"
#include "argine/mesh/Mesh.hpp"
#include "argine/points/MaterialPoints.hpp"

namespace argine::benchmark {

/// A ready-to-run scene: mesh, seeded and initialised points, materials and one stage.
struct Scene {
  std::string name;                     ///< e.g. "quad4-saturated"
  Mesh mesh;                            ///< background mesh (block "soil", maybe "empty")
  MaterialPoints points;                ///< seeded and initialised
  std::vector<MaterialSpec> materials;  ///< one material, block "soil"
  StageSpec stage;                      ///< explicit, gravity, rollers
};

/// Names of all scenes, in the order the benchmark runs them.
std::vector<std::string> sceneNames();

/// Builds one scene by name; std::invalid_argument for an unknown name.
Scene makeScene(const std::string& name);

/// The nine quad4-mohr-coulomb-<shapes>-<transfer> scenes: linear, gimp, bspline, each with
/// flip, apic then tpic.
std::vector<std::string> schemeSceneNames();

/// The scenes of a comma-separated list, "schemes" standing for schemeSceneNames().
std::vector<std::string> parseSceneList(const std::string& list);

/// A scene of the same kind at any size: a cells x cells mesh of 0.1 m elements whose lower
/// left soil_cells x soil_cells block holds points (4 per quad, 3 per triangle) of one
/// material of the given phase model.
Scene makeBlockScene(const std::string& name, ElementType type, int cells, int soil_cells,
                     PhaseModel phase);

/// Randomly permutes the points (every field alike), as large deformations leave them:
/// neighbouring points no longer neighbours in memory. Fixed seed, so runs repeat.
void shufflePoints(MaterialPoints& points);

}  // namespace argine::benchmark
