// Driver of the ACADS limit-equilibrium verification (doc/verification.md, "LEM: ACADS test
// problems"): runs one problem (--case KEY) or all (--case all), prints a row per problem
// (published answers and spread, argine's Bishop, Spencer and Janbu F, differences), writes
// the rows as CSV into --output, and fails (exit 1) when argine's F lies outside the
// published spread [band_min, band_max] of AcadsProblems.cpp: Bishop's and Spencer's critical
// circles for circular problems, Spencer's surface for non-circular ones. Janbu's simplified
// F (uncorrected, force equilibrium only) is reported, not judged.
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <string>

#include "AcadsProblems.hpp"
#include "argine/slopestability/Bishop.hpp"
#include "argine/slopestability/BlockSearch.hpp"
#include "argine/slopestability/CircleSearch.hpp"
#include "argine/slopestability/CircularSlip.hpp"
#include "argine/slopestability/PolylineSlip.hpp"
#include "argine/slopestability/Spencer.hpp"

namespace {

using argine::Real;
using namespace argine;
using namespace argine::lem_acads;

struct Row {
  Real bishop = NAN, spencer = NAN, janbu = NAN, theta = NAN;
  /// Bishop and Spencer on the published critical circle, sliced as the search slices
  /// (NaN: the problem has none).
  Real published_bishop = NAN, published_spencer = NAN;
  std::string surface;  ///< the critical surface, for the log
  bool ok = false;
};

std::string circleText(const CriticalCircle& c) {
  char text[160];
  std::snprintf(text, sizeof text, "circle (%.3f, %.3f) R %.3f, x %.2f-%.2f", c.circle.centre_x,
                c.circle.centre_y, c.circle.radius, c.mass.entry_x, c.mass.exit_x);
  return text;
}

std::string polylineText(const Polyline& p) {
  std::string text = "polyline";
  for (std::size_t i = 0; i < p.x.size(); ++i) {
    char point[48];
    std::snprintf(point, sizeof point, " (%.3f, %.3f)", p.x[i], p.y[i]);
    text += point;
  }
  return text;
}

Row run(const AcadsProblem& p) {
  Row row;
  switch (p.kind) {
    case SurfaceKind::CircleSearch: {
      const CriticalCircle bishop = searchCriticalCircle(p.section, p.grid);
      // Spencer's own critical circle, the moment about each circle's centre.
      const CriticalCircle spencer_c =
          searchCriticalCircleBy(p.section, p.grid, [](const SlipMass& mass, const SlipCircle& c) {
            SpencerOptions o;
            o.use_moment_point = true;
            o.moment_x = c.centre_x;
            o.moment_y = c.centre_y;
            return spencer(mass.slices, o).factor;
          });
      if (!bishop.found || !spencer_c.found) return row;
      row.bishop = bishop.bishop.value;
      row.spencer = spencer_c.objective.value;
      SpencerOptions o;
      o.use_moment_point = true;
      o.moment_x = spencer_c.circle.centre_x;
      o.moment_y = spencer_c.circle.centre_y;
      row.theta = spencer(spencer_c.mass.slices, o).theta;
      row.janbu = janbuSimplified(spencer_c.mass.slices).value;
      row.surface = "Bishop " + circleText(bishop) + "; Spencer " + circleText(spencer_c);
      row.ok = true;
      break;
    }
    case SurfaceKind::BlockSearch: {
      const CriticalBlock block = searchCriticalBlock(p.section, p.windows);
      if (!block.found) return row;
      row.spencer = block.spencer.factor.value;
      row.theta = block.spencer.theta;
      row.janbu = janbuSimplified(block.mass.slices).value;
      row.surface =
          polylineText(block.surface) + ", " + std::to_string(block.evaluated) + " surfaces";
      row.ok = true;
      break;
    }
    case SurfaceKind::Specified: {
      const SlipMass mass = slicePolyline(p.section, p.surface, p.slice_count, true);
      if (!mass.valid) return row;
      const SpencerFactor s = spencer(mass.slices);
      if (!s.factor.admissible) return row;
      row.spencer = s.factor.value;
      row.theta = s.theta;
      row.janbu = janbuSimplified(mass.slices).value;
      row.surface = polylineText(p.surface) + " (specified)";
      row.ok = true;
      break;
    }
  }
  return row;
}

Real percent(Real f, Real ref) {
  return 100 * (f - ref) / ref;
}

/// Bishop's and Spencer's F on `circle` (Spencer's moment about its centre, as in the search).
void bothOnCircle(const AcadsProblem& p, const SlipCircle& circle, int slice_count,
                  bool split_at_materials, Real& bishop_f, Real& spencer_f) {
  const SlipMass mass = sliceCircle(p.section, circle, slice_count, split_at_materials);
  bishop_f = bishopSimplified(mass.slices).value;
  SpencerOptions o;
  o.use_moment_point = true;
  o.moment_x = circle.centre_x;
  o.moment_y = circle.centre_y;
  spencer_f = spencer(mass.slices, o).factor.value;
}

/// The published critical circle, reported (not judged): with the search's slicing, with
/// 1000 slices (the slicing converged) and with equal slices without the cuts at layer tops
/// (the slicing of a program that does not cut there).
void reportPublishedCircle(const AcadsProblem& p, Row& row) {
  const SlipCircle& c = p.published_circle;
  bothOnCircle(p, c, p.grid.slice_count, p.grid.split_at_materials, row.published_bishop,
               row.published_spencer);
  Real bishop_fine = 0, spencer_fine = 0, bishop_equal = 0, spencer_equal = 0;
  bothOnCircle(p, c, 1000, p.grid.split_at_materials, bishop_fine, spencer_fine);
  bothOnCircle(p, c, p.grid.slice_count, false, bishop_equal, spencer_equal);
  std::printf(
      "  on the published critical circle (%.3f, %.3f) R %.3f (%s): Bishop %.4f "
      "(published %.3f, %+.2f %%), Spencer %.4f (published %.3f, %+.2f %%); 1000 "
      "slices: %.4f / %.4f; %d equal slices, no cuts: %.4f / %.4f\n",
      c.centre_x, c.centre_y, c.radius, p.published_circle_source.c_str(), row.published_bishop,
      p.published_circle_bishop, percent(row.published_bishop, p.published_circle_bishop),
      row.published_spencer, p.published_circle_spencer,
      percent(row.published_spencer, p.published_circle_spencer), bishop_fine, spencer_fine,
      p.grid.slice_count, bishop_equal, spencer_equal);
}

bool inBand(Real f, const AcadsProblem& p) {
  return f >= p.band_min && f <= p.band_max;
}

/// f with `digits` decimals; empty for NaN (no value: Bishop on a non-circular surface).
std::string fixed(Real f, int digits) {
  if (std::isnan(f)) return "";
  char text[32];
  std::snprintf(text, sizeof text, "%.*f", digits, f);
  return text;
}

}  // namespace

