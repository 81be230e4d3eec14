#include "argine/physics/DistributedStep.hpp"

#include <algorithm>
#include <cstring>

#include "argine/physics/HydraulicBoundaryStep.hpp"
#include "argine/physics/StabilityCheck.hpp"
#include "argine/physics/TimeStepControl.hpp"
#include "argine/points/MaterialPoints.hpp"
#include "argine/transfer/GridFields.hpp"
#include "argine/transfer/TwoPhaseTransfer.hpp"

namespace argine {

void sumGridAtSharedNodes(NodalExchange& exchange, GridFields& g) {
  exchange.sum({nodalField(g.mass_solid_i), nodalField(g.mass_liquid_i),
                nodalField(g.mass_liquid_intrinsic_i), nodalField(g.drag_i),
                nodalField(g.volume_liquid_i), nodalField(g.momentum_solid_i),
                nodalField(g.momentum_liquid_i), nodalField(g.force_mixture_i),
                nodalField(g.force_liquid_i)});
}

void sumMomentaAtSharedNodes(NodalExchange& exchange, GridFields& g) {
  exchange.sum({nodalField(g.momentum_solid_i), nodalField(g.momentum_liquid_i)});
}

void sumBoundaryGradientsAtSharedNodes(NodalExchange& exchange, BoundaryGradientFields& f) {
  exchange.sum(
      {nodalField(f.mass_gradient_i), nodalField(f.flux_weight_i), nodalField(f.wet_volume_i)});
}

void sumOverRanks(MPI_Comm comm, PointTotals& totals) {
  Real sums[4] = {totals.kinetic_energy_solid, totals.kinetic_energy_liquid, totals.liquid_mass,
                  static_cast<Real>(totals.non_finite_points)};
  MPI_Allreduce(MPI_IN_PLACE, sums, 4, MPI_DOUBLE, MPI_SUM, comm);
  totals.kinetic_energy_solid = sums[0];
  totals.kinetic_energy_liquid = sums[1];
  totals.liquid_mass = sums[2];
  totals.non_finite_points = static_cast<int>(sums[3]);
}

void sumOverRanks(MPI_Comm comm, KineticTotals& totals) {
  Real sums[3] = {totals.solid, totals.liquid, static_cast<Real>(totals.non_finite_points)};
  MPI_Allreduce(MPI_IN_PLACE, sums, 3, MPI_DOUBLE, MPI_SUM, comm);
  totals.solid = sums[0];
  totals.liquid = sums[1];
  totals.non_finite_points = static_cast<int>(sums[2]);
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
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  struct {
    double value;
    int rank;
  } mine{local.time_step, rank}, best{};
  MPI_Allreduce(&mine, &best, 1, MPI_DOUBLE_INT, MPI_MINLOC, comm);
  // The winner's choice, as bytes (a trivially copyable struct).
  static_assert(std::is_trivially_copyable_v<TimeStepChoice>);
  TimeStepChoice choice = local;
  MPI_Bcast(&choice, sizeof choice, MPI_BYTE, best.rank, comm);
  if (best.rank != rank) choice.point = -1;
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
