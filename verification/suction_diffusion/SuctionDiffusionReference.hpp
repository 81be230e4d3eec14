#pragma once
/// @file SuctionDiffusionReference.hpp
/// References of V2, suction diffusion in a rigid column (thesis Ch. 4 Sec. 2.2.1, Fig. 4.2;
/// VERIFICATION.md V2). Column of height h, impervious base (y = 0), suction s = 0 imposed
/// at the top (y = h) from t = 0, initial suction s0, gravity off, constant conductivity k,
/// linear SWRC S_L = 1 - a_v s. Signs: the thesis' suction is its tension-positive p_L;
/// here s = -p_L (argine's p_L is compression positive).
///
/// 1. The series of Eq. 4.17 (DiffusionSeries.hpp) with the time factor T = C_i t / h^2
///    (4.18) and the infiltration coefficient of Eq. 4.19,
///        C_i = k / (n rho_L g (S_L/K_L + a_v)).
///    C_i is the diffusivity of the linearised COMPLETE mass balance (4.12) with a rigid
///    skeleton: n rho_L (S_L/K_L + a_v) dp_L/dt = div(rho_L k/(rho_L g) grad p_L). It holds
///    S_L, which varies between S_L(s0) and 1 across the column: it is evaluated at the
///    middle of that range, S_ref = 1 - a_v s0/2. (Case a: C_i differs by +-0.3 % between
///    the ends; cases b and c by +-0.14 % and +-0.003 %.)
/// 2. A cross-check of that linearisation: the NON-linear equation the model solves,
///        n d(S_L(p) rho_L(p))/dt = d/dy((k/g) dp/dy),  rho_L = rho_L0 exp(p/K_L) (4.13),
///    (argine's drag n S_L rho_L g/k makes the liquid mass flux rho_L n S_L w = -(k/g) grad
///    p exactly), integrated by conservative finite volumes with explicit steps on a fine
///    grid. Reported beside the series, never used for the bound.

#include <algorithm>
#include <cmath>
#include <vector>

#include "DiffusionSeries.hpp"

namespace argine::verification {

struct SuctionDiffusionParameters {
  double height = 1.0;                 ///< h (m)
  double initial_suction = 5.0e5;      ///< s0 (Pa)
  double slope = 1.0e-6;               ///< a_v (1/Pa): S_L = 1 - a_v s
  double porosity = 0.3;               ///< n (-)
  double liquid_density = 1000.0;      ///< rho_L0 (kg/m^3)
  double liquid_bulk_modulus = 8.0e7;  ///< K_L (Pa)
  double conductivity = 4.905e-4;      ///< k (m/s)
  double gravity = 9.81;               ///< g in k = kappa rho_L g / mu_L (m/s^2)
};

class SuctionDiffusionReference {
 public:
  explicit SuctionDiffusionReference(const SuctionDiffusionParameters& parameters)
      : p_(parameters) {}

  const SuctionDiffusionParameters& parameters() const { return p_; }
  /// S_L(s) of the linear SWRC (5.6 / 4.27 with S_max = 1, S_min = 0).
  double saturation(double suction) const {
    return std::max(0.0, 1.0 - p_.slope * std::max(0.0, suction));
  }
  /// S_ref = S_L(s0/2), where C_i is evaluated.
  double referenceSaturation() const { return saturation(0.5 * p_.initial_suction); }
  /// C_i of Eq. 4.19 at a degree of saturation S (m^2/s).
  double infiltrationCoefficient(double saturation) const {
    return p_.conductivity / (p_.porosity * p_.liquid_density * p_.gravity *
                              (saturation / p_.liquid_bulk_modulus + p_.slope));
  }
  /// C_i at S_ref (m^2/s).
  double infiltrationCoefficient() const { return infiltrationCoefficient(referenceSaturation()); }
  /// t (s) of the time factor T (4.18).
  double timeOfFactor(double factor) const {
    return factor * p_.height * p_.height / infiltrationCoefficient();
  }
  /// s/s0 at height y (m, from the base), Eq. 4.17.
  double normalisedSuction(double y, double factor) const {
    return drainedTopSeries(y / p_.height, factor);
  }

