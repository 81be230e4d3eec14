#pragma once
/// @file DistributedStep.hpp
/// The communication of the explicit step over several MPI ranks (doc/parallel.md), as
/// named functions that ExplicitTwoPhaseSolver calls at fixed points of step() when it runs
/// on a RankDecomposition. Per step:
///   after mapPointsToGrid            sumGridAtSharedNodes (13 values per shared node)
///   after mapBoundaryGradients       sumBoundaryGradientsAtSharedNodes (5; hydraulic
///                                    conditions only)
///   after the momentum remap         sumMomentaAtSharedNodes (4)
///   end of the step                  one Allreduce (EndOfStepSums: energies, liquid mass,
///                                    invalid points, relocation and migration counts,
///                                    and the next time step: min over the ranks)
///   time step                        none after a step (it came with the end of the step);
///                                    else globalTimeStep (one Allgather)
///   after a point changed element    globalActiveElements (the free boundary)
///   relocation                       migratePoints (parallel/PointMigration.hpp)

#include <vector>

#include "argine/core/Types.hpp"
#include "argine/parallel/NodalExchange.hpp"
#include "argine/parallel/RankDecomposition.hpp"
#include "argine/physics/TimeStepControl.hpp"
#include "argine/transfer/CompensatedSum.hpp"

namespace argine {

struct BoundaryGradientFields;
struct GridFields;
struct KineticTotals;
struct MaterialPoints;
struct PointTotals;

/// Completes the P2G of mapPointsToGrid at the shared nodes: masses, drag, liquid volume,
/// momenta and forces, in one message per neighbour.
/// With `compensation` (reproducible sums) the binned sums (grid, compensation) are merged
/// (NodalExchange::sumCompensated); they still need folding.
void sumGridAtSharedNodes(NodalExchange& exchange, GridFields& grid,
                          LowParts<GridFields>* compensation = nullptr);
/// Completes the remapped momenta (updatePointVelocitiesAndMapMomenta) at the shared nodes.
void sumMomentaAtSharedNodes(NodalExchange& exchange, GridFields& grid,
                             LowParts<GridFields>* compensation = nullptr);
/// Completes mapBoundaryGradients at the shared nodes (mass gradient, flux weights, wet
/// volume).
void sumBoundaryGradientsAtSharedNodes(NodalExchange& exchange, BoundaryGradientFields& fields,
                                       LowParts<BoundaryGradientFields>* compensation = nullptr);

/// Everything the end of a step sums over the ranks, in ONE Allreduce: the point totals of
/// the state update, the kinetic totals of the velocity update, and the relocation counts
/// (lost points, points that changed element, points to migrate).
struct EndOfStepSums {
  Real kinetic_solid = 0, kinetic_liquid = 0, liquid_mass = 0;
  Real non_finite_state = 0, non_finite_velocity = 0;
  Real lost = 0, changed_element = 0, emigrants = 0;  // counts, exact in a double
};
/// The next step's time-step choice of this rank, carried by the end-of-step reduction so
/// that choosing the next step needs no collective of its own.
struct TimeStepCandidate {
  /// In: this rank's choice (time_step = infinity without points). Out: the smallest step
  /// over the ranks (ties: the lowest rank, as globalTimeStep), with the choice of the rank
  /// that gave it; `point` is an index on that rank only, -1 elsewhere.
  TimeStepChoice choice;
  /// In: this rank evaluated its choice. Out: every rank did (else choice is meaningless).
  bool ready = false;
};
/// Sums `sums` and `also` (e.g. the liquid volume through each hydraulic condition) over
/// the ranks and reduces `next` (when given) in ONE Allreduce, through `scratch` (grown,
/// never shrunk: no allocation per step).
void sumOverRanks(MPI_Comm comm, EndOfStepSums& sums, std::vector<Real>& also,
                  TimeStepCandidate* next, std::vector<Real>& scratch);
/// Reproducible sums: entry k of every rank's `sums` merged in rank order (exact, binned:
/// transfer/CompensatedSum.hpp), into sums[k] on every rank (fold with value()). Collective
/// (one Allgather of all parts, through `scratch`: grown, never shrunk).
void sumCompensatedOverRanks(MPI_Comm comm, std::vector<CompensatedReal>& sums,
                             std::vector<Real>& scratch);
/// Element-wise sum of `values` over the ranks (in place).
void sumOverRanks(MPI_Comm comm, std::vector<Real>& values);
long long sumOverRanks(MPI_Comm comm, long long value);

/// The smallest step over the ranks (ties: the lowest rank) with the choice of the rank
/// that gave it (its governing criterion, point id and position; `point` is an index on that
/// rank only, -1 elsewhere), by one Allgather of the choices. A rank without points passes a
/// choice with time_step = infinity.
TimeStepChoice globalTimeStep(MPI_Comm comm, const TimeStepChoice& local);

/// The elements holding at least one located point on ANY rank, ascending (collective).
std::vector<int> globalActiveElements(MPI_Comm comm, const MaterialPoints& points, int elements);

}  // namespace argine
