// A strength-reduction stage (P13 item 3): the factors it tries
// (StrengthReductionSearch), the displacement criterion (StrengthReductionTrial), the deck's
// needs, and a run on a dry slope: it brackets FS_SRM to the tolerance, its failure
// mechanism follows the limit-equilibrium critical circle, and it leaves the state as it
// found it.
#include <gtest/gtest.h>

#include <Teuchos_YamlParameterListCoreHelpers.hpp>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <stdexcept>

#include "CsvRows.hpp"
#include "DrySlopeDeck.hpp"
#include "QuietRun.hpp"
#include "argine/core/Error.hpp"
#include "argine/input/DeckReader.hpp"
#include "argine/simulation/Simulation.hpp"
#include "argine/simulation/StrengthReductionSearch.hpp"
#include "argine/simulation/StrengthReductionTrial.hpp"

namespace argine {
namespace {

/// Runs the search against a slope whose trials fail above `limit` (by `criterion`'s sense
/// of failure: both flags set) and returns the factors tried.
std::vector<Real> searchAgainst(StrengthReductionSearch& search, Real limit) {
  std::vector<Real> tried;
  while (!search.done()) {
    const Real f = search.next();
    tried.push_back(f);
    StrengthReductionTrial trial;
    trial.factor = f;
    trial.converged = f <= limit;
    trial.accelerating = f > limit;
    search.record(trial);
  }
  return tried;
}

/// Runs a search that follows `criterion` to its end, each trial judged by `judge(trial)`
/// (its factor set).
template <class Judge>
StrengthReductionSearch searchJudgedBy(StrengthReductionCriterion criterion, Judge judge) {
  StrengthReductionSpec spec;
  spec.criterion = criterion;
  StrengthReductionSearch search(spec);
  while (!search.done()) {
    StrengthReductionTrial trial;
    trial.factor = search.next();
    judge(trial);
    search.record(trial);
  }
  return search;
}

TEST(StrengthReductionSearch, BracketsThenBisects) {
  StrengthReductionSpec spec;  // F from 1, step 0.2, tolerance 0.01, within [0.1, 5]
  StrengthReductionSearch search(spec);
  const std::vector<Real> tried = searchAgainst(search, 1.337);
  // 1 and 1.2 hold, 1.6 (step doubled to 0.4) fails; bisection 1.4 f, 1.3 h, 1.35 f, 1.325 h,
  // 1.3375 f: holding 1.325, failing 1.3375, half width 0.00625 <= 0.01.
  const std::vector<Real> expected{1, 1.2, 1.6, 1.4, 1.3, 1.35, 1.325, 1.3375};
  ASSERT_EQ(tried.size(), expected.size());
  for (std::size_t k = 0; k < tried.size(); ++k) EXPECT_NEAR(tried[k], expected[k], 1e-12);
  const StrengthReductionBracket b = search.result();
  EXPECT_TRUE(b.closed());
  EXPECT_TRUE(b.ordered);
  EXPECT_NEAR(b.factor(), 1.33125, 1e-12);
  EXPECT_NEAR(b.halfWidth(), 0.00625, 1e-12);
}

TEST(StrengthReductionSearch, DownwardsAndAtTheLimits) {
  StrengthReductionSpec spec;
  StrengthReductionSearch down(spec);
  searchAgainst(down, 0.5);  // 1 f, 0.8 f, 0.4 h, then bisection
  const StrengthReductionBracket b = down.result();
  EXPECT_LE(b.holding, 0.5);
  EXPECT_GT(b.failing, 0.5);
  EXPECT_LE(b.halfWidth(), 0.01);
  EXPECT_NEAR(down.trials()[2].factor, 0.4, 1e-12);

  StrengthReductionSearch strong(spec);  // never fails: 1, 1.2, 1.6, 2.4, 4.0, 5.0 (maximum)
  const std::vector<Real> up = searchAgainst(strong, 1e9);
  EXPECT_EQ(up.size(), 6u);
  EXPECT_NEAR(up.back(), 5, 1e-12);
  EXPECT_FALSE(strong.result().closed());
  EXPECT_NEAR(strong.result().holding, 5, 1e-12);

  StrengthReductionSearch weak(spec);  // always fails: 1, 0.8, 0.4, 0.1 (minimum)
  const std::vector<Real> fallen = searchAgainst(weak, 0);
  EXPECT_EQ(fallen.size(), 4u);
  EXPECT_NEAR(fallen.back(), 0.1, 1e-12);
  EXPECT_EQ(weak.result().holding, 0);
}

TEST(StrengthReductionSearch, EachCriterionHasItsBracket) {
  // non-convergence above 1.1, accelerating displacement only above 1.17
  const StrengthReductionSearch search =
      searchJudgedBy(StrengthReductionCriterion::NonConvergence, [](StrengthReductionTrial& t) {
        t.converged = t.factor <= 1.1;
        t.accelerating = t.factor > 1.17;
      });
  const auto nc = search.bracket(StrengthReductionCriterion::NonConvergence);
  const auto ad = search.bracket(StrengthReductionCriterion::AcceleratingDisplacement);
  EXPECT_LE(nc.halfWidth(), 0.01);
  EXPECT_LE(nc.holding, 1.1);
  EXPECT_GT(nc.failing, 1.1);
  // 1 holds, 1.2 fails by both; bisection 1.1, 1.15, ... below 1.2: 1.2 is the only trial
  // above 1.17
  EXPECT_NEAR(ad.failing, 1.2, 1e-12);
  EXPECT_LE(ad.holding, 1.17);
  EXPECT_GT(ad.halfWidth(), nc.halfWidth());
  // either: the lower of the two
  EXPECT_EQ(search.bracket(StrengthReductionCriterion::Either).failing, nc.failing);
}

TEST(DisplacementTrend, ContinuingIsTheLastQuartersMotion) {
  // point 0 slides along x at a steady 2 mm/s from 1 to 3 s (not faster): 2 mm in the last
  // interval, not accelerating; with a minimum of 2.5 mm it is not continuing either
  const std::vector<Real> start{0, 0, 0, 0};
  const std::vector<Real> a{0.010, 0, 0, 0};
  const std::vector<Real> b{0.012, 0, 0, 0};
  const std::vector<Real> c{0.014, 0, 0, 0};
  const DisplacementTrend steady = displacementTrend(start, a, b, c, 1, 2, 3, 1e-3);
  EXPECT_NEAR(steady.later_rate, 0.002, 1e-15);
  EXPECT_FALSE(steady.accelerating);
  EXPECT_TRUE(steady.continuing);
  EXPECT_FALSE(displacementTrend(start, a, b, c, 1, 2, 3, 2.5e-3).continuing);
  // a mass that came to rest after the first interval: 10 mm moved, none in the last
  const std::vector<Real> rest{0.012, 0, 0, 0};
  EXPECT_FALSE(displacementTrend(start, a, b, rest, 1, 2, 3, 1e-3).continuing);
  // the last interval 0.5 s long: 1.1 mm in it (2.2 mm/s) counts at a 1 mm minimum, not at
  // 1.5 mm: the displacement over the interval is what counts, not the rate
  const std::vector<Real> c_short{0.0131, 0, 0, 0};
  const DisplacementTrend short_last = displacementTrend(start, a, b, c_short, 1, 2, 2.5, 1e-3);
  EXPECT_NEAR(short_last.later_rate, 0.0022, 1e-12);
  EXPECT_TRUE(short_last.continuing);
  EXPECT_FALSE(displacementTrend(start, a, b, c_short, 1, 2, 2.5, 1.5e-3).continuing);
}

TEST(StrengthReductionSearch, ContinuingDisplacementHasItsOwnBracket) {
  // relaxed up to 1.12, still moving above 1.09, accelerating nowhere
  const StrengthReductionSearch search = searchJudgedBy(
      StrengthReductionCriterion::ContinuingDisplacement, [](StrengthReductionTrial& t) {
        t.converged = t.factor <= 1.12;
        t.continuing = t.factor > 1.09;
        EXPECT_EQ(t.failed(StrengthReductionCriterion::ContinuingDisplacement), t.continuing);
        EXPECT_EQ(t.failed(StrengthReductionCriterion::Either), !t.converged);
      });
  const auto cd = search.result();
  EXPECT_LE(cd.halfWidth(), 0.01);
  EXPECT_LE(cd.holding, 1.09);
  EXPECT_GT(cd.failing, 1.09);
  // the trials followed this criterion, so the others' brackets come from the same factors
  EXPECT_FALSE(search.bracket(StrengthReductionCriterion::AcceleratingDisplacement).closed());
}

TEST(DisplacementTrend, AcceleratingDeceleratingAndCreep) {
  // point 0 slides along x; point 1 barely moves (not mobilised: < half the largest)
  const std::vector<Real> start{0, 0, 0, 0};
  const std::vector<Real> a{0.01, 0, 0, 0.0001};
  const std::vector<Real> b{0.02, 0, 0, 0.0002};
  const std::vector<Real> fast{0.04, 0, 0, 0.0003};
  DisplacementTrend t = displacementTrend(start, a, b, fast, 1, 2, 3, 1e-3);
  EXPECT_EQ(t.mobilised_points, 1);
  EXPECT_NEAR(t.largest, 0.04, 1e-15);
  EXPECT_NEAR(t.earlier_rate, 0.01, 1e-15);
  EXPECT_NEAR(t.later_rate, 0.02, 1e-15);
  EXPECT_TRUE(t.accelerating);
  const std::vector<Real> slow{0.025, 0, 0, 0.0003};
  EXPECT_FALSE(displacementTrend(start, a, b, slow, 1, 2, 3, 1e-3).accelerating);
  // the same motion a thousand times smaller: creep below the minimum displacement
  std::vector<Real> a2 = a, b2 = b, c2 = fast;
  for (auto* v : {&a2, &b2, &c2})
    for (Real& x : *v) x *= 1e-3;
  EXPECT_FALSE(displacementTrend(start, a2, b2, c2, 1, 2, 3, 1e-3).accelerating);
  EXPECT_FALSE(displacementTrend(start, a2, b2, c2, 1, 2, 3, 1e-3).continuing);
  EXPECT_THROW(displacementTrend(start, a, b, fast, 2, 1, 3, 1e-3), std::invalid_argument);
  EXPECT_THROW(displacementTrend(start, a, b, {0, 0}, 1, 2, 3, 1e-3), std::invalid_argument);
}

// A dry 2:1 slope 4 m high (the slope of FactorOfSafetyTest at 0.5 m), nodal volumetric
// averaging against Tri3 locking (doc/theory.md Sec. 11), relaxed under gravity, then the
// strength reduction with the stage keys `extra`.
std::string slopeDeck(const std::string& srm_keys, bool with_srm) {
  std::string deck =
      test_decks::drySlopeDeckHead(
          "0.5", "      Locking Mitigation: {Volumetric Strain Averaging: nodal}\n") +
      R"(
  Stages:
    gravity:
      Solver: quasi-static
      Duration (s): 5
      Local Damping: 0.7
      Relaxation: {Kinetic Energy Ratio: 1.0e-6, Window (s): 0.5}
      Boundary Conditions:
        base: {Type: solid fixity, Node Set: bottom, Direction: both}
        left: {Type: solid fixity, Node Set: left, Direction: x}
        right: {Type: solid fixity, Node Set: right, Direction: x}
)";
  if (with_srm)
    deck += R"(    srm:
      Solver: quasi-static
      Duration (s): 4
      Local Damping: 0.7
      Relaxation: {Kinetic Energy Ratio: 1.0e-6, Window (s): 0.5}
)" + srm_keys +
            R"(
      Boundary Conditions:
        base: {Type: solid fixity, Node Set: bottom, Direction: both}
        left: {Type: solid fixity, Node Set: left, Direction: x}
        right: {Type: solid fixity, Node Set: right, Direction: x}
)";
  deck += R"(  Factor Of Safety:
    Centre X (m): [2.0, 14.0]
    Centre Y (m): [9.4, 21.4]
    Tangent Y (m): [0.0, 8.6]
    Suction Strength: none
  Output: {Name: slope}
)";
  return deck;
}

