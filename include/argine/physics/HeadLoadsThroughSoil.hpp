#pragma once
/// @file HeadLoadsThroughSoil.hpp
/// `Hydraulic Loads: through the soil`: a total head's pressure loads the soil through its
/// points' volume instead of along a surface (doc/theory.md Sec. 5.5, "Loads through the
/// soil").
///
/// The river's load on the liquid (4.41) and the mixture (4.42) is -oint N_i p^ n dGamma
/// over the wetted surface. With p^ the head's hydrostatic field continued into the soil
/// (HeadPressureField: continuous, zero above the level), Gauss's theorem makes it a volume
/// integral, and the points' quadrature of it is
///     f_i = -sum_p V_p (p^(x_p) grad N_i(x_p) + N_i(x_p) grad p^(x_p)),
/// with the N_i the step's P2G uses. Added to the internal forces of the same points, it
/// turns sigma into sigma + p^ I (p_L into p_L - p^) and the weight into the buoyant weight: a
/// submerged ground at rest is loaded as a dry one, and the surface's load meets the points'
/// stresses exactly where their domains end, whether the surface lies on cell edges or
/// across cells, at rest or moving through the grid. For uGIMP in 1D, p^ linear, the sum is
/// exactly N_i(surface) p^(surface) at the surface's nodes and 0 inside.
///
/// Where the continued field reaches soil surface the river does not wet (below the level,
/// outside the condition's zone), it would load it too: the solver requires such free sides
/// to be fixed and sealed along their normal (a symmetry axis, a base), where the load does
/// no work.

#include "argine/boundary/HydraulicAlgebra.hpp"
#include "argine/core/Types.hpp"

namespace argine {

struct MaterialPoints;
struct PointShapes;
struct PointBorneLoadFields;

/// Adds f_i above into fields.spread_i (mixture components, then liquid, as PointBorneLoads):
/// the mixture's with field.mixture over every point, the liquid's with field.liquid over the
/// liquid-carrying points (liquid_m per material). Zero `fields` first; sum over the ranks
/// after (sumPointBorneLoadsAtSharedNodes), binned when fields.compensated().
void spreadHeadLoadsThroughSoil(const HeadPressureField& field, const MaterialPoints& points,
                                const PointShapes& shapes,
                                const Kokkos::View<const int*, MemSpace>& liquid_m,
                                PointBorneLoadFields& fields);

}  // namespace argine
