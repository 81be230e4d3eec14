#include "AcadsProblems.hpp"

#include <cmath>

namespace argine::lem_acads {

namespace {

constexpr Real kDegree = M_PI / 180;
constexpr Real kKilo = 1e3;

/// The circle-search grid of the 2:1 ACADS slopes (toe (30, 25), crest (50, 35), base y = 20):
/// centres over and in front of the face, circles tangent to y = 20 ... 34. It only frames
/// the region; nothing in it is tuned to an answer. Slices are also cut where the arc crosses a
/// layer top (no slice base in two materials): with 50 equal slices alone the search of 1(c)
/// finds circles whose straddling slices happen to be weak (Bishop 1.393 against 1.403 on
/// the same circle with the cuts or with 400 slices).
CircleSearchGrid acadsSlopeGrid() {
  CircleSearchGrid g;
  g.centre_x_min = 25;
  g.centre_x_max = 55;
  g.centre_y_min = 36;
  g.centre_y_max = 66;
  g.tangent_y_min = 20;
  g.tangent_y_max = 34;
  g.refinements = 3;
  g.slice_count = 50;
  g.split_at_materials = true;
  return g;
}

// ACADS 1(a), SLOPE/W Sec. 2.1, Slide2 problem 1: a homogeneous 2:1 slope, 10 m high, dry.
// c' = 3 kPa, phi' = 19.6 deg, gamma = 20 kN/m^3; toe bench y = 25, crest y = 35, base y = 20.
// Published: ACADS referee 1.00; Slide2 Bishop 0.987; SLOPE/W Bishop 0.963.
AcadsProblem problem1a() {
  AcadsProblem p;
  p.key = "acads_1a";
  p.title = "ACADS 1(a) homogeneous slope, dry";
  p.section.ground = Polyline({20, 30, 50, 70}, {25, 25, 35, 35});
  p.section.layers.push_back({"soil", p.section.ground, 20 * kKilo, 3 * kKilo, 19.6 * kDegree});
  p.section.floor = 20;
  p.grid = acadsSlopeGrid();
  p.referee = 1.00;
  p.band_min = 0.963;
  p.band_max = 1.00;
  p.band_source = "SLOPE/W Bishop 0.963 (Sec. 2.1) to the ACADS referee 1.00; Slide2 0.987";
  return p;
}

// ACADS 1(c), SLOPE/W Sec. 2.3, Slide2 problem 3: the 1(a) geometry in three soils, dry,
// gamma = 19.5 kN/m^3 throughout: soil 1 (top) c' = 0, phi' = 38 deg; soil 2 c' = 5.3 kPa,
// phi' = 23 deg; soil 3 c' = 7.2 kPa, phi' = 20 deg. Interfaces (SLOPE/W Fig. 7 labels):
// top of soil 2 (30, 25) (50, 29) (54, 31), flat beyond; top of soil 3 (30, 25) (40, 27)
// (52, 24), flat beyond (soil 2 pinches out at x = 40). Base y = 20. The flats run out to
// x = 0 and 90 (as xslope's model) so that deep circles stay inside the ground line.
// Published: ACADS referee 1.39; Slide2 Bishop 1.405, Spencer 1.375, GLE 1.374;
// SLOPE/W Bishop 1.414, Morgenstern-Price 1.382.
AcadsProblem problem1c() {
  AcadsProblem p;
  p.key = "acads_1c";
  p.title = "ACADS 1(c) three soils, dry";
  p.section.ground = Polyline({0, 30, 50, 90}, {25, 25, 35, 35});
  p.section.layers.push_back({"soil 1", p.section.ground, 19.5 * kKilo, 0, 38 * kDegree});
  p.section.layers.push_back({"soil 2", Polyline({0, 30, 50, 54, 90}, {25, 25, 29, 31, 31}),
                              19.5 * kKilo, 5.3 * kKilo, 23 * kDegree});
  p.section.layers.push_back({"soil 3", Polyline({0, 30, 40, 52, 90}, {25, 25, 27, 24, 24}),
                              19.5 * kKilo, 7.2 * kKilo, 20 * kDegree});
  p.section.floor = 20;
  p.grid = acadsSlopeGrid();
  p.referee = 1.39;
  p.band_min = 1.374;
  p.band_max = 1.414;
  p.band_source = "Slide2 GLE 1.374 to SLOPE/W Bishop 1.414; ACADS referee 1.39";
  // Slide2's critical circle, centre and the two ground intersections as printed in its
  // problem 3 figure (x 29.702 and 50.991, both 18.781 from the centre).
  p.published_circle = {34.121, 43.254, 18.781};
  p.published_circle_bishop = 1.405;
  p.published_circle_spencer = 1.375;
  p.published_circle_source = "Slide2 problem 3";
  return p;
}

/// The weak-layer slope of ACADS 3(a) and 3(b) (SLOPE/W Secs. 2.7, 2.8; Slide2 problems 7, 8):
/// ground (20, 27.75) (43, 27.75) (67.5, 40) (84, 40), a 2:1 face; a weak layer between
/// y = 26.5 and 27 (c' = 0, phi' = 10 deg) in soil 1 (c' = 28.5 kPa, phi' = 20 deg), both
/// gamma = 18.84 kN/m^3; phreatic line y = 26.5 (the base of the weak layer); base y = 20.
SlopeSection weakLayerSection() {
  SlopeSection s;
  s.ground = Polyline({20, 43, 67.5, 84}, {27.75, 27.75, 40, 40});
  s.layers.push_back({"soil 1", s.ground, 18.84 * kKilo, 28.5 * kKilo, 20 * kDegree});
  s.layers.push_back({"weak layer", Polyline({20, 84}, {27, 27}), 18.84 * kKilo, 0, 10 * kDegree});
  s.layers.push_back({"soil 1 below", Polyline({20, 84}, {26.5, 26.5}), 18.84 * kKilo, 28.5 * kKilo,
                      20 * kDegree});
  s.water_unit_weight = 9.81 * kKilo;
  s.phreatic = Polyline({20, 84}, {26.5, 26.5});
  s.floor = 20;
  return s;
}

// ACADS 3(a): the weak-layer slope, critical non-circular surface (block search).
// Published: ACADS referee range 1.24-1.27 (Giam); SLOPE/W Morgenstern-Price 1.261;
// Slide2 1.246 and 1.275 (Spencer, GLE).
AcadsProblem problem3a() {
  AcadsProblem p;
  p.key = "acads_3a";
  p.title = "ACADS 3(a) weak layer, block search";
  p.section = weakLayerSection();
  p.kind = SurfaceKind::BlockSearch;
  BlockSearchWindows& w = p.windows;
  w.left_end_min = 30;  // exit on the toe bench
  w.left_end_max = 43;
  w.left_vertex_min = 40;
  w.left_vertex_max = 52;
  w.right_vertex_min = 55;
  w.right_vertex_max = 67;
  w.right_end_min = 67.5;  // entry on the crest
  w.right_end_max = 84;
  w.plane = Polyline({20, 84}, {26.5, 26.5});  // base of the weak layer
  w.offset_min = 0.01;
  w.offset_max = 0.49;
  w.max_left_end_inclination = 45 * kDegree;  // the toe (passive) end, see problem4
  w.grid_count = 5;
  p.referee = 1.26;
  p.band_min = 1.24;
  p.band_max = 1.275;
  p.band_source = "ACADS referee range 1.24-1.27; SLOPE/W M-P 1.261; Slide2 1.246, 1.275";
  return p;
}

// ACADS 3(b): the weak-layer slope on the specified surface (41.85, 27.75) (44, 26.5)
// (63.5, 27) (73.31, 40) (SLOPE/W Sec. 2.8; Slide2 Table 8.2).
// Published: ACADS referee 1.34 (Giam); Slide2 Spencer 1.277, GLE 1.262; SLOPE/W Bishop 1.259,
// Morgenstern-Price 1.261.
AcadsProblem problem3b() {
  AcadsProblem p;
  p.key = "acads_3b";
  p.title = "ACADS 3(b) weak layer, specified surface";
  p.section = weakLayerSection();
  p.kind = SurfaceKind::Specified;
  p.surface = Polyline({41.85, 44, 63.5, 73.31}, {27.75, 26.5, 27, 40});
  p.slice_count = 50;
  p.referee = 1.34;
  p.band_min = 1.259;
  p.band_max = 1.34;
  p.band_source = "SLOPE/W 1.259 (Bishop), 1.261 (M-P); Slide2 1.262-1.277; ACADS referee 1.34";
  return p;
}

// ACADS 4, SLOPE/W Sec. 2.9 ("external loading"), Slide2 problem 9: the weak-layer slope with
// the weak layer a 0.6 m band inclined nearly parallel to the face, from y = 18.28-18.88 at
// x = 20 to 36.2-36.8 at x = 84 (SLOPE/W Fig. 25 labels), base y = 15, a phreatic line
// (20, 27.75) (43, 27.75) (49, 29.8) (60, 34) (66, 35.8) (74, 37.6) (80, 38.4) (84, 38.4)
// and two vertical surface loads: 20 kPa on x = 23-43 and 20 -> 40 kPa on x = 70-80.
// Materials as 3(a). Published: ACADS referee 0.78 (Giam), mean of the 20 programs 0.808,
// SLOPE 2000 GLE 0.6878; SLOPE/W Bishop 0.699, Morgenstern-Price 0.689; Slide2 0.683-0.760;
// the published band 0.67-0.81.
AcadsProblem problem4() {
  AcadsProblem p;
  p.key = "acads_4";
  p.title = "ACADS 4 inclined weak seam, phreatic line, loads";
  SlopeSection& s = p.section;
  s.ground = Polyline({20, 43, 67.5, 84}, {27.75, 27.75, 40, 40});
  s.layers.push_back({"soil 1", s.ground, 18.84 * kKilo, 28.5 * kKilo, 20 * kDegree});
  s.layers.push_back(
      {"weak seam", Polyline({20, 84}, {18.88, 36.8}), 18.84 * kKilo, 0, 10 * kDegree});
  s.layers.push_back({"soil 1 below", Polyline({20, 84}, {18.28, 36.2}), 18.84 * kKilo,
                      28.5 * kKilo, 20 * kDegree});
  s.water_unit_weight = 9.81 * kKilo;
  s.phreatic =
      Polyline({20, 43, 49, 60, 66, 74, 80, 84}, {27.75, 27.75, 29.8, 34, 35.8, 37.6, 38.4, 38.4});
  s.loads.push_back({23, 43, 20 * kKilo, 20 * kKilo});
  s.loads.push_back({70, 80, 20 * kKilo, 40 * kKilo});
  s.floor = 15;
  p.kind = SurfaceKind::BlockSearch;
  BlockSearchWindows& w = p.windows;
  w.left_end_min = 23;  // exit on the toe bench or the lower face
  w.left_end_max = 50;
  w.left_vertex_min = 30;
  w.left_vertex_max = 60;
  w.right_vertex_min = 50;
  w.right_vertex_max = 80;
  w.right_end_min = 67.5;  // entry on the crest
  w.right_end_max = 84;
  w.plane = Polyline({20, 84}, {18.28, 36.2});  // base of the seam
  w.offset_min = 0.01;
  w.offset_max = 0.59;
  // The toe (passive) end no steeper than 45 deg (Rankine's passive wedge: 45 - phi'/2 =
  // 35 deg here). Without this limit the search ends on a toe cut at 77 deg where Spencer's
  // two equations meet at theta = -47 deg, F = 0.65 (Janbu 2.33 on the same surface): a
  // spurious root, reported in doc/verification.md.
  w.max_left_end_inclination = 45 * kDegree;
  w.grid_count = 5;
  p.referee = 0.78;
  p.band_min = 0.67;
  p.band_max = 0.81;
  p.band_source = "published band 0.67-0.81 (ACADS 0.78, 20-program mean 0.808, SLOPE/W 0.689)";
  return p;
}

// Not an ACADS problem: the ACADS set has no circular case whose only pore pressure is a
// phreatic line (1(d) adds a seismic coefficient, 3(a)/(b) have the line at the base of the
// weak layer). Pockoski & Duncan (2000) test slope 1, Slide2 problem 55: a homogeneous 2:1
// slope 50 ft high, toe (0, 100) ft, crest (100, 150) ft, base 75 ft; c' = 300 psf,
// phi' = 30 deg, gamma = 120 pcf; phreatic line at the ground on the lower plateau, rising
// to 10 ft below the crest: (0, 100) (100, 140) ft; gamma_w = 62.4 pcf. Converted to SI
// exactly (F does not change). Published: UTEXAS4 Spencer 1.30, Bishop 1.29, Janbu
// simplified 1.15; Slide2 1.300, 1.293, 1.151.
AcadsProblem pockoskiDuncan1() {
  const Real ft = 0.3048, pcf = 157.08746, psf = 47.880259;
  AcadsProblem p;
  p.key = "pockoski_duncan_1";
  p.title = "Pockoski & Duncan slope 1, phreatic line";
  SlopeSection& s = p.section;
  s.ground = Polyline({-75 * ft, 0, 100 * ft, 170 * ft}, {100 * ft, 100 * ft, 150 * ft, 150 * ft});
  s.layers.push_back({"sandy clay", s.ground, 120 * pcf, 300 * psf, 30 * kDegree});
  s.water_unit_weight = 62.4 * pcf;
  s.phreatic =
      Polyline({-75 * ft, 0, 100 * ft, 170 * ft}, {100 * ft, 100 * ft, 140 * ft, 140 * ft});
  s.floor = 75 * ft;
  CircleSearchGrid& g = p.grid;
  g.centre_x_min = -20 * ft;
  g.centre_x_max = 60 * ft;
  g.centre_y_min = 160 * ft;
  g.centre_y_max = 240 * ft;
  g.tangent_y_min = 76 * ft;
  g.tangent_y_max = 140 * ft;
  g.refinements = 3;
  g.slice_count = 50;
  g.split_at_materials = true;
  p.referee = 1.30;
  p.band_min = 1.285;
  p.band_max = 1.305;
  p.band_source =
      "UTEXAS4 Bishop 1.29 to Spencer 1.30, +/-0.005 for their rounding; Slide2 1.293, 1.300";
  return p;
}

}  // namespace

std::vector<AcadsProblem> acadsProblems() {
  return {problem1a(), problem1c(), problem3a(), problem3b(), problem4(), pockoskiDuncan1()};
}

}  // namespace argine::lem_acads
