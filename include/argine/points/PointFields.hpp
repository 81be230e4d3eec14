#pragma once
/// @file PointFields.hpp
/// One list of every per-point View of MaterialPoints, for code that must treat all
/// fields alike (sorting, compaction, copying, checkpoints). A static_assert compares the
/// list with sizeof(MaterialPoints), so a field added to MaterialPoints but not here stops
/// the build instead of being silently left unsorted.

#include <cstddef>

#include "argine/points/MaterialPoints.hpp"

namespace argine {

/// X-macro of all per-point fields of MaterialPoints (everything except `count`).
// clang-format off
#define ARGINE_MATERIAL_POINT_FIELDS(FIELD)                                             \
  FIELD(id) FIELD(element) FIELD(local) FIELD(position) FIELD(initial_position)          \
  FIELD(material) FIELD(displacement) FIELD(velocity_solid) FIELD(velocity_liquid)       \
  FIELD(affine_velocity_solid) FIELD(affine_velocity_liquid) FIELD(rest_reference)        \
  FIELD(volume) FIELD(initial_volume) FIELD(mass_solid) FIELD(mass_liquid)               \
  FIELD(porosity) FIELD(separation) FIELD(pressure_liquid) FIELD(density_liquid)        \
  FIELD(saturation)                                                                       \
  FIELD(conductivity) FIELD(stress_effective) FIELD(strain) FIELD(deviatoric_strain)     \
  FIELD(plastic_strain) FIELD(plastic_state)
// clang-format on

namespace detail {
#define ARGINE_FIELD_BYTES(name) +sizeof(MaterialPoints::name)
/// Bytes of all listed fields.
inline constexpr std::size_t kListedPointFieldBytes =
    0 ARGINE_MATERIAL_POINT_FIELDS(ARGINE_FIELD_BYTES);
#undef ARGINE_FIELD_BYTES
/// Bytes taken by `count` with its padding up to the first View.
inline constexpr std::size_t kPointCountBytes =
    (sizeof(int) + alignof(MaterialPoints) - 1) / alignof(MaterialPoints) * alignof(MaterialPoints);
}  // namespace detail

static_assert(sizeof(MaterialPoints) == detail::kPointCountBytes + detail::kListedPointFieldBytes,
              "MaterialPoints has a member that ARGINE_MATERIAL_POINT_FIELDS does not list: add it "
              "to include/argine/points/PointFields.hpp");

/// Calls visit(name, view) for every per-point View of `points` (MaterialPoints, const or
/// not), in declaration order; name is the member name ("stress_effective").
template <class Points, class Visitor>
void forEachPointField(Points& points, Visitor&& visit) {
#define ARGINE_VISIT_FIELD(name) visit(#name, points.name);
  ARGINE_MATERIAL_POINT_FIELDS(ARGINE_VISIT_FIELD)
#undef ARGINE_VISIT_FIELD
}

}  // namespace argine