Deck parse(const std::string& text) {
  return parseDeck(*Teuchos::getParametersFromYamlString(text), "");
}

void expectInputError(const std::string& text, const std::string& path) {
  try {
    parse(text);
    FAIL() << "no error for " << path;
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
  }
}

TEST(StrengthReductionDeck, NeedsRelaxationAndAFrictionalMaterial) {
  const std::string srm = "      Strength Reduction: {Factor Tolerance: 0.01}";
  const Deck deck = parse(slopeDeck(srm, true));
  ASSERT_TRUE(deck.stages[1].strength_reduction.enabled);
  EXPECT_EQ(deck.stages[1].strength_reduction.tolerance, 0.01);
  EXPECT_EQ(deck.stages[1].strength_reduction.criterion,
            StrengthReductionCriterion::NonConvergence);
  EXPECT_FALSE(deck.stages[0].strength_reduction.enabled);
  EXPECT_EQ(
      parse(
          slopeDeck("      Strength Reduction: {Failure Criterion: continuing displacement}", true))
          .stages[1]
          .strength_reduction.criterion,
      StrengthReductionCriterion::ContinuingDisplacement);

  std::string no_relaxation = slopeDeck(srm, true);
  const std::string relax = "      Relaxation: {Kinetic Energy Ratio: 1.0e-6, Window (s): 0.5}\n";
  no_relaxation.erase(no_relaxation.rfind(relax), relax.size());
  expectInputError(no_relaxation, "Stages/srm/Strength Reduction");
  expectInputError(slopeDeck(srm + "\n      Output Interval (s): 0.5", true),
                   "Stages/srm/Output Interval (s)");
  expectInputError(slopeDeck("      Strength Reduction: {Initial Factor: 6.0}", true),
                   "Stages/srm/Strength Reduction/Initial Factor");
  std::string elastic = slopeDeck(srm, true);
  elastic.replace(elastic.find("Model: Mohr-Coulomb"), 19, "Model: linear elastic");
  const std::string strength =
      ", Cohesion (Pa): 1200, Friction Angle (deg): 19.6, Dilatancy Angle (deg): 0";
  elastic.erase(elastic.find(strength), strength.size());
  expectInputError(elastic, "Stages/srm/Strength Reduction");
}

