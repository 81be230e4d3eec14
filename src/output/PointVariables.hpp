#pragma once
/// @file PointVariables.hpp
/// (private to the output room) The table of point variables written to the points file:
/// one name and one function per variable, reading host copies of the point fields.

#include <string>
#include <vector>

#include "argine/points/MaterialPoints.hpp"

namespace argine {

/// Host copies of the point fields the points file shows, and each point's reference
/// position in the file (for displ_ = position - reference).
struct PointSnapshot {
  template <class T>
  using HostView = typename MaterialPoints::View<T>::HostMirror;

  explicit PointSnapshot(const MaterialPoints& points);

  HostView<int*> id;
  HostView<int*> material;
  HostView<Real* [kDim]> position;
  HostView<Real* [kDim]> displacement;
  HostView<Real* [kDim]> velocity_solid;
  HostView<Real* [kDim]> velocity_liquid;
  HostView<Real*> volume;
  HostView<Real*> porosity;
  HostView<Real*> pressure_liquid;
  HostView<Real*> saturation;
  HostView<Real*> conductivity;
  HostView<Real* [kStressComponents]> stress_effective;
  HostView<Real*> deviatoric_strain;
  HostView<Real*> plastic_strain;
  HostView<int*> plastic_state;
  std::vector<Real> reference_x;  ///< reference x of each point, filled by the points file
  std::vector<Real> reference_y;  ///< reference y of each point, filled by the points file
};

/// One nodal variable of the points file.
struct PointVariable {
  const char* name;                              ///< exodus variable name
  Real (*value)(const PointSnapshot& s, int p);  ///< its value at point p
};

/// All point variables, in file order.
const std::vector<PointVariable>& pointVariables();

}  // namespace argine
