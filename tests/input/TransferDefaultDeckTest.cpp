// The stage key `Velocity Transfer` when a deck does not name it: APIC on the grid families
// (the scheme for failure stages, doc/theory.md), FLIP on linear shapes (the thesis); and
// the PIC fractions, which blend FLIP only; XPIC's order.
#include "DeckTestSupport.hpp"
#include "argine/transfer/TransferScheme.hpp"

namespace argine::test {

namespace {

std::string withShapes(const std::string& deck, const std::string& shapes) {
  return replaced(deck, "  Mesh:\n", "  Mesh:\n    Shape Functions: " + shapes + "\n");
}

std::string withStageKey(const std::string& deck, const std::string& line) {
  return replaced(deck, "      Boundary Conditions:\n",
                  "      " + line + "\n      Boundary Conditions:\n");
}

TEST(TransferDefault, FollowsTheShapeFunctions) {
  EXPECT_EQ(transferForShapes(ShapeFamily::Linear), TransferScheme::Flip);
  EXPECT_EQ(transferForShapes(ShapeFamily::Gimp), TransferScheme::Apic);
  EXPECT_EQ(transferForShapes(ShapeFamily::BSpline), TransferScheme::Apic);
  EXPECT_EQ(parseText(kBaseDeck).stages[0].transfer, TransferScheme::Flip);
  EXPECT_EQ(parseText(withShapes(kBaseDeck, "GIMP")).stages[0].transfer, TransferScheme::Apic);
  EXPECT_EQ(parseText(withShapes(kBaseDeck, "B-spline")).stages[0].transfer, TransferScheme::Apic);
  EXPECT_EQ(parseText(withStageKey(kBaseDeck, "Velocity Transfer: by shape functions"))
                .stages[0]
                .transfer,
            TransferScheme::Flip);
}

TEST(TransferDefault, ANamedTransferIsKeptOnEveryShapeFamily) {
  const std::string gimp = withShapes(kBaseDeck, "GIMP");
  EXPECT_EQ(parseText(withStageKey(gimp, "Velocity Transfer: FLIP")).stages[0].transfer,
            TransferScheme::Flip);
  EXPECT_EQ(parseText(withStageKey(gimp, "Velocity Transfer: TPIC")).stages[0].transfer,
            TransferScheme::Tpic);
  EXPECT_EQ(parseText(withStageKey(kBaseDeck, "Velocity Transfer: APIC")).stages[0].transfer,
            TransferScheme::Apic);
}

TEST(TransferDefault, PicFractionsNeedFlip) {
  // on linear shapes the default is FLIP: the blend is read
  const Deck linear = parseText(withStageKey(kBaseDeck, "Solid PIC Fraction: 0.05"));
  EXPECT_EQ(linear.stages[0].transfer, TransferScheme::Flip);
  EXPECT_EQ(linear.stages[0].solid_pic_fraction, 0.05);
  // on GIMP the default is APIC: a blend is an error naming the key, with the remedy
  const std::string gimp = withShapes(kBaseDeck, "GIMP");
  expectInputError([&] { parseText(withStageKey(gimp, "Liquid PIC Fraction: 0.1")); },
                   "Stages/load/Liquid PIC Fraction", "set 'Velocity Transfer: FLIP'");
  expectInputError([&] { parseText(withStageKey(gimp, "Solid PIC Fraction: 0.1")); },
                   "Stages/load/Solid PIC Fraction", "APIC (the default on GIMP");
  const Deck flip = parseText(
      withStageKey(withStageKey(gimp, "Velocity Transfer: FLIP"), "Liquid PIC Fraction: 0.1"));
  EXPECT_EQ(flip.stages[0].liquid_pic_fraction, 0.1);
  // a named non-FLIP transfer with a blend stays the schema's error
  expectInputError(
      [&] {
        parseText(withStageKey(withStageKey(kBaseDeck, "Velocity Transfer: TPIC"),
                               "Liquid PIC Fraction: 0.1"));
      },
      "Stages/load/Liquid PIC Fraction", "Velocity Transfer");
}

TEST(TransferDefault, APicRateRelaxesFlipOrApicAndExcludesTheFraction) {
  const std::string gimp = withShapes(kBaseDeck, "GIMP");  // APIC by default
  EXPECT_EQ(parseText(gimp).stages[0].solid_pic_rate, 0.0);
  const Deck apic = parseText(withStageKey(gimp, "Solid PIC Rate (1/s): 40"));
  EXPECT_EQ(apic.stages[0].transfer, TransferScheme::Apic);
  EXPECT_EQ(apic.stages[0].solid_pic_rate, 40.0);
  EXPECT_EQ(parseText(withStageKey(kBaseDeck, "Solid PIC Rate (1/s): 25")).stages[0].solid_pic_rate,
            25.0);  // FLIP on linear shapes
  expectInputError(
      [&] {
        parseText(withStageKey(withStageKey(kBaseDeck, "Solid PIC Rate (1/s): 25"),
                               "Solid PIC Fraction: 0.1"));
      },
      "Stages/load/Solid PIC Rate (1/s)", "give one of them");
  const Deck liquid = parseText(withStageKey(gimp, "Liquid PIC Rate (1/s): 30"));
  EXPECT_EQ(liquid.stages[0].liquid_pic_rate, 30.0);
  EXPECT_EQ(liquid.stages[0].solid_pic_rate, 0.0);
  expectInputError(
      [&] {
        parseText(withStageKey(withStageKey(kBaseDeck, "Liquid PIC Rate (1/s): 25"),
                               "Liquid PIC Fraction: 0.1"));
      },
      "Stages/load/Liquid PIC Rate (1/s)", "'Liquid PIC Fraction' per step");
  expectInputError([&] { parseText(withStageKey(kBaseDeck, "Solid PIC Rate (1/s): 0")); },
                   "Stages/load/Solid PIC Rate (1/s)", "0");
  expectInputError(
      [&] {
        parseText(withStageKey(withStageKey(gimp, "Velocity Transfer: TPIC"),
                               "Solid PIC Rate (1/s): 25"));
      },
      "Stages/load/Solid PIC Rate (1/s)", "Velocity Transfer");
}

TEST(TransferDefault, XpicTakesItsOrderAndNoPicFraction) {
  const std::string xpic = withStageKey(kBaseDeck, "Velocity Transfer: XPIC");
  const Deck plain = parseText(xpic);
  EXPECT_EQ(plain.stages[0].transfer, TransferScheme::Xpic);
  EXPECT_EQ(plain.stages[0].xpic.order, 2);               // the schema's default
  EXPECT_EQ(plain.stages[0].xpic.lower_eigenvalue, 0.0);  // the binomial series
  EXPECT_EQ(parseText(withStageKey(xpic, "XPIC Order: 5")).stages[0].xpic.order, 5);
  expectInputError([&] { parseText(withStageKey(xpic, "XPIC Order: 0")); },
                   "Stages/load/XPIC Order", "1");
  expectInputError([&] { parseText(withStageKey(xpic, "XPIC Order: 9")); },
                   "Stages/load/XPIC Order", "Chebyshev");
  // Chebyshev's polynomial: up to 32 terms, its lower eigenvalue in (0, 1), default 0.05
  const std::string chebyshev = withStageKey(xpic, "XPIC Polynomial: Chebyshev");
  const Deck nine = parseText(withStageKey(chebyshev, "XPIC Order: 9"));
  EXPECT_EQ(nine.stages[0].xpic.order, 9);
  EXPECT_EQ(nine.stages[0].xpic.lower_eigenvalue, 0.05);
  EXPECT_EQ(parseText(withStageKey(chebyshev, "XPIC Lower Eigenvalue: 0.2"))
                .stages[0]
                .xpic.lower_eigenvalue,
            0.2);
  expectInputError([&] { parseText(withStageKey(chebyshev, "XPIC Order: 33")); },
                   "Stages/load/XPIC Order", "32");
  expectInputError([&] { parseText(withStageKey(chebyshev, "XPIC Lower Eigenvalue: 1")); },
                   "Stages/load/XPIC Lower Eigenvalue", "1");
  expectInputError([&] { parseText(withStageKey(xpic, "XPIC Lower Eigenvalue: 0.1")); },
                   "Stages/load/XPIC Lower Eigenvalue", "XPIC Polynomial");
  // the order belongs to XPIC, the PIC fractions to FLIP (XPIC takes both shares as 1)
  expectInputError(
      [&] {
        parseText(
            withStageKey(withStageKey(kBaseDeck, "Velocity Transfer: APIC"), "XPIC Order: 3"));
      },
      "Stages/load/XPIC Order", "Velocity Transfer");
  expectInputError([&] { parseText(withStageKey(xpic, "Solid PIC Fraction: 0.1")); },
                   "Stages/load/Solid PIC Fraction", "Velocity Transfer");
}

}  // namespace

}  // namespace argine::test