int main(int argc, char** argv) {
  std::string which = "all", output = ".";
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string key = argv[i];
    if (key == "--case") which = argv[i + 1];
    if (key == "--output") output = argv[i + 1];
  }
  const std::string csv_path = output + "/lem_" + which + ".csv";
  std::ofstream csv(csv_path);
  csv << "case,problem,referee,band_min,band_max,bishop,spencer,spencer_theta_deg,janbu,"
         "diff_bishop_pct,diff_spencer_pct,within_band,published_circle_bishop,"
         "published_circle_spencer\n";
  bool all_ok = true, any = false;
  for (const AcadsProblem& p : acadsProblems()) {
    if (which != "all" && which != p.key) continue;
    any = true;
    Row row = run(p);
    const bool circular = p.kind == SurfaceKind::CircleSearch;
    const bool ok = row.ok && inBand(row.spencer, p) && (!circular || inBand(row.bishop, p));
    all_ok = all_ok && ok;
    std::printf("%-48s referee %.3f, spread [%.3f, %.3f] (%s)\n", p.title.c_str(), p.referee,
                p.band_min, p.band_max, p.band_source.c_str());
    if (circular) {
      std::printf("  argine Bishop %.4f (%+.2f %%)", row.bishop, percent(row.bishop, p.referee));
    } else {
      std::printf("  argine Bishop   n/a  (non-circular)");
    }
    std::printf(", Spencer %.4f (%+.2f %%, theta %.2f deg), Janbu simplified %.4f on it: %s\n",
                row.spencer, percent(row.spencer, p.referee), row.theta * 180 / M_PI, row.janbu,
                ok ? "within the spread" : "OUTSIDE the spread");
    std::printf("  critical: %s\n", row.surface.c_str());
    if (p.published_circle.radius > 0) reportPublishedCircle(p, row);
    csv << p.key << ",\"" << p.title << "\"," << fixed(p.referee, 3) << "," << fixed(p.band_min, 3)
        << "," << fixed(p.band_max, 3) << "," << fixed(row.bishop, 4) << ","
        << fixed(row.spencer, 4) << "," << fixed(row.theta * 180 / M_PI, 2) << ","
        << fixed(row.janbu, 4) << "," << fixed(percent(row.bishop, p.referee), 2) << ","
        << fixed(percent(row.spencer, p.referee), 2) << "," << (ok ? "yes" : "no") << ","
        << fixed(row.published_bishop, 4) << "," << fixed(row.published_spencer, 4) << "\n";
  }
  if (!any) {
    std::cerr << "lem_acads: no problem named " << which << "\n";
    return 2;
  }
  std::cout << "CSV: " << csv_path << "\n";
  return all_ok ? 0 : 1;
}
