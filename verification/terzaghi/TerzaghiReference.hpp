#pragma once
/// @file TerzaghiReference.hpp
/// The exact solution of Terzaghi's 1D consolidation (VERIFICATION.md V1) with a weakly
/// compressible pore liquid: a column of height h on an impermeable base (y = 0), drained at
/// the top (y = h), loaded suddenly at t = 0 by a total stress q.
///
///   m_v = 1/E_oed,  c_v = k / (rho_L g (m_v + n/K_L)),  T = c_v t / h^2,
///   p0 = q m_v / (m_v + n/K_L)                       (undrained response to the load)
///   p/p0 = (4/pi) sum_j (-1)^(j-1)/(2j-1) cos((2j-1) pi y/(2h)) exp(-(2j-1)^2 pi^2 T/4)
///   U(T) = 1 - (8/pi^2) sum_j 1/(2j-1)^2 exp(-(2j-1)^2 pi^2 T/4)
/// Settlement (compression positive): the skeleton strain is m_v (q - p), so
///   w(t) = h m_v (q - p0 (1 - U)) = w_0 + (w_inf - w_0) U,  w_0 = h m_v (q - p0),
///   w_inf = h m_v q.
/// g = 9.81 m/s^2 is the g that converts between k and the drag (as argine does).

#include "DiffusionSeries.hpp"

namespace argine::verification {

struct TerzaghiParameters {
  double height = 1.0;                 ///< h (m), drainage length
  double load = 1.0e4;                 ///< q (Pa), sudden total stress on top
  double constrained_modulus = 1.0e7;  ///< E_oed (Pa); nu = 0 makes it Young's modulus
  double porosity = 0.4;               ///< n (-)
  double liquid_bulk_modulus = 2.2e9;  ///< K_L (Pa)
  double liquid_density = 1000.0;      ///< rho_L (kg/m^3)
  double conductivity = 1.0e-5;        ///< k (m/s)
  double gravity = 9.81;               ///< g in rho_L g / k (m/s^2)
};

class TerzaghiReference {
 public:
  explicit TerzaghiReference(const TerzaghiParameters& parameters) : p_(parameters) {}

  const TerzaghiParameters& parameters() const { return p_; }
  /// m_v = 1/E_oed (1/Pa).
  double compressibility() const { return 1.0 / p_.constrained_modulus; }
  /// n/K_L (1/Pa), the storage of the pore liquid.
  double liquidStorage() const { return p_.porosity / p_.liquid_bulk_modulus; }
  /// c_v (m^2/s).
  double consolidationCoefficient() const {
    return p_.conductivity /
           (p_.liquid_density * p_.gravity * (compressibility() + liquidStorage()));
  }
  /// p0 (Pa), the initial excess pore pressure.
  double initialPressure() const {
    return p_.load * compressibility() / (compressibility() + liquidStorage());
  }
  /// t (s) of the time factor T.
  double timeOfFactor(double factor) const {
    return factor * p_.height * p_.height / consolidationCoefficient();
  }
  /// T of the time t (s).
  double factorOfTime(double time) const {
    return consolidationCoefficient() * time / (p_.height * p_.height);
  }

  /// p/p0 at height y (m, from the base) and time factor T > 0 (DiffusionSeries.hpp).
  double normalisedPressure(double y, double factor) const {
    return drainedTopSeries(y / p_.height, factor);
  }
  /// Excess pore pressure p (Pa) at y and T.
  double pressure(double y, double factor) const {
    return initialPressure() * normalisedPressure(y, factor);
  }

  /// Degree of consolidation U(T) (DiffusionSeries.hpp).
  double degreeOfConsolidation(double factor) const { return drainedTopDegree(factor); }

  /// Immediate (undrained) settlement w_0 (m).
  double immediateSettlement() const {
    return p_.height * compressibility() * (p_.load - initialPressure());
  }
  /// Final settlement w_inf (m).
  double finalSettlement() const { return p_.height * compressibility() * p_.load; }
  /// Settlement w(T) (m).
  double settlement(double factor) const {
    return immediateSettlement() +
           (finalSettlement() - immediateSettlement()) * degreeOfConsolidation(factor);
  }

 private:
  TerzaghiParameters p_;
};

}  // namespace argine::verification
