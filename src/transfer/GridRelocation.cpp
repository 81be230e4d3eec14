#include "GridRelocation.hpp"

#include "argine/mesh/GridShapes.hpp"
#include "argine/mesh/Mesh.hpp"
#include "argine/points/MaterialPoints.hpp"

namespace argine {

RelocationCounts relocateOnGrid(const Mesh& mesh, Real tolerance,
                                Kokkos::View<const int*, MemSpace> cell_element,
                                MaterialPoints& points, PointShapes& shapes) {
  shapes.prepareGrid(points.count, mesh.structured);
  const StructuredGrid grid = mesh.structured;
  const ShapeFamily family = shapes.family;
  const auto grid_p = shapes.grid_p;
  const auto element_p = points.element;
  const auto local_p = points.local;
  const auto position_p = points.position;
  const auto displacement_p = points.displacement;
  const auto volume0_p = points.initial_volume;
  // The locator's tolerance (local coordinates, 2 per cell) in cells.
  const Real slack = 0.5 * tolerance;
  RelocationCounts counts;
  int restencilled = 0;
  Kokkos::parallel_reduce(
      "relocate_on_grid", Kokkos::RangePolicy<ExecSpace>(0, points.count),
      KOKKOS_LAMBDA(const int p, int& outside, int& moved, int& changed) {
        // The point kept clear of the grid's edges first (clearOfGridEdges, as
        // keepPointsClearOfGridEdges does on the element route), in the same pass: its xi is
        // the relocation's unless it moved (then from the new position, as a second pass would
        // compute it).
        const Real l = gimpHalfWidth(volume0_p(p), grid);
        Real xi[kDim];  // cells from the grid's origin
        for (int d = 0; d < kDim; ++d) {
          xi[d] = (position_p(p, d) - grid.origin[d]) / grid.spacing[d];
          const Real kept = clearOfGridEdges(xi[d], grid.cells[d], l);
          if (kept == xi[d]) continue;  // (not for NaN: as keepPointsClearOfGridEdges)
          const Real shift = (kept - xi[d]) * grid.spacing[d];
          position_p(p, d) += shift;
          displacement_p(p, d) += shift;
          xi[d] = (position_p(p, d) - grid.origin[d]) / grid.spacing[d];
        }
        int cell[kDim] = {0, 0};  // (set when inside)
        bool inside = true;
        for (int d = 0; d < kDim; ++d) {
          // within the tolerance of the grid (false for NaN)
          inside = inside && xi[d] >= -slack && xi[d] <= grid.cells[d] + slack;
          if (!inside) break;
          // The cell holding xi; of two cells that both hold it within the tolerance (xi on
          // their common line) the lower one, as the locator chooses the lowest element
          // index (element = cell on a structured mesh: cell_element).
          int c = static_cast<int>(Kokkos::Experimental::floor(xi[d]));
          if (xi[d] - c < slack) --c;
          cell[d] = c < 0 ? 0 : (c >= grid.cells[d] ? grid.cells[d] - 1 : c);
        }
        const int old = element_p(p);
        const int e = inside ? cell_element(cell[0] + grid.cells[0] * cell[1]) : -1;
        element_p(p) = e;
        if (e != old) ++moved;
        TensorShape& shape = grid_p(p);
        if (e < 0) {
          ++outside;
          setLostTensorShape(shape);
          return;
        }
        // Quad4 local coordinates (-1 at the cell's lower line, 1 at its upper)
        for (int d = 0; d < kDim; ++d) local_p(p, d) = 2 * (xi[d] - cell[d]) - 1;
        const int old_x = shape.line[0][0], old_y = shape.line[1][0];
        const Real half_width = family == ShapeFamily::Gimp ? l : Real(0);
        for (int d = 0; d < kDim; ++d) {
          GridStencil1D s;
          gridStencil1D(family, xi[d], grid.cells[d], grid.spacing[d], half_width, s);
          for (int k = 0; k < kGridStencil; ++k) {
            shape.line[d][k] = s.line[k];
            shape.value[d][k] = s.value[k];
            shape.gradient[d][k] = s.gradient[k];
          }
        }
        if (shape.line[0][0] != old_x || shape.line[1][0] != old_y) ++changed;
      },
      counts.lost, counts.changed_element, restencilled);
  counts.changed_element += restencilled;  // the active nodes follow the stencils
  return counts;
}

}  // namespace argine
