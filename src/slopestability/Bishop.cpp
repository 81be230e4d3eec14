#include "argine/slopestability/Bishop.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace argine {

namespace {

/// The sign that makes the driving moment sum W sin alpha non-negative: -1 mirrors a mass
/// sliding towards +x into one sliding towards -x.
Real slideSign(const std::vector<Slice>& slices, Real external_driving) {
  Real driving = external_driving;
  for (const Slice& s : slices) driving += s.weight * std::sin(s.base_angle);
  return driving < 0 ? Real(-1) : Real(1);
}

Real drivingSum(const std::vector<Slice>& slices, Real sign, Real external_driving) {
  Real driving = sign * external_driving;
  for (const Slice& s : slices) driving += s.weight * std::sin(sign * s.base_angle);
  return driving;
}

/// m_alpha = cos(alpha) (1 + tan(alpha) tan(phi') / F) from the three functions' values.
Real mAlpha(Real cos_alpha, Real tan_alpha, Real tan_phi, Real factor) {
  return cos_alpha * (1 + tan_alpha * tan_phi / factor);
}

/// What Bishop's iteration reads of one slice and does not change with F: the cosine and
/// tangent of its (mirrored) base angle, tan phi', c b (c = c' + S) and the effective weight
/// (W - u b)+. Taken once a slice instead of once an iteration (three calls of the
/// library's trigonometry a slice and iteration were most of a factor-of-safety search).
struct BishopSliceTerms {
  Real cos_alpha, tan_alpha, tan_phi, cohesion_width, effective_weight;
};

std::vector<BishopSliceTerms> bishopSliceTerms(const std::vector<Slice>& slices, Real sign) {
  std::vector<BishopSliceTerms> terms;
  terms.reserve(slices.size());
  for (const Slice& s : slices) {
    const Real alpha = sign * s.base_angle;
    const Real u = std::max(s.pore_pressure, Real(0));
    terms.push_back({std::cos(alpha), std::tan(alpha), std::tan(s.friction_angle),
                     s.apparentCohesion() * s.width, std::max(s.weight - u * s.width, Real(0))});
  }
  return terms;
}

/// The ordinary method's resisting sum, sum[c l + (W cos(alpha) - u l)+ tan phi'] with
/// l = b / cos(alpha), from the slices' terms (bishopSliceTerms with the same sign).
Real ordinaryResisting(const std::vector<Slice>& slices,
                       const std::vector<BishopSliceTerms>& terms) {
  Real resisting = 0;
  for (std::size_t i = 0; i < slices.size(); ++i) {
    const Slice& s = slices[i];
    const Real l = s.width / terms[i].cos_alpha;
    const Real u = std::max(s.pore_pressure, Real(0));
    // Effective normal force W cos(alpha) - u l, not allowed to become tensile.
    const Real normal = std::max(s.weight * terms[i].cos_alpha - u * l, Real(0));
    resisting += s.apparentCohesion() * l + normal * terms[i].tan_phi;
  }
  return resisting;
}

}  // namespace

Real bishopMAlpha(Real alpha, Real friction_angle, Real factor) {
  return mAlpha(std::cos(alpha), std::tan(alpha), std::tan(friction_angle), factor);
}

FactorOfSafety ordinaryMethodOfSlices(const std::vector<Slice>& slices, Real external_driving) {
  FactorOfSafety result;
  const Real sign = slideSign(slices, external_driving);
  result.driving = drivingSum(slices, sign, external_driving);
  result.converged = true;
  if (!(result.driving > 0)) return result;
  result.value = ordinaryResisting(slices, bishopSliceTerms(slices, sign)) / result.driving;
  result.admissible = true;
  return result;
}

FactorOfSafety bishopSimplified(const std::vector<Slice>& slices, const BishopOptions& options,
                                Real external_driving) {
  FactorOfSafety result;
  const Real sign = slideSign(slices, external_driving);
  result.driving = drivingSum(slices, sign, external_driving);
  if (!(result.driving > 0)) return result;

  // m_alpha > 0 for every slice needs F > F_zero = max(-tan(alpha) tan(phi')) (only slices
  // whose base dips against the sliding direction have a bound). The plain fixed-point
  // iteration can jump below it from a low guess (the ordinary F, for instance) and then
  // converge to a meaningless root with m_alpha < 0; an iterate that would leave the range
  // is replaced by the midpoint between the current F and F_zero instead.
  const std::vector<BishopSliceTerms> terms = bishopSliceTerms(slices, sign);
  Real zero_m_factor = 0;
  for (const BishopSliceTerms& t : terms)
    zero_m_factor = std::max(zero_m_factor, -t.tan_alpha * t.tan_phi);
  Real factor = options.initial_guess;
  if (!(factor > 0)) factor = ordinaryResisting(slices, terms) / result.driving;  // ordinary F
  if (!(factor > zero_m_factor)) factor = zero_m_factor > 0 ? 2 * zero_m_factor : Real(1);
  for (int k = 1; k <= options.max_iterations; ++k) {
    Real resisting = 0;
    for (const BishopSliceTerms& t : terms) {
      const Real m = mAlpha(t.cos_alpha, t.tan_alpha, t.tan_phi, factor);
      resisting += (t.cohesion_width + t.effective_weight * t.tan_phi) / m;
    }
    result.iterations = k;
    Real next = resisting / result.driving;
    if (!(next > zero_m_factor)) next = 0.5 * (factor + zero_m_factor);
    const bool done = std::abs(next - factor) <= options.tolerance * factor;
    factor = next;
    if (done) {
      result.converged = true;
      break;
    }
  }
  result.value = factor;
  if (result.converged) {
    Real min_m = std::numeric_limits<Real>::infinity();
    for (const BishopSliceTerms& t : terms)
      min_m = std::min(min_m, mAlpha(t.cos_alpha, t.tan_alpha, t.tan_phi, factor));
    result.min_m_alpha = min_m;
    result.admissible = min_m > options.min_m_alpha;
  }
  return result;
}

}  // namespace argine
