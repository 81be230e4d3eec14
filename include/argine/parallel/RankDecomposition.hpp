#pragma once
/// @file RankDecomposition.hpp
/// How the explicit MPM step is split over MPI ranks (doc/parallel.md):
///  - the 2D background mesh is small and REPLICATED on every rank; its ELEMENTS are
///    partitioned geometrically (recursive coordinate bisection of the element centroids,
///    weighted by the points each element holds at the start), identically on every rank;
///  - a material point lives on the rank that owns its element (points migrate when they
///    cross into another rank's element, PointMigration.hpp);
///  - nodal arrays keep one entry per mesh node on every rank; a node in the FOOTPRINT of
///    elements of several ranks (the nodes their points can reach, mesh/ElementFootprint.hpp:
///    the element's nodes on linear shapes, the 4 x 4 block around it on GIMP and B-spline)
///    is SHARED: its P2G sums are completed by a neighbour exchange (NodalExchange.hpp) so
///    that every rank holding it sees the same value, bit for bit;
///  - each node is OWNED by the lowest rank among the owners of the elements whose footprint
///    holds it; sums over nodes (boundary fluxes) count a node on its owner only.
/// With one rank nothing is shared and the step is the serial one.

#include <mpi.h>

#include <vector>

#include "argine/core/Types.hpp"

namespace argine {

struct Mesh;
struct MaterialPoints;

/// Recursive coordinate bisection: element -> part in [0, parts). Each cut is normal to the
/// longer side of the centroids' bounding box and splits the weight in proportion to the
/// parts on either side (ties broken by element index: every rank gets the same answer).
std::vector<int> bisectElements(const std::vector<Real>& centroid_x,
                                const std::vector<Real>& centroid_y,
                                const std::vector<Real>& weights, int parts);

/// Partition weights: points per element (points with element < 0 ignored) plus a small
/// weight (1e-3) for every element, so that empty elements are spread as well.
std::vector<Real> pointsPerElementWeights(const Mesh& mesh, const MaterialPoints& points);

/// One neighbouring rank and the shared nodes both hold (ascending: the same order on both).
struct RankNeighbour {
  int rank = -1;
  std::vector<int> nodes;  ///< mesh node indices
  std::vector<int> slots;  ///< index of each node in RankDecomposition::sharedNodes()
};

class RankDecomposition {
 public:
  /// Collective over `comm`; every rank passes the same mesh and weights (one per element).
  RankDecomposition(MPI_Comm comm, const Mesh& mesh, const std::vector<Real>& element_weights);

  MPI_Comm comm() const { return comm_; }
  int rank() const { return rank_; }
  int size() const { return size_; }

  /// Owner rank of each element (host copy and kernel copy).
  const std::vector<int>& elementOwners() const { return element_owner_; }
  Kokkos::View<const int*, MemSpace> elementOwnerView() const { return element_owner_e_; }
  /// Elements this rank owns.
  int ownedElements() const { return owned_elements_; }

  /// Nodes in the footprint of this rank's elements and of another rank's, ascending.
  const std::vector<int>& sharedNodes() const { return shared_nodes_; }
  Kokkos::View<const int*, MemSpace> sharedNodeView() const { return shared_nodes_i_; }
  /// Ranks sharing nodes with this one, ascending.
  const std::vector<RankNeighbour>& neighbours() const { return neighbours_; }
  /// 1 at the nodes this rank owns (the lowest rank among the owners of the elements whose
  /// footprint holds the node), else 0; a node in no footprint is owned by rank 0.
  Kokkos::View<const unsigned char*, MemSpace> nodeOwnedView() const { return node_owned_i_; }

 private:
  MPI_Comm comm_;
  int rank_ = 0;
  int size_ = 1;
  int owned_elements_ = 0;
  std::vector<int> element_owner_;
  Kokkos::View<int*, MemSpace> element_owner_e_;
  std::vector<int> shared_nodes_;
  Kokkos::View<int*, MemSpace> shared_nodes_i_;
  Kokkos::View<unsigned char*, MemSpace> node_owned_i_;
  std::vector<RankNeighbour> neighbours_;
};

}  // namespace argine
