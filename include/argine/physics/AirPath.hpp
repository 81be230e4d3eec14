#pragma once
/// @file AirPath.hpp
/// Where air can reach a tension crack (`Tension Cracks: air-filled`, keepsOpeningOut). An
/// air-filled crack is open to the atmosphere, so air must have a path to it: through the
/// soil's free surface or through an open crack next to it. The map marks, per element of
/// the background mesh, whether a point there may open an air-filled crack:
///  - an element with a free side that is not the mesh edge (FreeBoundary: its neighbour
///    holds no points, so the side lies on the soil's surface, open to the air or to
///    standing water, where S_L < S_max admits no crack anyway);
///  - an element holding a point with an open air-filled crack (separation > 0 in an
///    air-filled material), and the elements across its sides.
/// So a crack starts at the surface and grows inwards one element per step at most, through
/// elements that crack in turn; a point whose pores hold suction deep in an intact body (a
/// point with occluded air, S_L just below S_max) keeps the pore-space rule. A crack stays
/// open to the air until it closes, even when the crack that led to it has closed (a limit
/// of the model). Renewed before each step's point updates, from the points of every rank
/// (the map is the same on all ranks). Host loops over the points and the elements: the map
/// is built only when a material has air-filled cracks.

#include <mpi.h>

#include <vector>

#include "argine/core/Types.hpp"

namespace argine {

struct MaterialPoints;
class FreeBoundary;
class MaterialTable;

class AirPath {
 public:
  AirPath() = default;
  /// Enabled when a material of `table` has `Tension Cracks: air-filled`.
  AirPath(const MaterialTable& table, int elements);

  bool enabled() const { return enabled_; }

  /// Renews the map from the free boundary (detected for the points' current elements) and
  /// the points' open cracks; with `comm` != MPI_COMM_NULL the cracked elements of all ranks.
  void update(const FreeBoundary& boundary, const MaterialPoints& points,
              MPI_Comm comm = MPI_COMM_NULL);

  /// 1 where air reaches the element, by element (empty while not enabled: the point updates
  /// then admit an air-filled crack anywhere, their rule for a single point).
  Kokkos::View<const unsigned char*, MemSpace> reachesElement() const { return reaches_e_; }

  /// Elements holding a point with an open air-filled crack at the last update (all ranks).
  int crackedElements() const { return cracked_count_; }

 private:
  bool enabled_ = false;
  std::vector<unsigned char> air_filled_m_;           ///< by material id: air-filled cracks
  std::vector<unsigned char> cracked_;                ///< by element, scratch
  Kokkos::View<unsigned char*, MemSpace> reaches_e_;  ///< the map, by element
  Kokkos::View<unsigned char*, MemSpace>::HostMirror reaches_h_;  ///< its host side (the same
                                                                  ///< memory on a host space)
  int cracked_count_ = 0;
};

}  // namespace argine
