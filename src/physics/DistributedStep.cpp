#include "argine/physics/DistributedStep.hpp"

#include <algorithm>
#include <cstring>

#include "argine/physics/HydraulicBoundaryStep.hpp"
#include "argine/physics/StabilityCheck.hpp"
#include "argine/physics/TimeStepControl.hpp"
#include "argine/points/MaterialPoints.hpp"
#include "argine/transfer/CompensatedSum.hpp"
#include "argine/transfer/GridFields.hpp"
#include "argine/transfer/TwoPhaseTransfer.hpp"

namespace argine {

namespace {

/// The NodalFieldRefs of `refs(fields)` for each low part, part after part (sumCompensated).
template <class Fields, class Refs>
std::vector<NodalFieldRef> lowRefs(const LowParts<Fields>& lo, const Refs& refs) {
  std::vector<NodalFieldRef> all;
  for (int k = 0; k < kLowParts; ++k) {
    const std::vector<NodalFieldRef> part = refs(lo[k]);
    all.insert(all.end(), part.begin(), part.end());
  }
  return all;
}

std::vector<NodalFieldRef> gridSumRefs(const GridFields& g) {
  return {nodalField(g.mass_solid_i),
          nodalField(g.mass_liquid_i),
          nodalField(g.mass_liquid_intrinsic_i),
          nodalField(g.drag_i),
          nodalField(g.volume_liquid_i),
          nodalField(g.momentum_solid_i),
          nodalField(g.momentum_liquid_i),
          nodalField(g.force_mixture_i),
          nodalField(g.force_liquid_i)};
}

std::vector<NodalFieldRef> momentumRefs(const GridFields& g) {
  return {nodalField(g.momentum_solid_i), nodalField(g.momentum_liquid_i)};
}

std::vector<NodalFieldRef> boundaryRefs(const BoundaryGradientFields& f) {
  std::vector<NodalFieldRef> refs = {nodalField(f.mass_gradient_i), nodalField(f.flux_weight_i),
                                     nodalField(f.wet_volume_i)};
  if (f.with_surface_pressure) {
    refs.push_back(nodalField(f.volume_gradient_i));
    refs.push_back(nodalField(f.pressure_volume_i));
  }
  return refs;
}

}  // namespace

void sumGridAtSharedNodes(NodalExchange& exchange, GridFields& g,
                          LowParts<GridFields>* compensation) {
  if (!compensation) return exchange.sum(gridSumRefs(g));
  exchange.sumCompensated(gridSumRefs(g), lowRefs(*compensation, gridSumRefs));
}

void sumMomentaAtSharedNodes(NodalExchange& exchange, GridFields& g,
                             LowParts<GridFields>* compensation) {
  if (!compensation) return exchange.sum(momentumRefs(g));
  exchange.sumCompensated(momentumRefs(g), lowRefs(*compensation, momentumRefs));
}

void sumBoundaryGradientsAtSharedNodes(NodalExchange& exchange, BoundaryGradientFields& f,
                                       LowParts<BoundaryGradientFields>* compensation) {
  if (!compensation) return exchange.sum(boundaryRefs(f));
  exchange.sumCompensated(boundaryRefs(f), lowRefs(*compensation, boundaryRefs));
}

namespace {

/// Whether rank `rank`'s time step wins over rank `other`'s: the smaller step, on a tie the
/// lower rank (the one rule of globalTimeStep and of the end-of-step reduction).
bool stepWins(Real step, int rank, Real other_step, int other_rank) {
  return step < other_step || (step == other_step && rank < other_rank);
}

/// The time-step candidate at the head of the end-of-step buffer, as doubles (the ints and
/// the criterion's index are exact in a double).
enum CandidateSlot : int {
  kSlotStep = 0,
  kSlotCritical,
  kSlotAutomatic,
  kSlotGoverning,
  kSlotPoint,
  kSlotPointId,
  kSlotX,
  kSlotY,
  kSlotRank,
  kSlotReady,
  kCandidateSlots
};

void packCandidate(const TimeStepCandidate& next, int rank, Real* slot) {
  const TimeStepChoice& c = next.choice;
  slot[kSlotStep] = c.time_step;
  slot[kSlotCritical] = c.critical_step;
  slot[kSlotAutomatic] = c.automatic ? 1 : 0;
  slot[kSlotGoverning] = static_cast<Real>(static_cast<int>(c.governing));
  slot[kSlotPoint] = c.point;
  slot[kSlotPointId] = c.point_id;
  slot[kSlotX] = c.position[0];
  slot[kSlotY] = c.position[1];
  slot[kSlotRank] = rank;
  slot[kSlotReady] = next.ready ? 1 : 0;
}

void unpackCandidate(const Real* slot, int rank, TimeStepCandidate& next) {
  TimeStepChoice& c = next.choice;
  c.time_step = slot[kSlotStep];
  c.critical_step = slot[kSlotCritical];
  c.automatic = slot[kSlotAutomatic] != 0;
  c.governing = static_cast<CriterionKind>(static_cast<int>(slot[kSlotGoverning]));
  c.point = static_cast<int>(slot[kSlotRank]) == rank ? static_cast<int>(slot[kSlotPoint]) : -1;
  c.point_id = static_cast<int>(slot[kSlotPointId]);
  c.position[0] = slot[kSlotX];
  c.position[1] = slot[kSlotY];
  next.ready = slot[kSlotReady] != 0;
}

/// The end-of-step reduction (MPI_User_function): the winning candidate (stepWins), ready
/// only when both are, and the sum of every entry after the candidate. Commutative.
void combineEndOfStep(void* in, void* inout, int* length, MPI_Datatype*) {
  const Real* a = static_cast<const Real*>(in);
  Real* b = static_cast<Real*>(inout);
  const Real ready = a[kSlotReady] != 0 && b[kSlotReady] != 0 ? 1 : 0;
  if (stepWins(a[kSlotStep], static_cast<int>(a[kSlotRank]), b[kSlotStep],
               static_cast<int>(b[kSlotRank])))
    std::copy(a, a + kCandidateSlots, b);
  b[kSlotReady] = ready;
  for (int k = kCandidateSlots; k < *length; ++k) b[k] += a[k];
}

MPI_Op endOfStepOp() {
  static const MPI_Op op = [] {
    MPI_Op created;
    MPI_Op_create(&combineEndOfStep, /*commute=*/1, &created);
    return created;
  }();
  return op;
}

}  // namespace

void sumOverRanks(MPI_Comm comm, EndOfStepSums& sums, std::vector<Real>& also,
                  TimeStepCandidate* next, std::vector<Real>& scratch) {
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  Real* fixed[] = {&sums.kinetic_solid,       &sums.kinetic_liquid,
                   &sums.liquid_mass,         &sums.non_finite_state,
                   &sums.non_finite_velocity, &sums.lost,
                   &sums.changed_element,     &sums.emigrants};
  constexpr std::size_t kFixed = sizeof fixed / sizeof fixed[0];
  const std::size_t head = kCandidateSlots, n = head + kFixed + also.size();
  if (scratch.size() < n) scratch.resize(n);
  packCandidate(next ? *next : TimeStepCandidate{}, rank, scratch.data());
  for (std::size_t k = 0; k < kFixed; ++k) scratch[head + k] = *fixed[k];
  std::copy(also.begin(), also.end(), scratch.begin() + head + kFixed);
  MPI_Allreduce(MPI_IN_PLACE, scratch.data(), static_cast<int>(n), MPI_DOUBLE, endOfStepOp(), comm);
  if (next) unpackCandidate(scratch.data(), rank, *next);
  for (std::size_t k = 0; k < kFixed; ++k) *fixed[k] = scratch[head + k];
  std::copy(scratch.begin() + head + kFixed, scratch.begin() + n, also.begin());
}

void sumCompensatedOverRanks(MPI_Comm comm, std::vector<CompensatedReal>& sums,
                             std::vector<Real>& scratch) {
  int ranks = 1;
  MPI_Comm_size(comm, &ranks);
  const std::size_t n = sums.size() * kSumParts;
  // scratch = [this rank's parts | every rank's parts]
  const std::size_t needed = n * (1 + static_cast<std::size_t>(ranks));
  if (scratch.size() < needed) scratch.resize(needed);
  Real* mine = scratch.data();
  Real* all = mine + n;
  for (std::size_t k = 0; k < sums.size(); ++k)
    std::copy(sums[k].part, sums[k].part + kSumParts, mine + k * kSumParts);
  MPI_Allgather(mine, static_cast<int>(n), MPI_DOUBLE, all, static_cast<int>(n), MPI_DOUBLE, comm);
  for (std::size_t k = 0; k < sums.size(); ++k) {
    CompensatedReal total;
    for (int r = 0; r < ranks; ++r) {
      CompensatedReal theirs;
      const Real* parts = &all[n * static_cast<std::size_t>(r) + k * kSumParts];
      std::copy(parts, parts + kSumParts, theirs.part);
      total.add(theirs);
    }
    sums[k] = total;
  }
}

void sumOverRanks(MPI_Comm comm, std::vector<Real>& values) {
  MPI_Allreduce(MPI_IN_PLACE, values.data(), static_cast<int>(values.size()), MPI_DOUBLE, MPI_SUM,
                comm);
}

long long sumOverRanks(MPI_Comm comm, long long value) {
  MPI_Allreduce(MPI_IN_PLACE, &value, 1, MPI_LONG_LONG, MPI_SUM, comm);
  return value;
}

TimeStepChoice globalTimeStep(MPI_Comm comm, const TimeStepChoice& local) {
  int rank = 0, size = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  // Every rank's choice, as bytes (a trivially copyable struct); the buffer only grows.
  static_assert(std::is_trivially_copyable_v<TimeStepChoice>);
  static thread_local std::vector<TimeStepChoice> all;
  all.resize(size);
  MPI_Allgather(&local, sizeof local, MPI_BYTE, all.data(), sizeof local, MPI_BYTE, comm);
  int best = 0;
  for (int r = 1; r < size; ++r)
    if (stepWins(all[r].time_step, r, all[best].time_step, best)) best = r;
  TimeStepChoice choice = all[best];
  if (best != rank) choice.point = -1;
  return choice;
}

std::vector<int> globalActiveElements(MPI_Comm comm, const MaterialPoints& points, int elements) {
  std::vector<unsigned char> flag(elements, 0);
  const auto element = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), points.element);
  for (int p = 0; p < points.count; ++p)
    if (element(p) >= 0) flag[element(p)] = 1;
  MPI_Allreduce(MPI_IN_PLACE, flag.data(), elements, MPI_UNSIGNED_CHAR, MPI_BOR, comm);
  std::vector<int> active;
  for (int e = 0; e < elements; ++e)
    if (flag[e]) active.push_back(e);
  return active;
}

}  // namespace argine
