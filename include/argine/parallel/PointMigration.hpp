#pragma once
/// @file PointMigration.hpp
/// Material points move to the rank that owns their element (RankDecomposition). Called
/// after the relocation of a step: a point that crossed into another rank's element is
/// packed (every field of ARGINE_MATERIAL_POINT_FIELDS, as doubles: ints are exact) and sent
/// to that rank, which appends it. Points outside the mesh (element < 0) stay where they
/// are. The order of the kept points is unchanged; received points follow in sender-rank
/// order. Collective over the decomposition's ranks.

#include <mpi.h>

#include <vector>

#include "argine/core/Types.hpp"

namespace argine {

class RankDecomposition;
struct MaterialPoints;

/// What one migration moved (this rank's view, and the total over all ranks).
struct MigrationCounts {
  int sent = 0;         ///< points this rank sent away
  int received = 0;     ///< points this rank received
  long long total = 0;  ///< points moved between any two ranks
};

/// Values per point in a migration message (all components of all point fields).
int migratedValuesPerPoint(const MaterialPoints& points);

/// Sends every located point whose element another rank owns to that rank and appends the
/// points received. `points` is reallocated only when something moved on this rank.
MigrationCounts migratePoints(const RankDecomposition& decomposition, MaterialPoints& points);

/// Located points of this rank whose element another rank owns (local, no communication).
int countEmigrants(const RankDecomposition& decomposition, const MaterialPoints& points);

/// migratePoints when the caller already summed countEmigrants over the ranks (`total`, the
/// same on every rank; nothing is communicated when it is 0). Collective.
MigrationCounts exchangePoints(const RankDecomposition& decomposition, MaterialPoints& points,
                               long long total);

/// Keeps only the points whose element this rank owns (and, on rank 0, the points outside
/// the mesh): the first distribution of points seeded identically on every rank. Local.
void keepOwnedPoints(const RankDecomposition& decomposition, MaterialPoints& points);
/// The points of all ranks of `comm`, ordered by id (so the result does not depend on how
/// the points are split): on rank 0 only, or on every rank when `to_all_ranks`; an empty
/// set elsewhere. For output (rank 0 writes the files) and for handing the points to a
/// stage that keeps them replicated (the implicit seepage solver). Collective over `comm`.
MaterialPoints gatherPoints(MPI_Comm comm, const MaterialPoints& points, bool to_all_ranks);
/// The points of all ranks of `comm` on rank 0, rank after rank and each rank's in its own
/// memory order, with the number each rank holds in `counts` (on rank 0; empty elsewhere):
/// what a checkpoint of a decomposed run stores, so that every rank gets back its points in
/// the order of its sums (pointRange). Collective over `comm`.
MaterialPoints gatherPointsByRank(MPI_Comm comm, const MaterialPoints& points,
                                  std::vector<long long>& counts);
/// Points [first, first + count) of `points`, in order, as a new set. Local.
MaterialPoints pointRange(const MaterialPoints& points, int first, int count);

}  // namespace argine
