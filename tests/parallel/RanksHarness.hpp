#pragma once
// Runs a scene once on each rank alone and once over all ranks of MPI_COMM_WORLD and
// compares the point states gathered by id (the tests of the distributed explicit step:
// DistributedSolverTest, GridFamiliesRanksTest).

#include <string>
#include <vector>

#include "argine/input/Deck.hpp"
#include "argine/mesh/Mesh.hpp"
#include "argine/points/MaterialPoints.hpp"

namespace argine::test {

/// A scene: mesh, points and materials before any step, and how to run it.
struct RanksScene {
  Mesh mesh;
  MaterialPoints points;
  std::vector<MaterialSpec> materials;
  std::vector<StageSpec> stages;
  int steps_per_stage = 200;
  std::vector<Real> weights;  ///< partition weights per element (empty: points per element)
  bool reproducible_sums = false;
  /// p_L differences are taken relative to at least this (Pa): where the liquid carries
  /// little of the load, p_L's own largest value would magnify the round-off of the stresses
  /// it is in balance with.
  Real pressure_scale = 0;
};

/// Values compared per point: x, y, v_x, v_y, p_L, s_xx, s_yy, s_xy, M_L.
inline constexpr int kComparedValues = 9;

struct RanksRun {
  std::vector<Real> states;  ///< kComparedValues per point, by id
  long long migrated = 0;    ///< points moved between ranks
  long long steps = 0;
};

/// A deep copy of every point field.
MaterialPoints copyOf(const MaterialPoints& points);

/// Runs `scene` (on a copy of its points) on this rank alone or over all ranks, with
/// sorting every ExplicitTwoPhaseSolver::kRecommendedSortInterval steps.
RanksRun runScene(const RanksScene& scene, bool distributed);

/// Largest difference of each compared value over the points, relative to the largest
/// magnitude of its quantity in `one` (position, velocity, p_L, effective stress and M_L
/// each have one scale; p_L's at least `pressure_scale`); a missing point counts as infinite.
std::vector<Real> relativeDifferences(const std::vector<Real>& one, const std::vector<Real>& all,
                                      Real pressure_scale = 0);

/// Runs `scene` on one rank and on all ranks and expects every relative difference <=
/// `tolerance` (printed on rank 0); `migrated`: the points the run over all ranks moved.
void expectSameAsOneRank(const RanksScene& scene, Real tolerance, long long* migrated = nullptr);

/// The same, and on more than one rank points must have crossed a rank border.
void expectSameAsOneRankWithMigration(const RanksScene& scene, Real tolerance);

/// A saturated Mohr-Coulomb block (c' = 0, phi' = 25 deg) on a rough base with a vertical
/// free face, under gravity; a soft liquid (K_L = 2.2 MPa) for a long stable step, so the face
/// slumps by more than a quarter element within the 700 steps. The 16 x 6 quad4 mesh is cut in
/// the middle (equal weights), one column left of the face: points of the left rank flow into
/// the right rank's elements. `damping`: the stage's local damping.
RanksScene slumpingSlope(Real damping);

/// The scene of a deck: its stages [first, first + count), each run for `steps` steps (the
/// material changes of those stages applied up front).
RanksScene deckScene(const std::string& relative_path, int first, int count, int steps);

}  // namespace argine::test
