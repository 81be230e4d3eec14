#include "argine/slopestability/Spencer.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

namespace argine {

namespace {

/// How the end forces' moment enters sum w Q = 0 (the orientation of Q in interslice()).
constexpr Real kEndMomentSign = 1;

/// A slice reduced to what the equilibrium equations need, in the frame where the mass
/// slides towards -x (x and alpha mirrored when it slides towards +x).
struct SliceTerms {
  Real driving;    ///< A = W sin(alpha)
  Real resisting;  ///< B = c l + (W cos(alpha) - u l) tan(phi'), with c = c' + S
  Real tan_phi;
  Real alpha;
  Real x, y;         ///< base midpoint
  Real normal_free;  ///< W cos(alpha) - u l: N' when Q = 0
};

struct Frame {
  std::vector<SliceTerms> terms;
  Real sign = 1;     ///< -1: mirrored (the mass slides towards +x)
  Real driving = 0;  ///< sum W sin(alpha) in the mirrored frame (>= 0 when admissible)
  /// The end forces' moment about their slices' base midpoints, sum (y_H - y_b) H (N m/m,
  /// frame): what the moment equation adds to sum w Q (see addEndForces).
  Real end_moment = 0;
};

/// The slice whose base midpoint lies nearest to x (slices not empty).
std::size_t sliceNearest(const std::vector<Slice>& slices, Real x) {
  std::size_t k = 0;
  for (std::size_t i = 1; i < slices.size(); ++i)
    if (std::abs(slices[i].x_mid - x) < std::abs(slices[k].x_mid - x)) k = i;
  return k;
}

/// Horizontal end forces (water standing against the ends) on the slice at their abscissa:
/// in its equilibrium along and normal to the base, A -= H cos(alpha) and
/// N'_free += H sin(alpha) (the force's components down the base and into it, in the frame
/// sliding towards -x); in the moment equation the difference between its line of action and
/// the slice's base midpoint, through which Spencer's equations take every slice force.
void addEndForces(Frame& f, const std::vector<Slice>& slices,
                  const std::vector<HorizontalForce>& forces) {
  for (const HorizontalForce& h : forces) {
    if (slices.empty() || h.force == 0) continue;
    SliceTerms& t = f.terms[sliceNearest(slices, h.x)];
    const Real force = f.sign * h.force;
    t.driving -= force * std::cos(t.alpha);
    t.normal_free += force * std::sin(t.alpha);
    t.resisting += force * std::sin(t.alpha) * t.tan_phi;
    f.driving -= force * std::cos(t.alpha);
    f.end_moment += (h.y - t.y) * force;
  }
}

Frame toFrame(const std::vector<Slice>& slices, const std::vector<HorizontalForce>& forces = {}) {
  Frame f;
  Real driving = 0;
  for (const Slice& s : slices) driving += s.weight * std::sin(s.base_angle);
  for (const HorizontalForce& h : forces) {  // their driving part, -H cos(alpha) of their slice
    if (slices.empty()) break;
    driving -= h.force * std::cos(slices[sliceNearest(slices, h.x)].base_angle);
  }
  f.sign = driving < 0 ? Real(-1) : Real(1);
  for (const Slice& s : slices) {
    const Real alpha = f.sign * s.base_angle;
    const Real l = s.width / std::cos(alpha);
    const Real u = std::max(s.pore_pressure, Real(0));
    const Real tan_phi = std::tan(s.friction_angle);
    const Real normal_free = s.weight * std::cos(alpha) - u * l;
    f.terms.push_back({s.weight * std::sin(alpha), s.apparentCohesion() * l + normal_free * tan_phi,
                       tan_phi, alpha, f.sign * s.x_mid, s.base_y, normal_free});
    f.driving += s.weight * std::sin(alpha);
  }
  addEndForces(f, slices, forces);
  return f;
}

/// m = cos(alpha - theta)(1 + tan(alpha - theta) tan(phi') / F).
Real sliceM(const SliceTerms& t, Real factor, Real theta) {
  return std::cos(t.alpha - theta) + std::sin(t.alpha - theta) * t.tan_phi / factor;
}

/// Q = (A - B / F) / m.
Real interslice(const SliceTerms& t, Real factor, Real theta) {
  return (t.driving - t.resisting / factor) / sliceM(t, factor, theta);
}

/// The smallest F with every m > 0 at theta (0 when no slice bounds it); +inf when a slice
/// has |alpha - theta| >= 90 deg.
Real poleBound(const Frame& f, Real theta) {
  Real bound = 0;
  for (const SliceTerms& t : f.terms) {
    const Real c = std::cos(t.alpha - theta);
    if (!(c > 0)) return std::numeric_limits<Real>::infinity();
    bound = std::max(bound, -std::sin(t.alpha - theta) * t.tan_phi / c);
  }
  return bound;
}

/// A root of r on [a, b] with r(a) < 0 < r(b): the Illinois variant of regula falsi
/// (Dowell & Jarratt 1971), bisection as a fallback when it stalls.
bool illinois(const std::function<Real(Real)>& r, Real a, Real ra, Real b, Real rb, Real tol,
              int max_iterations, Real& root) {
  int side = 0;
  for (int k = 0; k < max_iterations; ++k) {
    Real x = (a * rb - b * ra) / (rb - ra);
    if (!(x > a && x < b)) x = 0.5 * (a + b);
    const Real rx = r(x);
    if (rx == 0 || (b - a) <= tol) {
      root = x;
      return true;
    }
    if ((rx < 0) == (ra < 0)) {
      a = x;
      ra = rx;
      if (side == -1) rb *= 0.5;
      side = -1;
    } else {
      b = x;
      rb = rx;
      if (side == 1) ra *= 0.5;
      side = 1;
    }
  }
  root = 0.5 * (a + b);
  return (b - a) <= 10 * tol;
}

/// F solving sum w_i Q_i(F) = 0 at theta, the root above the pole bound where the residual
/// turns from negative (strength ahead) to positive (driving ahead), searched from `hint`.
/// False when no such root lies below 1e3.
bool solveFactor(const Frame& f, Real theta, const std::vector<Real>& weights, Real hint, Real tol,
                 int max_iterations, Real& factor, Real constant = 0) {
  const Real pole = poleBound(f, theta);
  if (!std::isfinite(pole)) return false;
  // Orient the residual so that it is positive for large F (sum w A / cos(alpha - theta),
  // the driving part alone): a moment point below the mass flips the sign of every arm.
  Real at_infinity = constant;
  for (std::size_t i = 0; i < f.terms.size(); ++i) {
    at_infinity += weights[i] * f.terms[i].driving / std::cos(f.terms[i].alpha - theta);
  }
  if (!(at_infinity != 0)) return false;
  const Real orient = at_infinity > 0 ? Real(1) : Real(-1);
  const auto residual = [&](Real F) {
    Real sum = constant;
    for (std::size_t i = 0; i < f.terms.size(); ++i) {
      sum += weights[i] * interslice(f.terms[i], F, theta);
    }
    return orient * sum;
  };
  const Real lowest = std::max(pole * (1 + 1e-9), Real(1e-6));
  const Real highest = 1e3;
  Real a = std::clamp(hint > 0 ? hint : Real(1), lowest, highest);
  Real ra = residual(a);
  Real b = a, rb = ra;
  const Real step = 1.25;
  if (ra < 0) {  // step up to a positive residual
    while (rb < 0) {
      a = b;
      ra = rb;
      if (b >= highest) return false;
      b = std::min(b * step, highest);
      rb = residual(b);
    }
  } else {  // step down to a negative residual
    while (ra >= 0) {
      b = a;
      rb = ra;
      if (a <= lowest) return false;
      a = std::max(lowest + (a - lowest) / step, lowest);
      if (b - a <= tol * b) a = lowest;
      ra = residual(a);
    }
  }
  if (!(std::isfinite(ra) && std::isfinite(rb))) return false;
  return illinois(residual, a, ra, b, rb, tol * b, max_iterations, factor);
}

std::vector<Real> forceWeights(const Frame& f) {
  return std::vector<Real>(f.terms.size(), Real(1));
}

std::vector<Real> momentWeights(const Frame& f, Real theta, Real x0, Real y0) {
  std::vector<Real> w;
  for (const SliceTerms& t : f.terms) {
    w.push_back((t.x - x0) * std::sin(theta) - (t.y - y0) * std::cos(theta));
  }
  return w;
}

Real minM(const Frame& f, Real factor, Real theta) {
  Real m = std::numeric_limits<Real>::infinity();
  for (const SliceTerms& t : f.terms) m = std::min(m, sliceM(t, factor, theta));
  return m;
}

FactorOfSafety partialFactor(const Frame& f, Real theta, const std::vector<Real>& weights,
                             Real constant = 0) {
  FactorOfSafety r;
  r.driving = f.driving;
  if (!(f.driving > 0)) return r;
  Real factor = 0;
  r.converged = solveFactor(f, theta, weights, 1, 1e-12, 200, factor, constant);
  r.value = factor;
  if (r.converged) {
    r.min_m_alpha = minM(f, factor, theta);
    r.admissible = r.min_m_alpha > 0;
  }
  return r;
}

}  // namespace

void spencerMomentPoint(const std::vector<Slice>& slices, Real& x0, Real& y0) {
  if (slices.empty()) {
    x0 = y0 = 0;
    return;
  }
  const Real left = slices.front().x_mid - 0.5 * slices.front().width;
  const Real right = slices.back().x_mid + 0.5 * slices.back().width;
  Real top = -std::numeric_limits<Real>::infinity();
  for (const Slice& s : slices) top = std::max(top, s.top_y);
  x0 = 0.5 * (left + right);
  y0 = top + 0.5 * (right - left);
}

FactorOfSafety spencerForceFactor(const std::vector<Slice>& slices, Real theta) {
  const Frame f = toFrame(slices);
  return partialFactor(f, f.sign * theta, forceWeights(f));
}

FactorOfSafety janbuSimplified(const std::vector<Slice>& slices) {
  return spencerForceFactor(slices, 0);
}

FactorOfSafety spencerMomentFactor(const std::vector<Slice>& slices, Real theta, Real x0, Real y0,
                                   const std::vector<HorizontalForce>& end_forces) {
  const Frame f = toFrame(slices, end_forces);
  const Real th = f.sign * theta;
  return partialFactor(f, th, momentWeights(f, th, f.sign * x0, y0), kEndMomentSign * f.end_moment);
}

SpencerFactor spencer(const std::vector<Slice>& slices, const SpencerOptions& options,
                      const std::vector<HorizontalForce>& end_forces) {
  SpencerFactor result;
  if (options.use_moment_point) {
    result.moment_x = options.moment_x;
    result.moment_y = options.moment_y;
  } else {
    spencerMomentPoint(slices, result.moment_x, result.moment_y);
  }
  const Frame f = toFrame(slices, end_forces);
  result.factor.driving = f.driving;
  if (!(f.driving > 0)) return result;
  const Real x0 = f.sign * result.moment_x, y0 = result.moment_y;
  const Real tol = options.tolerance;

  // g(theta) = F_m(theta) - F_f(theta); each evaluation starts from the last F found.
  Real hint = 1, last_force = 0;
  int evaluations = 0;
  const auto gap = [&](Real theta, bool& ok) {
    ++evaluations;
    Real fm = 0, ff = 0;
    ok = solveFactor(f, theta, momentWeights(f, theta, x0, y0), hint, tol, options.max_iterations,
                     fm, kEndMomentSign * f.end_moment) &&
         solveFactor(f, theta, forceWeights(f), fm, tol, options.max_iterations, ff);
    if (!ok) return Real(0);
    hint = ff;
    last_force = ff;
    return fm - ff;
  };

  // Bracket a root of g stepping out from theta = 0 in both directions.
  bool ok = false;
  Real g0 = gap(0, ok);
  if (!ok) return result;
  Real theta = 0;
  bool found = std::abs(g0) <= tol * last_force;
  Real a = 0, ga = g0, b = 0, gb = g0;
  const Real step = 0.02;  // rad
  Real previous_up = 0, g_up = g0, previous_down = 0, g_down = g0;
  bool up_alive = true, down_alive = true;
  for (int k = 1; !found && (up_alive || down_alive); ++k) {
    for (const int direction : {1, -1}) {
      bool& alive = direction > 0 ? up_alive : down_alive;
      if (!alive || found) continue;
      const Real t = direction * step * k;
      if (std::abs(t) > options.max_theta) {
        alive = false;
        continue;
      }
      bool ok_t = false;
      const Real gt = gap(t, ok_t);
      if (!ok_t) {
        alive = false;
        continue;
      }
      Real& prev = direction > 0 ? previous_up : previous_down;
      Real& gprev = direction > 0 ? g_up : g_down;
      if ((gt < 0) != (gprev < 0)) {
        a = std::min(prev, t);
        b = std::max(prev, t);
        ga = a == prev ? gprev : gt;
        gb = b == prev ? gprev : gt;
        found = true;
      }
      prev = t;
      gprev = gt;
    }
  }
  if (!found) return result;
  if (a != b) {
    // Illinois on theta needs g(a) < 0 < g(b): orient by the sign.
    const Real orient = ga < 0 ? Real(1) : Real(-1);
    bool failed = false;
    const auto oriented = [&](Real t) {
      bool ok_t = false;
      const Real g = gap(t, ok_t);
      failed = failed || !ok_t;
      return orient * g;
    };
    if (!illinois(oriented, a, orient * ga, b, orient * gb, tol, options.max_iterations, theta) ||
        failed) {
      return result;
    }
  }
  // F at the solution: force and moment factor at theta (equal to the tolerance).
  Real factor = 0;
  if (!solveFactor(f, theta, forceWeights(f), hint, tol, options.max_iterations, factor)) {
    return result;
  }
  result.factor.value = factor;
  result.factor.converged = true;
  result.factor.iterations = evaluations;
  result.theta = f.sign * theta;
  result.factor.min_m_alpha = minM(f, factor, theta);
  result.factor.admissible = result.factor.min_m_alpha > options.min_m_alpha;
  Real min_normal = std::numeric_limits<Real>::infinity();
  for (const SliceTerms& t : f.terms) {
    const Real q = interslice(t, factor, theta);
    min_normal = std::min(min_normal, t.normal_free + q * std::sin(t.alpha - theta));
  }
  result.min_effective_normal = min_normal;
  return result;
}

}  // namespace argine
