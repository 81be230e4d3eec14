#pragma once
/// @file PointLocator.hpp
/// Finds the background element containing a point and the point's local coordinates.
///
/// Search order: the hint element (a point's current element), then its edge neighbours,
/// then a uniform grid of bins over the mesh bounding box, each bin listing (CSR) the
/// elements whose bounding boxes overlap it. Works on any valid tri3/quad4 mesh, including
/// non-convex domains and domains with holes: a point is found only if an element contains
/// it, never by walking across empty space.
///
/// Ties: a point on a shared edge or vertex belongs to the lowest-index element containing
/// it (within the tolerance), whatever the hint, so results are deterministic. A point
/// strictly inside an element (margin above the tolerance) is accepted at once.
///
/// The locator holds only Kokkos Views and scalars: copy it by value into kernels.

#include "argine/core/Types.hpp"
#include "argine/mesh/Mesh.hpp"
#include "argine/mesh/ShapeFunctions.hpp"

namespace argine {

class PointLocator {
 public:
  PointLocator() = default;

  /// Builds edge adjacency and the bins (host work, once per mesh; the mesh must have
  /// passed checkMeshQuality). Shares the mesh's coordinate and connectivity Views, so
  /// the locator must be rebuilt if the mesh geometry changes.
  explicit PointLocator(const Mesh& mesh);

  /// Element containing x (and its local coordinates in xi), or -1 when x is outside the
  /// mesh (xi is then left unchanged). `hint` is the element to try first (-1: none).
  KOKKOS_INLINE_FUNCTION int locate(const Real x[kDim], Real xi[kDim], int hint = -1) const {
    return type_ == ElementType::Tri3 ? locateWith<Tri3>(x, xi, hint)
                                      : locateWith<Quad4>(x, xi, hint);
  }

  /// Updates elements and local coordinates from positions (current element as hint).
  /// Points outside the mesh get element -1 (local unchanged). Returns their number.
  int locateAll(const Kokkos::View<const Real* [kDim], MemSpace>& positions,
                const Kokkos::View<int*, MemSpace>& elements,
                const Kokkos::View<Real* [kDim], MemSpace>& local) const;

  /// Same for a set of material points (MaterialPoints or anything with position, element
  /// and local Views): points.element and points.local from points.position.
  template <class Points>
  int locateAll(Points& points) const {
    return locateAll(points.position, points.element, points.local);
  }

  /// Edge adjacency (elements x sides): the element across side s (local nodes s, s+1),
  /// -1 on the mesh boundary. Built once; also used for boundary detection.
  const Kokkos::View<const int**, MemSpace>& elementNeighbours() const { return neighbours_; }

  /// Containment tolerance in local coordinates (dimensionless): 1e-12, raised when large
  /// absolute coordinates make round-off in the local coordinates larger than that.
  KOKKOS_INLINE_FUNCTION Real tolerance() const { return tolerance_; }

  /// Number of bins along x and y (for diagnostics).
  int binCount(int axis) const { return bins_[axis]; }

 private:
  /// Local coordinates of x in `element` and its margin (Shape::margin); a very negative
  /// margin when x is outside the element's bounding box or the map fails.
  template <class Shape>
  KOKKOS_INLINE_FUNCTION Real marginIn(int element, const Real x[kDim], Real xi[kDim]) const {
    constexpr Real kFar = -1e300;
    if (x[0] < boxes_(element, 0) || x[1] < boxes_(element, 1) || x[0] > boxes_(element, 2) ||
        x[1] > boxes_(element, 3))
      return kFar;
    Real X[Shape::kNodes][kDim];
    gatherElementCoordinates<Shape>(coordinates_, connectivity_, element, X);
    if (!mapToLocal<Shape>(X, x, xi)) return kFar;
    const Real margin = Shape::margin(xi);
    return margin == margin ? margin : kFar;  // NaN -> outside
  }

  /// Bin index along `axis` of a coordinate inside the bounding box.
  KOKKOS_INLINE_FUNCTION int binOf(Real coordinate, int axis) const {
    const int i = static_cast<int>((coordinate - box_min_[axis]) * inverse_bin_size_[axis]);
    return i < 0 ? 0 : (i >= bins_[axis] ? bins_[axis] - 1 : i);
  }

  template <class Shape>
  KOKKOS_INLINE_FUNCTION int locateWith(const Real x[kDim], Real xi[kDim], int hint) const {
    Real trial[kDim] = {0.0, 0.0};
    // 1. The hint and its neighbours: most points stay in or move next to their element.
    if (hint >= 0 && hint < num_elements_) {
      if (marginIn<Shape>(hint, x, trial) >= tolerance_) {
        xi[0] = trial[0];
        xi[1] = trial[1];
        return hint;
      }
      for (int s = 0; s < Shape::kNodes; ++s) {
        const int next = neighbours_(hint, s);
        if (next >= 0 && marginIn<Shape>(next, x, trial) >= tolerance_) {
          xi[0] = trial[0];
          xi[1] = trial[1];
          return next;
        }
      }
    }
    // 2. The bin of x. Elements are listed in increasing index within a bin, so the first
    //    element containing x within the tolerance is the lowest-index one; a strictly
    //    containing element is unique and returned at once.
    if (num_elements_ == 0 ||
        !(x[0] >= box_min_[0] && x[0] <= box_max_[0] && x[1] >= box_min_[1] && x[1] <= box_max_[1]))
      return -1;  // also catches NaN coordinates
    const int bin = binOf(x[1], 1) * bins_[0] + binOf(x[0], 0);
    int found = -1;
    Real found_xi[kDim] = {0.0, 0.0};
    for (int k = bin_offsets_(bin); k < bin_offsets_(bin + 1); ++k) {
      const int element = bin_elements_(k);
      const Real margin = marginIn<Shape>(element, x, trial);
      if (margin >= tolerance_) {
        xi[0] = trial[0];
        xi[1] = trial[1];
        return element;
      }
      if (margin >= -tolerance_ && found < 0) {
        found = element;
        found_xi[0] = trial[0];
        found_xi[1] = trial[1];
      }
    }
    if (found >= 0) {
      xi[0] = found_xi[0];
      xi[1] = found_xi[1];
    }
    return found;
  }

  ElementType type_ = ElementType::Tri3;
  int num_elements_ = 0;
  Kokkos::View<const Real* [kDim], MemSpace> coordinates_;  ///< mesh node coordinates
  Kokkos::View<const int**, MemSpace> connectivity_;        ///< mesh connectivity
  Kokkos::View<const int**, MemSpace> neighbours_;          ///< edge adjacency
  /// Element bounding boxes (xmin, ymin, xmax, ymax), enlarged by the tolerance.
  Kokkos::View<const Real* [4], MemSpace> boxes_;
  Kokkos::View<const int*, MemSpace> bin_offsets_;   ///< CSR offsets, bins + 1 entries
  Kokkos::View<const int*, MemSpace> bin_elements_;  ///< CSR element lists
  Real box_min_[kDim] = {0.0, 0.0};                  ///< lower corner of the binned box
  Real box_max_[kDim] = {0.0, 0.0};                  ///< upper corner of the binned box
  Real inverse_bin_size_[kDim] = {0.0, 0.0};         ///< 1 / bin width along x and y
  int bins_[kDim] = {0, 0};                          ///< bins along x and y
  Real tolerance_ = 1e-12;                           ///< containment tolerance (local units)
};

}  // namespace argine
