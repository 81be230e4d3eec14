// The keys of an argine deck. Every key is declared here and nowhere else: the validator,
// the reader's defaults and doc/deck-reference.md all come from this table.
#include "argine/input/DeckSchema.hpp"
#include "argine/input/DeckWords.hpp"

namespace argine {

namespace {

using Words = std::vector<std::string>;

// ---------------------------------------------------------------- Mesh

ListSchema regionKeys() {
  ListSchema region;
  region.add(KeySpec::reals("Vertices (m)", "m", 0,
                            "polygon corners as x0, y0, x1, y1, ... (at least 3 vertices, "
                            "either orientation)")
                 .require());
  return region;
}

ListSchema generatorKeys() {
  ListSchema generate;
  generate.add(KeySpec::choice("Type", deckWords(kGeneratorWords),
                               "rectangle: a structured grid of the box, one block filling it or "
                               "soil regions seeded at point resolution (see Regions); polygon: "
                               "elements following the region edges, the rest of the box becomes "
                               "block `empty`")
                   .require());
  generate.add(KeySpec::choice("Element", deckWords(kElementWords), "element shape")
                   .byDefault(std::string("quad4")));
  generate.add(
      KeySpec::real("Element Size (m)", "m", "target element edge length").above(0).require());
  generate.add(
      KeySpec::reals("Lower Left (m)", "m", 2, "corner (x_min, y_min) of the box").require());
  generate.add(
      KeySpec::reals("Upper Right (m)", "m", 2, "corner (x_max, y_max) of the box").require());
  generate.add(KeySpec::text("Block",
                             "element block name of a rectangle without Regions; node and side "
                             "sets `left`, `right`, `bottom`, `top` are made too")
                   .when("Type", {"rectangle"})
                   .byDefault(std::string("soil")));
  generate.add(
      KeySpec::namedSublists(
          "Regions", "region", regionKeys(),
          "soil regions (polygons that may share edges but not area); each region's name becomes "
          "its block name and the rest of the box block `empty`. In a rectangle the grid stays "
          "structured: an element's block is the region holding its centroid (the first in deck "
          "order when on a shared edge), and a region's material is seeded at the pattern "
          "positions inside the polygon in every element it touches, each point keeping its "
          "pattern share of the element area")
          .requireWhen("Type", {"polygon"})
          .require()
          .atLeastOneEntry());
  return generate;
}

ListSchema meshKeys() {
  ListSchema mesh;
  mesh.add(KeySpec::file("Exodus File", "Exodus II background mesh (relative to the deck)"));
  mesh.add(KeySpec::file("Gmsh File",
                         "gmsh mesh (relative to the deck): an .msh file (MSH 4.1, ASCII or "
                         "binary) of 3-node triangles or 4-node quadrangles in the xy plane, or "
                         "a .geo file meshed by the gmsh program (apt-get install gmsh); "
                         "physical surfaces become element blocks, physical curves side sets "
                         "and node sets, physical points node sets, each named as in gmsh"));
  mesh.add(KeySpec::sublist("Generate", generatorKeys(), "built-in mesh generator"));
  mesh.exactlyOneOf({"Exodus File", "Gmsh File", "Generate"});
  mesh.add(KeySpec::choice("Shape Functions", deckWords(kShapeFamilyWords),
                           "shape functions of the particle-grid transfers: linear (the "
                           "element's own, the thesis), uGIMP or quadratic B-spline (both "
                           "need a structured Quad4 grid, Generate/Type rectangle; they "
                           "remove the cell-crossing noise of linear shapes, doc/theory.md)")
               .byDefault(std::string("linear")));
  return mesh;
}

// ---------------------------------------------------------------- Materials

const Words kMohrCoulombModels{"Mohr-Coulomb", "suction Mohr-Coulomb"};
const Words kWetPhases{"saturated", "unsaturated"};

ListSchema solidKeys() {
  ListSchema solid;
  solid.add(KeySpec::choice("Model", deckWords(kSolidModelWords), "constitutive model").require());
  solid.add(
      KeySpec::real("Young's Modulus (Pa)", "Pa", "drained Young's modulus E'").above(0).require());
  solid.add(KeySpec::real("Poisson's Ratio", "-", "drained Poisson's ratio nu'")
                .above(-1)
                .below(0.5)
                .require());
  solid.add(KeySpec::real("Cohesion (Pa)", "Pa", "effective cohesion c'")
                .atLeast(0)
                .when("Model", kMohrCoulombModels)
                .require());
  solid.add(KeySpec::real("Friction Angle (deg)", "deg", "effective friction angle phi'")
                .atLeast(0)
                .below(90)
                .when("Model", kMohrCoulombModels)
                .require());
  solid.add(KeySpec::real("Dilatancy Angle (deg)", "deg",
                          "dilatancy angle psi (at most the friction angle)")
                .atLeast(0)
                .below(90)
                .when("Model", kMohrCoulombModels)
                .byDefault(0.0));
  solid.add(KeySpec::real("Tensile Strength (Pa)", "Pa",
                          "tension cut-off: largest principal stress <= this (Tension Cut-Off)")
                .atLeast(0)
                .when("Model", kMohrCoulombModels)
                .byDefault(0.0));
  solid.add(KeySpec::boolean("Tension Cut-Off",
                             "apply the tension cut-off at Tensile Strength (it binds only "
                             "below the apex c cot phi)")
                .when("Model", kMohrCoulombModels)
                .byDefault(true));
  solid.add(KeySpec::real("Cohesion Increase Max (Pa)", "Pa",
                          "dc_max in c = c' + dc_max (1 - exp(-B s/p_atm)) (Eq. 4.25)")
                .atLeast(0)
                .when("Model", {"suction Mohr-Coulomb"})
                .require());
  solid.add(KeySpec::real("Cohesion Suction Rate B", "-", "B in the cohesion law (Eq. 4.25)")
                .atLeast(0)
                .when("Model", {"suction Mohr-Coulomb"})
                .require());
  solid.add(KeySpec::real("Friction Suction Rate A (deg)", "deg",
                          "A in phi = phi' + A s/p_atm (Eq. 4.26)")
                .atLeast(0)
                .when("Model", {"suction Mohr-Coulomb"})
                .require());
  solid.add(KeySpec::real("Atmospheric Pressure (Pa)", "Pa", "p_atm scaling the suction")
                .above(0)
                .when("Model", {"suction Mohr-Coulomb"})
                .byDefault(101325.0));
  return solid;
}

ListSchema liquidKeys() {
  ListSchema liquid;
  liquid.add(KeySpec::real("Density (kg/m3)", "kg/m3", "liquid density rho_L at zero pressure")
                 .above(0)
                 .byDefault(1000.0));
  liquid.add(KeySpec::real("Bulk Modulus (Pa)", "Pa", "liquid bulk modulus K_L (Eq. 4.13)")
                 .above(0)
                 .byDefault(2.2e9));
  liquid.add(KeySpec::real("Viscosity (Pa s)", "Pa s", "dynamic viscosity mu_L")
                 .above(0)
                 .byDefault(1.0e-3));
  return liquid;
}

ListSchema retentionKeys() {
  ListSchema retention;
  retention.add(
      KeySpec::choice("Model", deckWords(kRetentionModelWords), "soil-water retention curve S_L(s)")
          .require());
  retention.add(KeySpec::real("Slope (1/Pa)", "1/Pa", "a_v in S_L = S_max - a_v s (Eq. 5.6)")
                    .atLeast(0)
                    .when("Model", {"linear"})
                    .require());
  retention.add(KeySpec::real("Reference Pressure (Pa)", "Pa", "p_ref of van Genuchten (Eq. 4.28)")
                    .above(0)
                    .when("Model", {"van Genuchten"})
                    .require());
  retention.add(KeySpec::real("Lambda", "-", "lambda of van Genuchten (Eq. 4.28)")
                    .above(0)
                    .below(1)
                    .when("Model", {"van Genuchten"})
                    .require());
  retention.add(
      KeySpec::real("Alpha (1/Pa)", "1/Pa", "alpha in S_e = exp(-alpha s) (Gardner exponential)")
          .above(0)
          .when("Model", {"Gardner"})
          .require());
  retention.add(KeySpec::real("Minimum Saturation", "-", "residual saturation S_min")
                    .atLeast(0)
                    .below(1)
                    .byDefault(0.0));
  retention.add(KeySpec::real("Maximum Saturation", "-",
                              "saturation S_max at zero suction (> Minimum Saturation)")
                    .above(0)
                    .atMost(1)
                    .byDefault(1.0));
  retention.add(
      KeySpec::real(
          "Occluded Air Pressure (Pa)", "Pa",
          "absolute pressure p_a of the air occluded in the pores at p_L = 0 (the "
          "atmosphere's, 101325 Pa): the 1 - S_max of air left at zero suction then "
          "compresses by Boyle's law, S_L = 1 - (1 - S_max) p_a / (p_a + p_L) at p_L > 0, "
          "and the liquid's storage there is that of an air-water mixture; 0: the air "
          "does not compress, S_L = S_max at p_L >= 0 (the thesis; doc/theory.md Sec. 3.8)")
          .atLeast(0)
          .byDefault(0.0));
  return retention;
}

ListSchema conductivityKeys() {
  ListSchema conductivity;
  conductivity.add(KeySpec::choice("Model", deckWords(kConductivityModelWords),
                                   "hydraulic conductivity curve k(S_L)")
                       .byDefault(std::string("constant")));
  conductivity.add(KeySpec::real("Intrinsic Permeability (m2)", "m2",
                                 "kappa; k_sat = kappa rho_L g / mu_L with g = 9.81 m/s2")
                       .above(0));
  conductivity.add(KeySpec::real("Saturated Conductivity (m/s)", "m/s",
                                 "k_sat; kappa = k_sat mu_L / (rho_L g) with g = 9.81 m/s2")
                       .above(0));
  conductivity.exactlyOneOf({"Intrinsic Permeability (m2)", "Saturated Conductivity (m/s)"});
  conductivity.add(KeySpec::real("Exponent", "-", "r in k = k_sat S_L^r (Hillel, Eq. 4.30)")
                       .above(0)
                       .when("Model", {"Hillel"})
                       .byDefault(3.0));
  conductivity.add(KeySpec::real("Lambda", "-", "lambda* of Mualem (Eq. 4.31)")
                       .above(0)
                       .below(1)
                       .when("Model", {"Mualem"})
                       .require());
  conductivity.add(KeySpec::real("Alpha (1/Pa)", "1/Pa", "alpha in k = k_sat exp(-alpha s)")
                       .above(0)
                       .when("Model", {"Gardner"})
                       .require());
  return conductivity;
}

ListSchema initialStateKeys() {
  ListSchema initial;
  initial.add(KeySpec::real("Liquid Pressure (Pa)", "Pa",
                            "uniform initial p_L (compression positive; suction is -p_L)")
                  .when("Phase Model", kWetPhases)
                  .byDefault(0.0));
  initial.add(KeySpec::real("Vertical Effective Stress (Pa)", "Pa",
                            "initial sigma'_yy (tension positive, so compression is negative)")
                  .atMost(0)
                  .byDefault(0.0));
  initial.add(KeySpec::real("K0", "-", "earth pressure coefficient: sigma'_xx = K0 sigma'_yy")
                  .atLeast(0)
                  .byDefault(1.0));
  return initial;
}

// ---- Locking mitigation (volumetric averaging, physics/VolumetricAveraging.hpp)

ListSchema lockingMitigationKeys() {
  ListSchema locking;
  locking.add(KeySpec::choice("Volumetric Strain Averaging", deckWords(kIncrementAveragingWords),
                              "the volumetric strain increment of each point replaced by the "
                              "volume-weighted average over the points of its element "
                              "(element, MPM-MIXED) or mapped to the nodes and back (nodal "
                              "mixed discretisation)")
                  .byDefault(std::string("none")));
  locking.add(KeySpec::choice("Liquid Pressure Averaging", deckWords(kIncrementAveragingWords),
                              "the same averaging of the liquid pressure increment of "
                              "saturated points")
                  .byDefault(std::string("none")));
  locking.add(KeySpec::real("Averaging Length (m)", "m",
                            "L: the element averages of Volumetric Strain Averaging and Liquid "
                            "Pressure Averaging are taken over square patches of side L instead "
                            "of single elements (an element belongs to the patch holding its "
                            "centre; the patches tile the mesh's bounding box from its lower "
                            "left corner), so that the averaging length stays L as the mesh is "
                            "refined (doc/theory.md Sec. 3.3.4); the same L for every material "
                            "that gives it; 0: one element (a cell of a structured grid whose "
                            "size is L gives the same patches)")
                  .atLeast(0)
                  .byDefault(0.0));
  locking.add(KeySpec::boolean(
                  "Checkerboard Filter",
                  "the element averages of Volumetric Strain Averaging (and of "
                  "Liquid Pressure Averaging) filtered each step by an exchange "
                  "between edge neighbours: each pair passes min(W_r, W_s) (q_s - "
                  "q_r) / (2 n) of sum V q, W = sum V of an element (or patch), n the "
                  "most edge neighbours an element has (4 on a grid of cells): sum V "
                  "q kept, a uniform value kept where a surface cuts or ends the "
                  "cells, and with equal weights half its own plus 1/(2 n) of each "
                  "neighbour's. One value a cell "
                  "leaves the alternating (checkerboard) pattern of the cells' "
                  "mean stress free of any nodal force, and a sliding body grows "
                  "it; the filter removes that mode and smooths the rest over one "
                  "cell (doc/theory.md Sec. 3.3.4); on several MPI ranks each element's sums are "
                  "completed over the ranks; false: off")
                  .byDefault(false));
  locking.add(KeySpec::boolean(
                  "Conjugate Mean Stress",
                  "the nodal forces take each point's in-plane mean stress (s'_xx + s'_yy) / 2 - "
                  "S_L p_L and its p_L in the liquid's force averaged as the volumetric strain "
                  "is (element, patch or nodal) instead of the point's own: the work conjugates of "
                  "the averaged d eps_vol and div v_L, so that forces and strains see one "
                  "operator (B-bar; a "
                  "symmetric stiffness for any tangent). It keeps a sliding body's cell "
                  "checkerboard as low as Checkerboard Filter does; needs Volumetric Strain "
                  "Averaging: element or nodal and cannot be "
                  "combined with Checkerboard Filter (whose null space, the checkerboard, the "
                  "forces would then not see; doc/theory.md Sec. 3.3.4); one choice for all "
                  "materials that average the volumetric strain the same way (they share the "
                  "sums). false: each point's own")
                  .byDefault(false));
  locking.add(KeySpec::real("Liquid Head Stabilisation", "-",
                            "alpha: each step a point exchanges liquid at alpha k/g (capped for "
                            "stability) with planes of the piezometric pressure p_L + rho_L g y "
                            "through the node centres; removes the Tri3 "
                            "one-pressure-per-element checkerboard of the saturated zone, "
                            "leaves any linear head field alone (steady unsaturated flow "
                            "included) and conserves the liquid mass (doc/theory.md Sec. "
                            "3.3.5); 0: off (the thesis)")
                  .atLeast(0)
                  .byDefault(0.0));
  locking.add(KeySpec::boolean("Intra-Element Seepage",
                               "the points of one element exchange liquid by Darcy flow (their "
                               "own k) towards their common piezometric pressure p_L + rho_L g "
                               "y, implicit in time; the element's liquid mass is kept. The "
                               "grid sees one pressure per linear triangle, so nothing else "
                               "relaxes pressure differences between the points of an element, "
                               "and a sliding body pumps saturated and unsaturated neighbours "
                               "apart (+300 / -120 kPa in the levee drawdown, issue P11; "
                               "doc/theory.md); false: off (the thesis)")
                  .byDefault(false));
  locking.add(KeySpec::choice("Seepage Patch", deckWords(kSeepagePatchWords),
                              "with Intra-Element Seepage: which points exchange. element: "
                              "the points of one element, through its centre; nodal: the "
                              "points that share a node, through the node centres (the node "
                              "averaging of Volumetric Strain Averaging), so that a point "
                              "alone in its cell, as a shear band on a grid leaves them, "
                              "exchanges with its neighbours across the cell edge "
                              "(doc/theory.md Sec. 3.3.6)")
                  .byDefault(std::string("element")));
  return locking;
}

ListSchema materialKeys() {
  ListSchema material;
  material.add(KeySpec::text("Block", "mesh element block filled with this material").require());
  material.add(KeySpec::integer("Points Per Element",
                                "material points seeded in each element: tri3 1, 3, 4, 6 or 12; "
                                "quad4 1, 4, 9 or 16 (an m x m grid)")
                   .onlyIntegers({1, 3, 4, 6, 9, 12, 16})
                   .byDefault(3LL));
  material.add(KeySpec::choice("Phase Model", deckWords(kPhaseModelWords),
                               "dry: solid only; saturated: two-phase, S_L = 1; unsaturated: "
                               "two-phase with suction")
                   .byDefault(std::string("saturated")));
  material.add(KeySpec::real("Porosity", "-", "initial porosity n0").above(0).below(1).require());
  material.add(KeySpec::real("Solid Density (kg/m3)", "kg/m3", "density of the solid grains rho_S")
                   .above(0)
                   .require());
  material.add(KeySpec::choice("Mass Balance", deckWords(kMassBalanceWords),
                               "liquid mass balance: complete (Eq. 4.12) or simplified (Eq. 4.14)")
                   .when("Phase Model", kWetPhases)
                   .byDefault(std::string("complete")));
  material.add(
      KeySpec::choice("Tension Cracks", deckWords(kTensionCracksWords),
                      "what fills the opening of a point at the tension cut-off that held suction "
                      "at the start of the step: pore space: the point's own pores, on the "
                      "retention curve (the thesis; the suction it makes draws water into the "
                      "crack); air-filled: a crack open to the surface, kept out of the pores as "
                      "for a dry point, and the point drains into it above p_L = 0 while it is "
                      "open; it opens only where air reaches it, in an element on the soil's "
                      "free surface or beside an open air-filled crack (doc/theory.md, "
                      "'Air-filled tension cracks'); known defect: a fixed-skeleton stage on a "
                      "slid grid body can go unstable with it (doc/verification.md, 'The crack "
                      "model tested')")
          .when("Phase Model", {"unsaturated"})
          .byDefault(std::string("pore space")));
  material.add(KeySpec::sublist("Solid", solidKeys(), "solid skeleton").require());
  material.add(KeySpec::sublist("Liquid", liquidKeys(), "pore liquid (defaults: water at 20 C)")
                   .when("Phase Model", kWetPhases));
  material.add(KeySpec::sublist("Retention", retentionKeys(), "soil-water retention curve")
                   .when("Phase Model", {"unsaturated"})
                   .require());
  material.add(KeySpec::sublist("Conductivity", conductivityKeys(), "hydraulic conductivity")
                   .when("Phase Model", kWetPhases)
                   .require());
  material.add(KeySpec::sublist("Initial State", initialStateKeys(),
                                "state of the points before the first stage"));
  material.add(KeySpec::sublist("Locking Mitigation", lockingMitigationKeys(),
                                "volumetric-locking / cell-crossing mitigation"));
  return material;
}

// ---------------------------------------------------------------- Stages

ListSchema timeStepKeys() {
  ListSchema step;
  step.add(KeySpec::choice("Mode", deckWords(kTimeStepModeWords),
                           "automatic: from the critical-step criteria; fixed: Fixed Step (s)")
               .byDefault(std::string("automatic")));
  step.add(KeySpec::real("Fixed Step (s)", "s", "the time step")
               .above(0)
               .when("Mode", {"fixed"})
               .require());
  step.add(KeySpec::real("Safety Factor", "-", "multiplies the smallest critical step")
               .above(0)
               .atMost(1)
               .when("Mode", {"automatic"})
               .byDefault(0.5));
  step.add(KeySpec::choices("Criteria", deckWords(kCriterionWords),
                            "critical-step criteria, a list or a comma-separated string")
               .when("Mode", {"automatic"})
               .byDefault(Words{"mieremet liquid drag", "consolidation"}));  // as Deck.hpp
  step.add(KeySpec::integer("Update Interval", "recompute the step every N steps")
               .atLeast(1)
               .when("Mode", {"automatic"})
               .byDefault(1LL));
  return step;
}

// ---------------------------------------------------------------- hydraulic conditions (P3)
// Conditions on the moving free boundary (thesis Sec. 4.1-4.3): where (a zone tested on the
// current free boundary, or a side set) and a value in time (constant, table or CSV file).

const Words kHydraulicKinds{"total head", "pressure series", "infiltration", "seepage face"};

ListSchema zoneKeys() {
  ListSchema zone;
  zone.add(KeySpec::choice("Type", deckWords(kZoneWords),
                           "region tested at the midpoints of the current free sides: "
                           "everywhere, half-plane, box or polyline band. A side whose "
                           "midpoint lies outside is not taken, though its nodes lie inside: "
                           "to leave out a mesh boundary (a base at y = 0), keep the zone's "
                           "edge nearer to it than half the shortest side that meets it")
               .require());
  zone.add(KeySpec::reals("Point (m)", "m", 2, "a point on the edge of the half-plane")
               .when("Type", {"half-plane"})
               .require());
  zone.add(KeySpec::reals("Inside Direction", "-", 2,
                          "vector pointing into the half-plane: the zone is (x - Point) . "
                          "direction >= 0 (x < 8 m: Point [8, 0], direction [-1, 0])")
               .when("Type", {"half-plane"})
               .require());
  zone.add(KeySpec::reals("Lower Left (m)", "m", 2, "corner (x_min, y_min) of the box")
               .when("Type", {"box"})
               .require());
  zone.add(KeySpec::reals("Upper Right (m)", "m", 2, "corner (x_max, y_max) of the box")
               .when("Type", {"box"})
               .require());
  zone.add(KeySpec::reals("Vertices (m)", "m", 0, "polyline vertices x0, y0, x1, y1, ...")
               .when("Type", {"polyline band"})
               .require());
  zone.add(KeySpec::real("Width (m)", "m", "largest distance from the polyline")
               .above(0)
               .when("Type", {"polyline band"})
               .require());
  return zone;
}

/// Adds the three ways of giving a time-dependent `value` (a constant `<value> (<unit>)`,
/// a `<value> Table` of time, value pairs, a `<value> File` CSV), exactly one of them.
void addTimeSeriesKeys(ListSchema& boundary, const std::string& value, const std::string& unit,
                       const std::string& kind, const std::string& doc, bool constant) {
  if (constant)
    boundary.add(
        KeySpec::real(value + " (" + unit + ")", unit, "constant " + doc).when("Type", {kind}));
  boundary.add(KeySpec::reals(value + " Table", "s, " + unit, 0,
                              doc + " in time: pairs t0, v0, t1, v1, ... (times increasing; "
                                    "linear between, clamped outside)")
                   .when("Type", {kind}));
  boundary.add(
      KeySpec::file(value + " File", doc + " in time: CSV file with columns time (s), value (" +
                                         unit + "), optional header line (relative to the deck)")
          .when("Type", {kind}));
  std::vector<std::string> group;
  if (constant) group.push_back(value + " (" + unit + ")");
  group.push_back(value + " Table");
  group.push_back(value + " File");
  boundary.exactlyOneOf(group, Condition{"Type", {kind}});
}

void addHydraulicBoundaryKeys(ListSchema& boundary) {
  boundary.add(KeySpec::sublist("Zone", zoneKeys(),
                                "where the condition applies on the CURRENT free boundary "
                                "(instead of a side set)")
                   .when("Type", kHydraulicKinds));
  boundary.exactlyOneOf({"Side Set", "Zone"}, Condition{"Type", kHydraulicKinds});
  addTimeSeriesKeys(boundary, "Total Head", "m", "total head",
                    "total head H = y + p_L / (rho_L g) (Eq. 4.50), an elevation", true);
  boundary.add(KeySpec::choice("Above Level", deckWords(kAboveLevelWords),
                               "on the boundary above the current level: constant pressure, "
                               "linear (hydrostatic) suction, or potential seepage face")
                   .when("Type", {"total head"})
                   .byDefault(std::string("constant pressure")));
  boundary.add(KeySpec::real("Pressure Above Level (Pa)", "Pa",
                             "p_L above the level with Above Level: constant pressure")
                   .when("Above Level", {"constant pressure"})
                   .byDefault(0.0));
  boundary.add(KeySpec::real("Liquid Density (kg/m3)", "kg/m3",
                             "rho_L converting head to pressure, p_L = rho_L g (H - y)")
                   .above(0)
                   .when("Type", {"total head"})
                   .byDefault(1000.0));
  addTimeSeriesKeys(boundary, "Pressure", "Pa", "pressure series",
                    "prescribed p_L (compression positive)", false);
  boundary.add(KeySpec::reals("Linear Between x (m)", "m", 2,
                              "x0, x1 (x0 < x1): p_L varies linearly in x from the Pressure "
                              "Table/File (at x0) to the End Pressure Table/File (at x1), "
                              "constant beyond (e.g. the bottom of the thesis' toe-uplift "
                              "model, Table 5.6); absent: the same p_L all along the condition")
                   .when("Type", {"pressure series"}));
  boundary.add(KeySpec::reals("End Pressure Table", "s, Pa", 0,
                              "with Linear Between x (m): p_L (compression positive) at x1 in "
                              "time, pairs t0, v0, t1, v1, ... (times increasing; linear "
                              "between, clamped outside)")
                   .when("Type", {"pressure series"}));
  boundary.add(KeySpec::file("End Pressure File",
                             "with Linear Between x (m): p_L at x1 in time, CSV file with "
                             "columns time (s), value (Pa), optional header line (relative "
                             "to the deck)")
                   .when("Type", {"pressure series"}));
  addTimeSeriesKeys(boundary, "Flux", "m/s", "infiltration",
                    "infiltration flux q into the soil (rain positive, evaporation negative)",
                    true);
  boundary.add(KeySpec::choice("Time Origin", deckWords(kTimeOriginWords),
                               "what the times of a Total Head/Pressure/Flux Table or File "
                               "count from: the start of this stage, or the start of the "
                               "first stage (simulation time)")
                   .when("Type", {"total head", "pressure series", "infiltration"})
                   .byDefault(std::string("stage start")));
  boundary.add(KeySpec::boolean("Ponding",
                                "rain the saturated surface cannot take ponds and is imposed "
                                "anyway (true), or runs off at zero pressure (false)")
                   .when("Type", {"infiltration"})
                   .byDefault(false));
}
// ---------------------------------------------------------------- end hydraulic conditions

/// A rigid wall with Coulomb friction (boundary/FrictionalContact.hpp, doc/theory.md Sec. 5.6).
void addFrictionalWallKeys(ListSchema& boundary) {
  const std::vector<std::string> wall{"frictional wall"};
  boundary.add(KeySpec::real("Friction Coefficient (-)", "-",
                             "Coulomb coefficient mu of the soil on the wall(s): 0 smooth, "
                             "large rough (the soil still lifts off a frictional wall)")
                   .atLeast(0)
                   .when("Type", {"frictional wall", "side walls"})
                   .require());
  boundary.add(KeySpec::reals("Normal", "-", 2,
                              "node set only: outward normal of the soil, pointing into the "
                              "wall (any length); default: from the mesh-boundary sides "
                              "joining nodes of the set")
                   .when("Type", wall));
  boundary.add(KeySpec::boolean("Impermeable",
                                "the wall holds the pore liquid: zero relative liquid velocity "
                                "normal to it (false: the liquid drains through the wall)")
                   .when("Type", wall)
                   .byDefault(true));
}

/// The walls of a quasi-2D channel (boundary/SideWalls.hpp, doc/theory.md Sec. 5.7).
void addSideWallKeys(ListSchema& boundary) {
  boundary.add(KeySpec::real("Channel Width (m)", "m",
                             "distance W between the two walls of a quasi-2D channel, out "
                             "of the plane of the section; their width-averaged Coulomb "
                             "friction 2 mu max(-sigma'_zz, 0) / W opposes the solid's motion")
                   .above(0)
                   .when("Type", {"side walls"})
                   .require());
}

ListSchema boundaryKeys() {
  ListSchema boundary;
  boundary.add(KeySpec::choice("Type", deckWords(kBoundaryWords),
                               "solid fixity (node set), impermeable (zero relative liquid "
                               "velocity), traction, liquid pressure (side set), frictional "
                               "wall (Coulomb contact of the solid, side or node set), side "
                               "walls (the two walls of a quasi-2D channel, no set)")
                   .require());
  boundary.add(KeySpec::text("Node Set", "mesh node set")
                   .when("Type", {"solid fixity", "impermeable", "frictional wall"})
                   .requireWhen("Type", {"solid fixity"}));
  boundary.add(
      KeySpec::text("Side Set", "mesh side set")
          .when("Type", {"impermeable", "traction", "liquid pressure", "total head",
                         "pressure series", "infiltration", "seepage face", "frictional wall"})
          .requireWhen("Type", {"traction", "liquid pressure"}));
  boundary.exactlyOneOf({"Node Set", "Side Set"},
                        Condition{"Type", {"impermeable", "frictional wall"}});
  boundary.add(
      KeySpec::choice("Direction", deckWords(kDirectionWords), "velocity components held at zero")
          .when("Type", {"solid fixity"})
          .require());
  boundary.add(KeySpec::reals("Traction (Pa)", "Pa", 2,
                              "total traction (t_x, t_y), tension positive along the outward "
                              "normal")
                   .when("Type", {"traction"})
                   .require());
  boundary.add(KeySpec::real("Pressure (Pa)", "Pa", "prescribed p_L (compression positive)")
                   .when("Type", {"liquid pressure"})
                   .require());
  addFrictionalWallKeys(boundary);
  addSideWallKeys(boundary);
  addHydraulicBoundaryKeys(boundary);
  return boundary;
}

// ---------------------------------------------------------------- implicit seepage (P5)

ListSchema linearSolverKeys() {
  ListSchema linear;
  linear.add(KeySpec::choice("Solver", Words{"gmres", "cg", "direct"},
                             "Belos Krylov solver (cg needs a symmetric system: no "
                             "non-symmetric terms are assembled, so both work), or direct: "
                             "Amesos2 KLU2 sparse LU (symbolic factorisation once per stage; "
                             "Tolerance, Preconditioner ignored; on several MPI ranks the "
                             "matrix is gathered to every rank and factorised there, "
                             "doc/parallel.md)")
                 .byDefault(std::string("gmres")));
  linear.add(KeySpec::real("Tolerance", "-", "relative residual of each linear solve")
                 .above(0)
                 .below(1)
                 .byDefault(1e-12));
  linear.add(KeySpec::integer("Maximum Iterations", "Krylov iterations per solve")
                 .atLeast(1)
                 .byDefault(1000LL));
  linear.add(KeySpec::choice("Preconditioner",
                             Words{"riluk", "ilut", "relaxation", "chebyshev", "none"},
                             "Ifpack2 preconditioner (relaxation: symmetric Gauss-Seidel)")
                 .byDefault(std::string("riluk")));
  linear.add(KeySpec::integer("Fill Level", "riluk/ilut level of fill").atLeast(0).byDefault(1LL));
  linear.add(
      KeySpec::integer("Sweeps", "relaxation sweeps / chebyshev degree").atLeast(1).byDefault(2LL));
  return linear;
}

ListSchema implicitSeepageKeys() {
  ListSchema seepage;
  seepage.add(KeySpec::choice("Nonlinear Solver", Words{"picard", "newton"},
                              "iteration of each step: picard, the mass-conservative modified "
                              "Picard (Celia et al. 1990; symmetric matrix), or newton (full "
                              "Jacobian with the conductivity's pressure derivative: "
                              "non-symmetric, so not with the cg linear solver)")
                  .byDefault(std::string("picard")));
  seepage.add(KeySpec::real("Theta", "-",
                            "theta of the time scheme: 1 backward Euler, 0.5 "
                            "Crank-Nicolson")
                  .atLeast(0.5)
                  .atMost(1)
                  .byDefault(1.0));
  seepage.add(KeySpec::real("Initial Step (s)", "s", "first time step").above(0).byDefault(1.0));
  seepage.add(KeySpec::real("Minimum Step (s)", "s", "a step that fails below this stops the run")
                  .above(0)
                  .byDefault(1e-6));
  seepage.add(
      KeySpec::real("Maximum Step (s)", "s", "largest time step (default: unlimited)").above(0));
  seepage.add(KeySpec::boolean("Adaptive Step",
                               "adapt the step to its time error, the saturation change and the "
                               "Picard iterations (doc/theory.md, 'Time step')")
                  .byDefault(true));
  seepage.add(KeySpec::real("Step Error (Pa)", "Pa",
                            "target local time error of p_L per step (adaptive step): the step "
                            "grows while backward Euler's error, estimated from the change of "
                            "dp_L/dt between steps, stays below it")
                  .above(0)
                  .byDefault(100.0));
  seepage.add(KeySpec::real("Maximum Saturation Change", "-",
                            "target largest |dS_L| of a point per step (adaptive step)")
                  .above(0)
                  .atMost(1)
                  .byDefault(0.05));
  seepage.add(KeySpec::integer("Picard Iterations", "most modified-Picard iterations per step")
                  .atLeast(1)
                  .byDefault(30LL));
  seepage.add(KeySpec::real("Pressure Tolerance (Pa)", "Pa",
                            "converged when the last Picard update changed no p_L by more")
                  .above(0)
                  .byDefault(1e-6));
  seepage.add(KeySpec::real("Mass Tolerance", "-",
                            "converged when the free-node mass residual is below this fraction "
                            "of the storage + flux terms")
                  .above(0)
                  .byDefault(1e-12));
  seepage.add(KeySpec::real("Minimum Suction Fraction", "-",
                            "van Genuchten lambda < 0.5: the Picard matrix takes dS_L/ds at no "
                            "less than this fraction of p_ref (the residual is not changed)")
                  .atLeast(0)
                  .byDefault(1e-2));
  seepage.add(KeySpec::boolean("Reuse Matrix",
                               "keep the first Picard iteration's matrix (and its factorisation "
                               "or preconditioner) for the rest of the step: a chord iteration, "
                               "cheaper per iteration; the residual, hence the converged answer, "
                               "is unchanged")
                  .byDefault(false));
  seepage.add(KeySpec::sublist("Linear Solver", linearSolverKeys(), "Belos + Ifpack2 settings"));
  return seepage;
}

// ---- issue P4: stage relaxation and material changes ----

ListSchema relaxationKeys() {
  ListSchema relaxation;
  relaxation.add(KeySpec::real("Kinetic Energy Ratio", "-",
                               "end the stage when the largest kinetic energy of the last Window "
                               "steps is below this fraction of the stored elastic energy")
                     .above(0)
                     .below(1)
                     .require());
  relaxation.add(KeySpec::real("Window (s)", "s",
                               "time over which the ratio must stay below the tolerance (longer "
                               "than the slowest oscillation period, so a turning point is not "
                               "taken for rest)")
                     .above(0)
                     .require());
  return relaxation;
}

// ---- issue P12: back to the implicit path when the slide stops ----

ListSchema handBackKeys() {
  ListSchema hand_back;
  hand_back.add(KeySpec::real("Largest Speed (m/s)", "m/s",
                              "at rest when no point has moved more than this speed times the "
                              "window's length over a window (a mean speed, robust to "
                              "oscillations)")
                    .above(0)
                    .require());
  hand_back.add(KeySpec::real("Window (s)", "s",
                              "shortest window, judged at the first output at least this long "
                              "after it began (the outputs must be closer than this); a window "
                              "with more motion starts the next one")
                    .above(0)
                    .require());
  return hand_back;
}

ListSchema strengthReductionKeys() {
  ListSchema srm;
  srm.add(KeySpec::real("Initial Factor", "-", "F of the first trial").above(0).byDefault(1.0));
  srm.add(KeySpec::real("Factor Step", "-",
                        "first change of F while no trial has failed (or none has held), "
                        "doubled after each trial in the same direction")
              .above(0)
              .byDefault(0.2));
  srm.add(KeySpec::real("Factor Tolerance", "-",
                        "the search bisects until the lowest failing and the highest holding F "
                        "are at most twice this apart; the result is their mean, +- this")
              .above(0)
              .byDefault(0.01));
  srm.add(KeySpec::real("Minimum Factor", "-", "the search ends when a trial at this F fails")
              .above(0)
              .byDefault(0.1));
  srm.add(KeySpec::real("Maximum Factor", "-", "the search ends when a trial at this F holds")
              .above(0)
              .byDefault(5.0));
  srm.add(KeySpec::choice("Failure Criterion", deckWords(kStrengthReductionCriterionWords),
                          "what makes a trial fail: non-convergence = not at rest (stage "
                          "Relaxation) at the end of its Duration (s); accelerating "
                          "displacement = the mobilised mass (points that moved at least half "
                          "the most) moves faster in the trial's last quarter than in its "
                          "third, and at least Minimum Displacement (m) in all; either = "
                          "either of them; continuing displacement = the mobilised mass still "
                          "moves at least Minimum Displacement (m) over the trial's last quarter "
                          "(under Local Damping a failing mass slides at a steady rate rather "
                          "than faster, while one that holds comes to rest). The CSV reports "
                          "all three for every trial")
              .byDefault(std::string("non-convergence")));
  srm.add(KeySpec::real("Minimum Displacement (m)", "m",
                        "mean displacement of the mobilised mass that counts as motion: over "
                        "the whole trial for accelerating displacement (below it a trial does "
                        "not fail), over the trial's last quarter for continuing displacement "
                        "(at or above it a trial fails)")
              .above(0)
              .byDefault(1e-3));
  return srm;
}

ListSchema materialChangeKeys() {
  ListSchema change;
  change.add(
      KeySpec::real("Young's Modulus (Pa)", "Pa", "new drained Young's modulus E'").above(0));
  change.add(
      KeySpec::real("Poisson's Ratio", "-", "new drained Poisson's ratio").above(-1).below(0.5));
  change.add(KeySpec::real("Cohesion (Pa)", "Pa", "new effective cohesion c' (Mohr-Coulomb models)")
                 .atLeast(0));
  change.add(
      KeySpec::real("Friction Angle (deg)", "deg", "new friction angle (Mohr-Coulomb models)")
          .atLeast(0)
          .below(90));
  change.add(
      KeySpec::real("Dilatancy Angle (deg)", "deg", "new dilatancy angle (Mohr-Coulomb models)")
          .atLeast(0)
          .below(90));
  change.add(
      KeySpec::real("Tensile Strength (Pa)", "Pa", "new tension cut-off (Mohr-Coulomb models)")
          .atLeast(0));
  change.add(KeySpec::real("Intrinsic Permeability (m2)", "m2",
                           "new kappa (k_sat follows with the material's rho_L, mu_L, g = 9.81)")
                 .above(0));
  change.add(KeySpec::real("Saturated Conductivity (m/s)", "m/s",
                           "new k_sat (kappa follows); not with Intrinsic Permeability (m2)")
                 .above(0));
  return change;
}

// ---- end of issue P4 stage keys ----

ListSchema stageKeys() {
  ListSchema stage;
  stage.add(KeySpec::choice("Solver", deckWords(kSolverWords),
                            "what moves: explicit dynamic MPM, fixed skeleton (seepage only), "
                            "quasi-static, or implicit seepage")
                .require());
  stage.add(KeySpec::real("Duration (s)", "s", "length of the stage").above(0).require());
  stage.add(KeySpec::real("Gravity (m/s2)", "m/s2", "gravity magnitude, acting in -y; 0: off")
                .atLeast(0)
                .byDefault(9.81));
  stage.add(KeySpec::real("Local Damping", "-", "alpha: damping force = -alpha |f| sign(v)")
                .atLeast(0)
                .below(1)
                .byDefault(0.0));
  stage.add(KeySpec::choice("Local Damping Form", Words{"start-of-step", "dissipative"},
                            "start-of-step: D = -alpha |F| sign(v^k), v^k the nodal velocity "
                            "at the start of the step (Anura3D's form); adds alpha |F| in the "
                            "sign-alternating mode of an explicit instability, so a damped "
                            "stage can be unstable below the criteria's step; dissipative: D = "
                            "-sign(vbar) min(alpha |F|, m |vbar| / dt), vbar = v^k + dt F / "
                            "(2m) the step's mean velocity: never adds energy, stable wherever "
                            "the undamped step is; the same as start-of-step on a node moving "
                            "steadily (doc/theory.md Sec. 3.5, doc/stability.md)")
                .byDefault(std::string("start-of-step"))
                .when("Solver", {"explicit", "fixed skeleton", "quasi-static"}));
  stage.add(KeySpec::choice("Liquid At Solid Fixities", Words{"velocity", "relative velocity"},
                            "at a node direction with a solid fixity and no impermeable lock, "
                            "after the remap: velocity: the liquid keeps its mapped velocity "
                            "v_L (the thesis), so all of it is Darcy flux against the fixed "
                            "solid, including the motion both phases share that the fixity "
                            "removes from the solid (a point's grid-invisible FLIP velocity, "
                            "a body sliding onto a fixed base); relative velocity: it keeps "
                            "v_L - v_S as mapped (doc/theory.md Sec. 5.1)")
                .byDefault(std::string("velocity"))
                .when("Solver", {"explicit", "quasi-static"}));
  stage.add(KeySpec::choice("Hydraulic Loads",
                            Words{kHydraulicLoadsByMesh, "on free sides", "at boundary points",
                                  "through the soil"},
                            "where the pressure of total head and pressure series conditions "
                            "loads the soil: on free sides: integrated along the free sides "
                            "and given to their end nodes (the thesis), right where the mesh "
                            "follows the surface; at boundary points: each node's load passed "
                            "through the points that carry the node to their shape functions "
                            "at their outer edge, for a surface that cuts through its cells "
                            "(a soil region in a rectangle grid: on free sides put +70 kPa "
                            "on a surface point of the grid levee; doc/theory.md Sec. 5.5); "
                            "through the soil: the total head's hydrostatic pressure as a "
                            "field over the soil's points, -sum_p V grad(N_i p^) (Gauss's "
                            "theorem), so it meets the surface where the points' stresses "
                            "end (one total-head condition; its level's pressure must be 0 "
                            "or linear suction above it; free sides below the level outside "
                            "its zone must be fixed and sealed; other loads at boundary "
                            "points; doc/theory.md Sec. 5.5, Loads through the soil); "
                            "by mesh: at boundary points on a rectangle with Regions, on free "
                            "sides on every other mesh (whose elements follow the soil's "
                            "outline)")
                .byDefault(std::string(kHydraulicLoadsByMesh))
                .when("Solver", {"explicit", "fixed skeleton", "quasi-static"}));
  stage.add(KeySpec::choice("Surfaces Without Condition", Words{"atmosphere", "open"},
                            "the liquid's rule on free sides that no hydraulic condition covers "
                            "(a crest, the faces of a crack or of the slid mass): atmosphere: "
                            "the rule of a seepage face, which drains where p_L >= 0 and lets "
                            "no liquid in at suction, since the air holds no water to give; "
                            "open: the natural condition of the liquid momentum balance (4.36), "
                            "p_L = 0, which draws water in at suction as if a film of water "
                            "covered the surface (the thesis; 0.014 m3/m into the crest of "
                            "the levee drawdown, doc/verification.md). The implicit seepage "
                            "path keeps its natural condition, no flux")
                .byDefault(std::string("atmosphere"))
                .when("Solver", {"explicit", "fixed skeleton", "quasi-static"}));
  stage.add(KeySpec::choice("Interior Liquid Balance", Words{"point", "conservative"},
                            "point: each point's liquid changes by its own mass balance, -dt V "
                            "div(c w) (4.12, the thesis); where a cell inside the body is "
                            "unevenly filled (a crack at the tension cut-off, a swollen cell of "
                            "a slide) this makes or destroys liquid that no boundary passes "
                            "(the boundary-flux CSV's net_inflow_interior_nodes; 2.4 L/m into "
                            "the default levee as it drains, doc/verification.md); "
                            "conservative: at every node inside the body or on sides that "
                            "impermeable conditions seal, under no hydraulic condition, what "
                            "the point balance makes is "
                            "given back by the points that carry the node, in proportion to "
                            "their N n S_L V, so the body's liquid changes only at its boundary "
                            "(doc/theory.md Sec. 5.5)")
                .byDefault(std::string("point"))
                .when("Solver", {"explicit", "fixed skeleton", "quasi-static"}));
  stage.add(
      KeySpec::choice(
          "Free Surface Liquid Pressure", Words{"zero", "suction held"},
          "zero: the liquid's natural condition p_L = 0 wherever the points "
          "end, on the free sides and inside part-filled cells (4.36, the "
          "thesis); at suction the air then pulls on the soil's water; "
          "suction held: where a node's liquid is at suction the surface "
          "carries that suction (menisci), so nothing pulls water from the "
          "air; at p_L >= 0 the surface stays at 0; changes only nodes whose "
          "support a surface cuts; needs Interior Liquid Balance: conservative (doc/theory.md "
          "Sec. 5.5)")
          .byDefault(std::string("zero"))
          .when("Solver", {"explicit", "fixed skeleton", "quasi-static"}));
  stage.add(
      KeySpec::real("Mass Scaling", "-", "factor on the nodal masses").atLeast(1).byDefault(1.0));
  Words transfers = deckWords(kTransferSchemeWords);
  transfers.push_back(kTransferByShapeFunctions);
  stage.add(KeySpec::choice("Velocity Transfer", transfers,
                            "FLIP: v_p += dt sum N a_i (the thesis, 7.10-7.11), optionally "
                            "blended with PIC; APIC: affine particle-in-cell (Jiang et al. "
                            "2015), v_p and an affine velocity matrix C_p from the grid for both "
                            "phases, conserving angular momentum and leaving no point velocity "
                            "the grid cannot see; TPIC: v_p from the grid, C_p the velocity "
                            "gradient of the remapped field, robust where points barely reach a "
                            "node (doc/theory.md Sec. 3.11); XPIC: extended PIC of order m "
                            "(Hammerquist and Nairn 2017), FLIP's update with the grid-invisible "
                            "part of the point velocities removed each step and a resolved mode "
                            "damped by (1 - lambda)^m instead of PIC's (1 - lambda) (XPIC Order); "
                            "by shape functions: APIC on GIMP "
                            "and B-spline meshes (the scheme for failure stages), FLIP on "
                            "linear shapes (the thesis; doc/theory.md, 'The scheme for failure "
                            "stages')")
                .byDefault(std::string(kTransferByShapeFunctions))
                .when("Solver", {"explicit", "quasi-static", "fixed skeleton"}));
  stage.add(KeySpec::integer("XPIC Order",
                             "m of XPIC(m): the degree of the polynomial in S+ S that filters "
                             "the point velocities each step, m - 1 extra G2P/P2G passes; 1 is "
                             "PIC, 2 already keeps a resolved mode to (kh)^4 per step; at most 8 "
                             "with the binomial series (its alternating terms lose digits "
                             "beyond), 32 with Chebyshev's (doc/theory.md Sec. 3.6)")
                .atLeast(1)
                .atMost(32)
                .byDefault(2LL)
                .when("Velocity Transfer", {"XPIC"}));
  stage.add(KeySpec::choice("XPIC Polynomial", {"binomial", "Chebyshev"},
                            "binomial: [I - (I - S+ S)^m] (Hammerquist and Nairn 2017), a mode "
                            "of the round trip's eigenvalue lambda keeps 1 - (1 - lambda)^m; "
                            "Chebyshev: the same m - 1 passes as a Chebyshev iteration towards "
                            "the consistent-mass projection, keeping 1 - (1 - lambda)^j "
                            "s_k(lambda)^2 (k = (m - 1) / 2, j = m - 2k), nearly all of every "
                            "mode with lambda >= XPIC Lower Eigenvalue, never more than all")
                .byDefault(std::string("binomial"))
                .when("Velocity Transfer", {"XPIC"}));
  stage.add(KeySpec::real("XPIC Lower Eigenvalue", "-",
                          "a: the lower end of the eigenvalues of S+ S that the Chebyshev "
                          "polynomial keeps (m = 9, a = 0.05: at least 90.5 % of every such "
                          "mode each step; the smaller a, the larger m it needs)")
                .above(0)
                .below(1)
                .byDefault(0.05)
                .when("XPIC Polynomial", {"Chebyshev"}));
  stage.add(KeySpec::real("Solid PIC Fraction", "-",
                          "share of the PIC update in the solid point velocities, per step; "
                          "0: FLIP (the thesis); removes point-scale velocity noise in "
                          "about dt / fraction")
                .atLeast(0)
                .atMost(1)
                .byDefault(0.0)
                .when("Velocity Transfer", {"FLIP", kTransferByShapeFunctions}));
  stage.add(KeySpec::real("Solid PIC Rate (1/s)", "1/s",
                          "rate at which the solid point velocities relax towards the grid's: "
                          "each step of dt takes a share 1 - exp(-rate dt) of the grid's "
                          "update (PIC's with FLIP, APIC's velocity and C_p with APIC) and the "
                          "rest from FLIP's v_p + dt sum N a_i, so the velocity the grid cannot "
                          "see decays as exp(-rate t) whatever the step; omitted: FLIP takes "
                          "Solid PIC Fraction per step, APIC the grid's update in full (an "
                          "infinite rate), whose loss at every transfer makes a slide's run-out "
                          "depend on the step (doc/theory.md Sec. 3.11)")
                .above(0)
                .when("Velocity Transfer", {"FLIP", "APIC", kTransferByShapeFunctions}));
  stage.add(KeySpec::real("Liquid PIC Rate (1/s)", "1/s",
                          "the liquid's as Solid PIC Rate: with FLIP Liquid PIC Fraction = 1 - "
                          "exp(-rate dt) each step (the relative velocity's grid share), with "
                          "APIC the share of APIC's liquid update, the rest FLIP's; omitted: "
                          "Liquid PIC Fraction (FLIP), APIC in full (the liquid, drag-locked to "
                          "the solid, carries a share of the mixture's momentum and loses it at "
                          "every transfer as the solid does)")
                .above(0)
                .when("Velocity Transfer", {"FLIP", "APIC", kTransferByShapeFunctions}));
  stage.add(KeySpec::real("Liquid PIC Fraction", "-",
                          "share per step of the grid's relative velocity v_L - v_S in the "
                          "liquid point velocities (PIC for the Darcy part); 0: FLIP (the "
                          "thesis); keep 0 with mass scaling (doc/theory.md Sec. 3.6)")
                .atLeast(0)
                .atMost(1)
                .byDefault(0.0)
                .when("Velocity Transfer", {"FLIP", kTransferByShapeFunctions}));
  stage.add(KeySpec::choice("Liquid Drag", Words{"explicit", "implicit"},
                            "explicit: the Darcy drag Q_L (v_L - v_S) at t^k (Eq. 4.36, the "
                            "thesis), which bounds the step by about 2 rho_L k / (n S_L g) "
                            "times the mass scaling (the criteria's drag terms); implicit: "
                            "the drag at the new velocities, solved node by node with the "
                            "mixture equation (backward Euler in the drag, stable for any k): "
                            "the criteria drop their drag terms; the stage needs 'cfl undrained' "
                            "and 'consolidation' or 'infiltration' among its criteria "
                            "(doc/theory.md Sec. 3.1, doc/stability.md)")
                .byDefault(std::string("explicit"))
                .when("Solver", {"explicit", "fixed skeleton", "quasi-static"}));
  stage.add(KeySpec::choice("Liquid Pressure", Words{"free", "held"},
                            "free: the liquid flows and p_L follows the mass balance; held: "
                            "p_L and S_L stay as the stage finds them and the liquid moves "
                            "with the solid, so the skeleton settles into equilibrium with "
                            "the pore pressure a previous (implicit seepage) stage left "
                            "(drained hand-over; the liquid mass follows the pore volume)")
                .byDefault(std::string("free"))
                .when("Solver", {"quasi-static"}));
  stage.add(KeySpec::real("Output Interval (s)", "s", "time between outputs; 0: end of stage only")
                .atLeast(0)
                .byDefault(0.0));
  stage.add(KeySpec::boolean("Reset Displacements", "zero the displacements when the stage starts")
                .byDefault(false));
  stage.add(KeySpec::sublist("Time Step", timeStepKeys(), "time-step control"));
  stage.add(KeySpec::namedSublists("Boundary Conditions", "condition", boundaryKeys(),
                                   "boundary conditions of this stage"));
  stage.add(KeySpec::sublist("Implicit Seepage", implicitSeepageKeys(),
                             "settings of an implicit seepage stage (explicit stages: of the "
                             "rest of the stage after Hand Back At Rest)")
                .when("Solver", {"implicit seepage", "explicit"}));
  // issue P4
  stage.add(KeySpec::sublist("Relaxation", relaxationKeys(),
                             "end the stage early once quasi-static (Duration (s) is then the "
                             "maximum)"));
  stage.add(KeySpec::sublist("Hand Back At Rest", handBackKeys(),
                             "once nothing moves, run the rest of the stage on the implicit "
                             "seepage path (fixed skeleton; the stage's conditions and "
                             "Implicit Seepage settings)")
                .when("Solver", {"explicit"}));
  stage.add(KeySpec::real("Hand Over Below Factor Of Safety", "-",
                          "end the stage at the first output whose factor of safety (deck "
                          "section Factor Of Safety) is below this, e.g. 1.0: the next stage "
                          "(e.g. explicit MPM) starts from that state")
                .above(0));
  stage.add(KeySpec::sublist("Strength Reduction", strengthReductionKeys(),
                             "make the stage a strength-reduction analysis (P13): trials from "
                             "the state the stage finds, each with c, tan phi (and the suction "
                             "terms) and the cut-off of the Mohr-Coulomb materials divided by F "
                             "and Duration (s) of the stage's quasi-static steps; needs "
                             "Relaxation; writes <Name>_strength_reduction.csv and "
                             "<Name>_strength_reduction_points.csv and leaves the state as it "
                             "found it")
                .when("Solver", {"quasi-static"}));
  stage.add(KeySpec::namedSublists("Material Changes", "material", materialChangeKeys(),
                                   "new parameters of materials (entry name = material name), "
                                   "applied when the stage starts"));
  return stage;
}

// ---------------------------------------------------------------- Output and the deck

// ---- issue P8: checkpoints (doc/checkpoints.md) ----

ListSchema checkpointKeys() {
  ListSchema checkpoint;
  checkpoint.add(KeySpec::integer("Every Steps",
                                  "write `<Name>.checkpoint` in the output directory after every "
                                  "this many time steps (counted over all stages); 0: never")
                     .atLeast(0)
                     .byDefault(0LL));
  checkpoint.add(KeySpec::real("Wall Interval (min)", "min",
                               "write it when this much wall time has passed since the run (or "
                               "restart) began or the last checkpoint; 0: never")
                     .atLeast(0)
                     .byDefault(0.0));
  return checkpoint;
}

// ---- end of issue P8 deck keys ----

// ---- issue P13: factor of safety (simulation/FactorOfSafetyMonitor.hpp) ----

ListSchema factorOfSafetyKeys() {
  ListSchema fs;
  fs.add(KeySpec::choice("Method", Words{"bishop", "spencer"},
                         "bishop: Bishop's simplified method (moment equilibrium, horizontal "
                         "interslice forces); spencer: Spencer's method (force and moment "
                         "equilibrium, interslice forces at one inclination), moments about "
                         "each circle's centre; the CSV also gives Bishop's and the ordinary "
                         "method's F on the critical circle")
             .byDefault(std::string("bishop")));
  fs.add(KeySpec::reals("Centre X (m)", "m", 2,
                        "range of the trial circles' centre abscissae; default: the ground's "
                        "extent within Mass X Range (m)"));
  fs.add(KeySpec::reals("Centre Y (m)", "m", 2,
                        "range of the centre elevations; default: from the top of the ground "
                        "to twice the height of the section above it"));
  fs.add(KeySpec::reals("Tangent Y (m)", "m", 2,
                        "range of the elevations the circles are tangent to (radius = centre y "
                        "- tangent y); default: from the bottom of the points to the top of the "
                        "ground"));
  fs.add(KeySpec::integer("Grid Count",
                          "points per range of the search grid (centre x, centre "
                          "y, tangent: count^3 circles a pass)")
             .atLeast(2)
             .atMost(101)
             .byDefault(11LL));
  fs.add(KeySpec::integer("Refinements",
                          "passes after the first, each around the best circle with a spacing "
                          "about (count - 1) / 2 times finer")
             .atLeast(0)
             .atMost(20)
             .byDefault(3LL));
  fs.add(KeySpec::integer("Search Starts",
                          "refinements start from this many of the first pass's local minima, "
                          "lowest first; the lowest F of all is the result (1: from the best "
                          "grid point only)")
             .atLeast(1)
             .atMost(100)
             .byDefault(8LL));
  fs.add(KeySpec::integer("Slices", "slices of each trial mass")
             .atLeast(5)
             .atMost(2000)
             .byDefault(50LL));
  fs.add(KeySpec::real("Minimum Depth (m)", "m",
                       "circles reaching less than this below the ground are not tried (a "
                       "cohesionless slope's critical circle otherwise shrinks to its skin)")
             .atLeast(0)
             .byDefault(0.0));
  fs.add(KeySpec::reals("Mass X Range (m)", "m", 2,
                        "the sliding mass must lie between these abscissae (e.g. the landside "
                        "of a levee); default: anywhere"));
  fs.add(KeySpec::choice("Suction Strength", Words{"solid model", "vanapalli", "fredlund", "none"},
                         "shear strength from matric suction s = -p_L on the slip surface: "
                         "solid model = the materials' own (c(s), phi(s) of the suction-"
                         "dependent Mohr-Coulomb, Eqs. 4.23-4.26, and Bishop's chi = S_L, Eq. "
                         "4.5: the MPM's strength); vanapalli = s S_e tan(phi') (Eq. 5.1); "
                         "fredlund = s tan(phi_b) (Eq. 5.2); none = suction ignored")
             .byDefault(std::string("solid model")));
  fs.add(KeySpec::real("Suction Friction Angle (deg)", "deg", "phi_b of the fredlund form")
             .atLeast(0)
             .below(90)
             .when("Suction Strength", {"fredlund"})
             .require());
  fs.add(KeySpec::reals("Ground Surface (m)", "m", 0,
                        "ground polyline x0, y0, x1, y1, ... (x increasing); default: the upper "
                        "envelope of the material points at each evaluation"));
  fs.add(KeySpec::real("Cell Size (m)", "m",
                       "cell of the raster that averages the points' weights, p_L and S_L; 0: "
                       "twice the median point spacing")
             .atLeast(0)
             .byDefault(0.0));
  fs.add(KeySpec::boolean("Slice Table",
                          "also write the critical circle's slices at each "
                          "evaluation to <Name>_critical_slices.csv")
             .byDefault(true));
  return fs;
}

// ---- end of issue P13 deck keys ----

ListSchema outputKeys() {
  ListSchema output;
  output.add(KeySpec::text("Directory", "results directory (relative to the working directory)")
                 .byDefault(std::string("results")));
  output.add(KeySpec::text("Name", "file stem: `<Name>_grid.e`, `<Name>_points.e`")
                 .byDefault(std::string("argine")));
  output.add(KeySpec::sublist("Checkpoint", checkpointKeys(),
                              "restart files, continued by `argine run DECK --restart FILE` (P8)"));
  return output;
}

// ---- issue P4: initialisation and probes ----

ListSchema initialisationKeys() {
  ListSchema init;
  init.add(KeySpec::choice("Method", deckWords(kInitialisationWords),
                           "uniform: each material's Initial State; K0 procedure: geostatic "
                           "stress and hydrostatic p_L from the surfaces below (thesis Ch. 4 "
                           "Sec. 5.1); pore pressure: p_L (and S_L, k, M_L) from a phreatic "
                           "surface or a table, the stress each material's Initial State")
               .byDefault(std::string("uniform")));
  init.add(KeySpec::reals("Ground Surface (m)", "m", 0,
                          "ground surface as x0, y0, x1, y1, ... (x increasing; flat beyond the "
                          "ends); the overburden is integrated from it down")
               .when("Method", {"K0 procedure"})
               .require());
  init.add(KeySpec::reals("Phreatic Surface (m)", "m", 0,
                          "zero-pressure surface as x0, y0, x1, y1, ... (x increasing); above the "
                          "ground it is an outside water level whose weight loads the ground. "
                          "Absent: each material's uniform Initial State p_L. With pore "
                          "pressure: p_L = rho_L g (y_ph(x) - y)")
               .when("Method", {"K0 procedure", "pore pressure"}));
  init.add(KeySpec::real("Maximum Suction (Pa)", "Pa",
                         "cap on the suction above the phreatic surface (Fig. 4.7 a); absent: "
                         "linear hydrostatic suction (Fig. 4.7 b)")
               .atLeast(0)
               .when("Method", {"K0 procedure", "pore pressure"}));
  init.add(KeySpec::reals("Pore Pressure Table", "m, Pa", 0,
                          "p_L as a function of height: pairs y0, p0, y1, p1, ... (y increasing; "
                          "linear between, constant beyond the ends), the same at every x")
               .when("Method", {"pore pressure"}));
  init.exactlyOneOf({"Phreatic Surface (m)", "Pore Pressure Table"},
                    Condition{"Method", {"pore pressure"}});
  return init;
}

ListSchema pointProbeKeys() {
  ListSchema point;
  point.add(
      KeySpec::reals("Position (m)", "m", 2, "initial position; the nearest point is followed")
          .require());
  point.add(KeySpec::real("Tolerance (m)", "m", "the nearest point must lie this close")
                .above(0)
                .require());
  return point;
}

ListSchema sectionProbeKeys() {
  ListSchema section;
  section.add(KeySpec::choice("Type", deckWords(kSectionWords),
                              "band: every point within Width/2 of the segment (one row per "
                              "point); profile: p_L and S_L at Samples positions along it")
                  .require());
  section.add(KeySpec::reals("From (m)", "m", 2, "start of the segment").require());
  section.add(KeySpec::reals("To (m)", "m", 2, "end of the segment").require());
  section.add(KeySpec::real("Width (m)", "m",
                            "band width; for a profile the diameter of the averaging disc "
                            "around each sample (inverse-distance weights)")
                  .above(0)
                  .require());
  section.add(KeySpec::integer("Samples", "sample positions of a profile (ends included)")
                  .atLeast(2)
                  .atMost(100000)
                  .when("Type", {"profile"})
                  .byDefault(10LL));
  return section;
}

ListSchema probeKeys() {
  ListSchema probes;
  probes.add(KeySpec::real("Interval (s)", "s", "time between probe rows; 0: at every output")
                 .atLeast(0)
                 .byDefault(0.0));
  probes.add(
      KeySpec::namedSublists("Points", "point", pointProbeKeys(),
                             "material points followed by id; file <Name>_probe_<point>.csv"));
  probes.add(KeySpec::namedSublists("Sections", "section", sectionProbeKeys(),
                                    "line sections; file <Name>_section_<section>.csv"));
  return probes;
}

// ---- end of issue P4 deck keys ----

// ---- issue P8: physical guards ----

ListSchema guardKeys() {
  ListSchema guards;
  guards.add(
      KeySpec::choice("Points Leaving Mesh", Words{"stop", "remove"},
                      "material points that leave the background mesh: stop (the run "
                      "ends with an error naming time, step, point id and position; the "
                      "last output is kept) or remove (taken out of the computation: "
                      "velocities set to zero, frozen where they left; counted in the log and in "
                      "the diagnostics' lost_points)")
          .byDefault(std::string("stop")));
  guards.add(KeySpec::real("Mass Balance Bound", "-",
                           "warn once when |liquid storage change - net inflow through the "
                           "nodes| exceeds this fraction of the initial liquid volume "
                           "(checked in explicit stages of runs with hydraulic conditions)")
                 .above(0)
                 .byDefault(1e-3));
  guards.add(KeySpec::real("Kinetic Energy Bound", "-",
                           "warn once when the kinetic energy exceeds this fraction of the "
                           "stage's energy scale (potential energy above the mesh's lowest "
                           "point + stored and kinetic energy at the stage start + loads x "
                           "mesh extent + energy of the liquid that entered: the most a "
                           "stable stage can turn into motion; the run stops at 1 x the "
                           "scale)")
                 .above(0)
                 .byDefault(0.1));
  return guards;
}

// ---- end of issue P8 deck keys ----

// ---- issue P7 deck keys ----

ListSchema parallelKeys() {
  ListSchema parallel;
  parallel.add(KeySpec::boolean("Reproducible Sums",
                                "node sums binned and rounded once (doc/parallel.md): the "
                                "results do not depend on the number of MPI ranks or on the "
                                "order of the points, also through local damping; the "
                                "particle-to-grid kernels cost many times more (about 6x the "
                                "whole step on a 1e5-point block)")
                   .byDefault(false));
  return parallel;
}

ListSchema makeDeckSchema() {
  ListSchema deck;
  deck.add(
      KeySpec::text("Title", "a title for logs and output").allowEmpty().byDefault(std::string()));
  deck.add(KeySpec::sublist("Mesh", meshKeys(), "background mesh").require());
  deck.add(KeySpec::namedSublists("Materials", "material", materialKeys(),
                                  "materials, each filling one element block")
               .require()
               .atLeastOneEntry());
  deck.add(
      KeySpec::namedSublists("Stages", "stage", stageKeys(), "stages, run in the order written")
          .require()
          .atLeastOneEntry());
  deck.add(KeySpec::sublist("Output", outputKeys(), "result files"));
  // issue P4
  deck.add(KeySpec::sublist("Initialisation", initialisationKeys(),
                            "initial stress and liquid pressure of the points"));
  deck.add(KeySpec::sublist("Probes", probeKeys(), "CSV time series of points and sections"));
  deck.add(KeySpec::sublist("Guards", guardKeys(), "physical guards checked after each step"));
  deck.add(KeySpec::sublist("Parallel", parallelKeys(), "how a run over MPI ranks adds up"));
  deck.add(KeySpec::sublist("Factor Of Safety", factorOfSafetyKeys(),
                            "limit equilibrium (Bishop's simplified method, critical circle) on "
                            "the points' state at every output; <Name>_factor_of_safety.csv"));
  checkSchema(deck);
  return deck;
}

}  // namespace

const ListSchema& deckSchema() {
  static const ListSchema schema = makeDeckSchema();
  return schema;
}

}  // namespace argine
