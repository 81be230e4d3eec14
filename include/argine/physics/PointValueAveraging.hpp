#pragma once
/// @file PointValueAveraging.hpp
/// The volume-weighted smoothing of point quantities that the locking mitigation
/// (VolumetricAveraging) and the liquid head stabilisation (LiquidHeadStabilisation) share:
///
///   element  q_p <- sum_{q in e} w_q q_q / sum_{q in e} w_q  over the points of the point's
///            element e with the same mode (or of its patch of elements, usePatches);
///   nodal    q_i = sum_p N_i(x_p) w_p q_p / sum_p N_i(x_p) w_p at the nodes, then
///            q_p <- sum_i N_i(x_p) q_i.
///
/// Both keep sum_p w_p q_p over an element (element) or over the body (nodal, with complete
/// node sums): sum_p w_p sum_i N_i(x_p) q_i = sum_i q_i sum_p N_i(x_p) w_p.
///
/// Several quantities ("channels") that share the weight are averaged in one call: one pass
/// over the points and, on several MPI ranks, ONE exchange of their node sums (each channel's
/// sums are the ones a call of its own would form, so the results are the same to the bit).

#include <mpi.h>

#include <vector>

#include "argine/core/Types.hpp"
#include "argine/transfer/CompensatedSum.hpp"

namespace argine {

class ActiveNodes;
class NodalExchange;
struct MaterialPoints;
struct PointShapes;

/// What a point takes part in (IncrementAveraging's values, as int for the kernels).
constexpr int kAverageNone = 0;
constexpr int kAverageElement = 1;
constexpr int kAverageNodal = 2;

/// Which averages some point may ask for, gathered over the materials (kAverage* modes), so
/// that AveragingScratch::allocateSums sizes only the sums that are read.
struct AveragingUse {
  bool elements = false, nodes = false;
  void add(int mode) {
    elements = elements || mode == kAverageElement;
    nodes = nodes || mode == kAverageNodal;
  }
  bool any() const { return elements || nodes; }
};

/// The inputs, outputs and sums of averagePointValues for `channels()` quantities.
struct AveragingScratch {
  /// (point, channel): kAverage* of the point in that channel.
  Kokkos::View<int**, Kokkos::LayoutLeft, MemSpace> mode_pc;
  /// Per point: its weight w_p (> 0 where some channel's mode is not none).
  Kokkos::View<Real*, MemSpace> weight_p;
  /// (point, channel): the quantity q_p, replaced by its average.
  Kokkos::View<Real**, Kokkos::LayoutLeft, MemSpace> value_pc;
  /// (element, 2c): sum w q of channel c; (element, 2c + 1): sum w. Empty: nodal only.
  /// With patches: one row per patch instead of per element.
  Kokkos::View<Real**, MemSpace> element_sums;
  /// Per element: the patch whose row of element_sums it adds to and reads (usePatches);
  /// empty: its own row.
  Kokkos::View<const int*, MemSpace> patch_e;
  /// With patches on several ranks: the ranks over which a patch's sums are completed (a
  /// patch may hold elements of several ranks); MPI_COMM_NULL: one rank.
  MPI_Comm patch_comm = MPI_COMM_NULL;
  /// Reproducible sums over the ranks: the patches' sums as values and the reduction's
  /// buffer, kept so that no step allocates them.
  std::vector<CompensatedReal> patch_parts;
  std::vector<Real> patch_buffer;
  /// The checkerboard filter of the element averages (useCheckerboardFilter): per row of
  /// element_sums its edge neighbours (AveragingPatches.hpp); empty: no filter.
  Kokkos::View<const int*, MemSpace> neighbour_start, neighbour_rows;
  Real neighbour_share = 0;                        ///< 1 / (2 n), n the most neighbours a row has
  Kokkos::View<Real**, MemSpace> filter_averages;  ///< (row, channel): the filter's q = S / W
  /// (node, 2c): sum N w q of channel c; (node, 2c + 1): sum N w. After averagePointValues
  /// (node, 2c) holds the node's average, the quotient of the two, at the active nodes.
  Kokkos::View<Real**, MemSpace> node_sums;
  /// Reproducible sums (transfer/CompensatedSum.hpp): the low parts of both sums, shaped as
  /// they are; empty: plain sums.
  LowParts<Kokkos::View<Real**, MemSpace>> element_lo, node_lo;

