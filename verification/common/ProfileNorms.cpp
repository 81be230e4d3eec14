#include "ProfileNorms.hpp"

#include <array>
#include <cmath>
#include <map>
#include <stdexcept>

namespace argine::verification {

double weightedNorm(const std::vector<double>& values, const std::vector<double>& weights) {
  if (values.size() != weights.size())
    throw std::invalid_argument("weightedNorm: values and weights differ in length");
  double sum = 0;
  for (std::size_t p = 0; p < values.size(); ++p) sum += weights[p] * values[p] * values[p];
  return std::sqrt(sum);
}

ProfileError profileError(const std::vector<double>& numerical,
                          const std::vector<double>& reference, const std::vector<double>& initial,
                          const std::vector<double>& weights) {
  const std::size_t n = weights.size();
  if (numerical.size() != n || reference.size() != n || initial.size() != n)
    throw std::invalid_argument("profileError: profiles differ in length");
  std::vector<double> error(n), change(n);
  ProfileError result;
  for (std::size_t p = 0; p < n; ++p) {
    error[p] = numerical[p] - reference[p];
    change[p] = reference[p] - initial[p];
    result.max_abs = std::max(result.max_abs, std::fabs(error[p]));
  }
  const double error_norm = weightedNorm(error, weights);
  result.relative = error_norm / weightedNorm(reference, weights);
  result.of_change = error_norm / weightedNorm(change, weights);
  return result;
}

double elementMeanError(const std::vector<double>& numerical, const std::vector<double>& reference,
                        const std::vector<double>& weights, const std::vector<int>& element) {
  const std::size_t n = weights.size();
  if (numerical.size() != n || reference.size() != n || element.size() != n)
    throw std::invalid_argument("elementMeanError: profiles differ in length");
  std::map<int, std::array<double, 3>> sums;  // element -> V, V f_num, V f_ref
  for (std::size_t p = 0; p < n; ++p) {
    auto& sum = sums[element[p]];
    sum[0] += weights[p];
    sum[1] += weights[p] * numerical[p];
    sum[2] += weights[p] * reference[p];
  }
  std::vector<double> error, exact, volume;
  for (const auto& [e, sum] : sums) {
    error.push_back((sum[1] - sum[2]) / sum[0]);
    exact.push_back(sum[2] / sum[0]);
    volume.push_back(sum[0]);
  }
  return weightedNorm(error, volume) / weightedNorm(exact, volume);
}

double observedOrder(double coarse_error, double fine_error, double ratio) {
  return std::log(coarse_error / fine_error) / std::log(ratio);
}

}  // namespace argine::verification