 private:
  SuctionDiffusionParameters p_;
};

/// The non-linear cross-check (item 2 above): cells of equal height, unknown the liquid
/// mass per unit volume m = n S_L(p) rho_L(p) in each cell; the top face sees p = 0 half a
/// cell above the top centre, the base is closed. Explicit Euler in m with
/// dt = 0.2 dy^2 / C_max, then p from m by safeguarded Newton.
class NonlinearSuctionDiffusion {
 public:
  NonlinearSuctionDiffusion(const SuctionDiffusionParameters& parameters, int cells)
      : p_(parameters), cells_(cells), dy_(parameters.height / cells) {
    pressure_.assign(cells_, -p_.initial_suction);
    mass_.resize(cells_);
    for (int i = 0; i < cells_; ++i) mass_[i] = liquidContent(pressure_[i]);
    // Largest diffusivity k/(g n rho (a_v + S/K)) over the range: smallest S and rho.
    const double rho = density(-p_.initial_suction);
    const double s = saturationOf(-p_.initial_suction);
    const double c_max = p_.conductivity /
                         (p_.gravity * p_.porosity * rho * (p_.slope + s / p_.liquid_bulk_modulus));
    step_ = 0.2 * dy_ * dy_ / c_max;
  }

  /// Advances to time t (s), landing on it exactly.
  void advanceTo(double t) {
    std::vector<double> flux(cells_ + 1);  // upward mass flux through face i (kg/m^2/s)
    const double a = p_.conductivity / p_.gravity;
    while (time_ < t - 1e-15 * t) {
      const double dt = std::min(step_, t - time_);
      flux[0] = 0;  // closed base
      for (int i = 1; i < cells_; ++i) flux[i] = -a * (pressure_[i] - pressure_[i - 1]) / dy_;
      flux[cells_] = -a * (0.0 - pressure_[cells_ - 1]) / (0.5 * dy_);
      for (int i = 0; i < cells_; ++i) {
        mass_[i] -= dt * (flux[i + 1] - flux[i]) / dy_;
        pressure_[i] = pressureOfContent(mass_[i], pressure_[i]);
      }
      time_ += dt;
    }
  }

  /// s/s0 at height y, linear between cell centres, 0 at the top face.
  double normalisedSuction(double y) const {
    const double x = y / dy_ - 0.5;  // cell-centre coordinate
    double p;
    if (x <= 0) {
      p = pressure_.front();
    } else if (x >= cells_ - 1) {
      const double w = (x - (cells_ - 1)) / 0.5;  // towards the top face
      p = (1 - w) * pressure_.back();
    } else {
      const int i = static_cast<int>(x);
      const double w = x - i;
      p = (1 - w) * pressure_[i] + w * pressure_[i + 1];
    }
    return -p / p_.initial_suction;
  }

 private:
  double density(double pressure) const {
    return p_.liquid_density * std::exp(pressure / p_.liquid_bulk_modulus);
  }
  double saturationOf(double pressure) const {
    return std::max(0.0, 1.0 - p_.slope * std::max(0.0, -pressure));
  }
  double liquidContent(double pressure) const {
    return p_.porosity * saturationOf(pressure) * density(pressure);
  }
  /// p with n S_L(p) rho_L(p) = m (increasing in p); Newton from `guess`.
  double pressureOfContent(double m, double guess) const {
    double p = guess;
    for (int iteration = 0; iteration < 50; ++iteration) {
      const double rho = density(p), s = saturationOf(p);
      const double slope_s = p < 0 ? p_.slope : 0.0;  // dS/dp
      const double derivative = p_.porosity * rho * (slope_s + s / p_.liquid_bulk_modulus);
      const double change = (liquidContent(p) - m) / derivative;
      p -= change;
      if (std::fabs(change) < 1e-10 * (1 + std::fabs(p))) break;
    }
    return p;
  }

  SuctionDiffusionParameters p_;
  int cells_;
  double dy_;
  double step_ = 0;
  double time_ = 0;
  std::vector<double> pressure_;
  std::vector<double> mass_;
};

}  // namespace argine::verification