  /// Sums of `channels` quantities over `elements` elements (0 when only nodal averaging is
  /// used) and `nodes` nodes (0 when only element averaging is used).
  void allocateSums(int channels, int elements, int nodes);
  /// The same with rows only for the averages in `use` (a mesh's worth of element sums is
  /// zeroed at every call, and node sums are zeroed, exchanged and divided).
  void allocateSums(int channels, const AveragingUse& use, int elements, int nodes) {
    allocateSums(channels, use.elements ? elements : 0, use.nodes ? nodes : 0);
  }
  /// Element averages over patches of elements: `patch_e` maps each element to one of
  /// `patches` rows of the element sums (allocateSums sizes them by `patches` afterwards);
  /// on several ranks `comm` completes their sums. Call before allocateSums.
  void usePatches(Kokkos::View<const int*, MemSpace> patch_of_element, MPI_Comm comm) {
    patch_e = patch_of_element;
    patch_comm = comm;
  }
  /// The element averages filtered, after the sums, by an exchange between edge neighbours,
  ///   S_r <- S_r + sum_{s ~ r} min(W_r, W_s) (q_s - q_r) / (2 n),   q = S / W,
  /// n the most edge neighbours a row has, an empty row (W = 0) exchanging nothing. Each pair
  /// passes equal and opposite amounts, so sum_r S_r is kept; a uniform q stays uniform
  /// wherever the rows end or are part-filled (a surface that cuts the cells); each new q_r
  /// is a convex combination of q_r (weight >= 1/2) and its neighbours'. Where the weights are
  /// equal and a row has its n neighbours it is q_r / 2 + sum_{s ~ r} q_s / (2 n): on a grid of
  /// cells (n = 4) it maps the checkerboard pattern (-1)^(i + j) to zero and a smooth field q
  /// to q + h^2 lap(q) / 8.
  /// `start`, `rows`: each row's edge neighbours (RowNeighbours); the rows' sums must be
  /// complete on this rank (one rank, or rows of patches completed over the ranks).
  void useCheckerboardFilter(Kokkos::View<const int*, MemSpace> start,
                             Kokkos::View<const int*, MemSpace> rows, int most) {
    neighbour_start = start;
    neighbour_rows = rows;
    neighbour_share = most > 0 ? 0.5 / most : 0;
  }
  bool filtersElementAverages() const { return neighbour_start.extent(0) > 0; }
  /// The per-point views for `points` points (kept when the count is unchanged).
  void fitPoints(int points);
  /// Allocates (on) or empties (off) the low parts.
  void compensate(bool on);
  int channels() const { return static_cast<int>(node_sums.extent(1)) / 2; }
  bool compensated() const { return node_lo[0].extent(0) > 0 || element_lo[0].extent(0) > 0; }
  /// Whether some channel may average over nodes (the node sums have rows).
  bool nodal() const { return node_sums.extent(0) > 0; }
};

/// The element and node sums of every channel (element_sums, node_sums), complete over the
/// ranks and folded when compensated: the first half of averagePointValues, for a caller that
/// combines the channels' node averages itself (LiquidHeadStabilisation's linear fit).
void sumPointValues(const MaterialPoints& points, const PointShapes& shapes,
                    const ActiveNodes& active, AveragingScratch& scratch, NodalExchange* exchange);

/// node_sums(i, 2c) <- sum N w q / sum N w, channel c's average at every active node (after
/// sumPointValues): one division a node and channel instead of one a point, node and channel
/// where the points read the averages.
void divideNodeSums(const ActiveNodes& active, const AveragingScratch& scratch);

/// Replaces value_pc(p, c) by its element or nodal average (file comment of the header) at
/// the points with mode_pc(p, c) != none, for every channel c of `scratch`. Elements and
/// nodes see only the points of the same mode in the same channel. On several ranks
/// `exchange` completes the node sums of all channels in one exchange (collective).
void averagePointValues(const MaterialPoints& points, const PointShapes& shapes,
                        const ActiveNodes& active, AveragingScratch& scratch,
                        NodalExchange* exchange);

}  // namespace argine