TEST(StrengthReductionRun, BracketsTheFactorFollowsTheCircleAndRestoresTheState) {
  const auto dir = std::filesystem::path(::testing::TempDir()) / "argine_strength_reduction";
  const RunOptions options = test::quietRunIn(dir);
  Simulation simulation(
      parse(slopeDeck("      Strength Reduction: {Factor Tolerance: 0.01}", true)), options);
  simulation.run();

  // The trials bracket FS_SRM to +- 0.01: the lowest failing factor and the highest holding
  // one below it at most 0.02 apart.
  const auto trials = readCsvRows((dir / "slope_strength_reduction.csv").string());
  ASSERT_GE(trials.size(), 3u);
  Real holding = 0, failing = 1e30;
  for (const auto& t : trials) {
    EXPECT_EQ(t[0], trials[0][0]);  // one stage: one start time
    if (t[5] > 0.5)
      failing = std::min(failing, t[2]);
    else
      holding = std::max(holding, t[2]);
  }
  ASSERT_LT(failing, 1e30);
  ASSERT_GT(holding, 0);
  EXPECT_LT(holding, failing);
  EXPECT_LE(failing - holding, 0.02 + 1e-12);
  const auto fs = readCsvRows((dir / "slope_factor_of_safety.csv").string());
  ASSERT_FALSE(fs.empty());
  const Real lem = fs.back()[1];
  std::cout << "dry slope, 0.5 m tri3: FS_SRM = " << 0.5 * (holding + failing) << " +- "
            << 0.5 * (failing - holding) << ", Bishop on the same state " << lem << "\n";

  // The mechanism of the failing trial: the points of largest deviatoric strain increment
  // (the top 5 %) lie on the critical circle of the limit-equilibrium search, within about
  // one element (0.5 m; a shear band in MPM is one to two elements wide).
  const Real xc = fs.back()[4], yc = fs.back()[5], radius = fs.back()[6];
  const auto map = readCsvRows((dir / "slope_strength_reduction_points.csv").string());
  std::vector<std::pair<Real, Real>> strain_distance;
  for (const auto& p : map)
    if (p[2] > 0.5)
      strain_distance.emplace_back(p[7], std::fabs(std::hypot(p[4] - xc, p[5] - yc) - radius));
  ASSERT_GT(strain_distance.size(), 100u);
  std::sort(strain_distance.rbegin(), strain_distance.rend());
  const std::size_t top = strain_distance.size() / 20;
  Real mean_distance = 0;
  for (std::size_t k = 0; k < top; ++k) mean_distance += strain_distance[k].second / top;
  std::cout << "the top 5 % of the deviatoric strain lie " << mean_distance
            << " m from the critical circle on average\n";
  EXPECT_LT(mean_distance, 0.5);

  // The state afterwards is the state before: a run without the stage ends with the same
  // points, bit for bit.
  const auto dir2 = dir / "without";
  Simulation reference(parse(slopeDeck("", false)), test::quietRunIn(dir2));
  reference.run();
  const MaterialPoints& p = simulation.points();
  const MaterialPoints& q = reference.points();
  ASSERT_EQ(p.count, q.count);
  const auto px = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p.position);
  const auto qx = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), q.position);
  const auto ps = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p.stress_effective);
  const auto qs = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), q.stress_effective);
  const auto pid = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p.id);
  const auto qid = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), q.id);
  int differing = 0;
  for (int i = 0; i < p.count; ++i)
    differing += pid(i) != qid(i) || px(i, 0) != qx(i, 0) || px(i, 1) != qx(i, 1) ||
                 ps(i, 0) != qs(i, 0) || ps(i, 1) != qs(i, 1) || ps(i, 3) != qs(i, 3);
  EXPECT_EQ(differing, 0);
  EXPECT_EQ(simulation.currentMaterials()[0].solid.strength_reduction, 1);
  EXPECT_EQ(simulation.currentMaterials()[0].solid.cohesion, 1200);
}

}  // namespace
}  // namespace argine
