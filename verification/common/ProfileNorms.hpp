#pragma once
/// @file ProfileNorms.hpp
/// Error norms of a numerical profile against a reference profile, both sampled at the
/// material points (weights = point volumes, so the sums approximate integrals over the
/// column).

#include <vector>

namespace argine::verification {

/// The two relative L2 errors of one isochrone (see doc/verification.md, "Error norms"):
///   relative  = ||f_num - f_ref|| / ||f_ref||          (error against what is left)
///   of_change = ||f_num - f_ref|| / ||f_ref - f_init|| (error against what has changed)
/// with ||g||^2 = sum_p V_p g_p^2. `relative` is strict late (small f_ref), `of_change`
/// strict early (little has changed yet); `governing` is the larger of the two.
struct ProfileError {
  double relative = 0;   ///< ||f_num - f_ref|| / ||f_ref||
  double of_change = 0;  ///< ||f_num - f_ref|| / ||f_ref - f_init||
  double max_abs = 0;    ///< max_p |f_num - f_ref| (units of f)
  double governing() const { return relative > of_change ? relative : of_change; }
};

/// Weighted L2 norm sqrt(sum w g^2).
double weightedNorm(const std::vector<double>& values, const std::vector<double>& weights);

/// The errors of `numerical` against `reference`, `initial` being the profile at t = 0 (all
/// four the same length). std::invalid_argument for mismatched lengths.
ProfileError profileError(const std::vector<double>& numerical,
                          const std::vector<double>& reference, const std::vector<double>& initial,
                          const std::vector<double>& weights);

/// The relative L2 error of the element means: numerical and reference values are first
/// averaged (volume-weighted) over the points of each element (`element` of each point),
/// then compared as ||mean_num - mean_ref|| / ||mean_ref|| with element volumes as weights.
/// A diagnostic: it is blind to any variation inside an element.
double elementMeanError(const std::vector<double>& numerical, const std::vector<double>& reference,
                        const std::vector<double>& weights, const std::vector<int>& element);

/// Observed order of convergence between two meshes whose element sizes differ by `ratio`:
/// log(e_coarse / e_fine) / log(ratio).
double observedOrder(double coarse_error, double fine_error, double ratio);

}  // namespace argine::verification
