// [Output] StepFallReport: a log line each time a stage's critical step halves, naming the
// criterion and the point; nothing for a step that flickers above the last low or is fixed.
#include <gtest/gtest.h>

#include "argine/simulation/StepFallReport.hpp"

namespace argine {
namespace {

TimeStepChoice automaticStep(Real critical, int point_id = 7) {
  TimeStepChoice choice;
  choice.automatic = true;
  choice.critical_step = critical;
  choice.time_step = critical / 2;
  choice.governing = CriterionKind::CflDry;
  choice.point_id = point_id;
  choice.position[0] = 11.04;
  choice.position[1] = 0.053;
  return choice;
}

TEST(StepFallReport, ReportsEachNewLowBelowHalfOfTheLastOne) {
  StepFallReport report;
  report.begin(automaticStep(1e-4));
  EXPECT_EQ(report.note("drained", 1.0, 10, automaticStep(6e-5)), "");  // not half
  const std::string fell = report.note("drained", 2.5, 20, automaticStep(4e-5, 84838));
  EXPECT_NE(fell.find("stage 'drained'"), std::string::npos) << fell;
  EXPECT_NE(fell.find("fell to 4e-05 s (0.4 x 0.0001 s)"), std::string::npos) << fell;
  EXPECT_NE(fell.find("t = 2.5 s, step 20"), std::string::npos) << fell;
  EXPECT_NE(fell.find("'CFL dry' at point 84838 (11.04, 0.053) m"), std::string::npos) << fell;
  // the reference is now 4e-5: 3e-5 is no new halving, a return above it none either
  EXPECT_EQ(report.note("drained", 3.0, 30, automaticStep(3e-5)), "");
  EXPECT_EQ(report.note("drained", 3.5, 40, automaticStep(1e-4)), "");
  EXPECT_NE(report.note("drained", 4.0, 50, automaticStep(1.9e-5)), "");
  EXPECT_EQ(report.note("drained", 4.5, 60, automaticStep(1.9e-5)), "");
}

TEST(StepFallReport, AFixedStepOrAStageWithoutReferenceNeverFalls) {
  StepFallReport report;
  EXPECT_EQ(report.note("s", 0, 1, automaticStep(1e-9)), "");  // no begin: no reference
  TimeStepChoice fixed;
  fixed.time_step = 1e-3;
  report.begin(fixed);
  EXPECT_EQ(report.note("s", 0, 1, automaticStep(1e-9)), "");
  report.begin(automaticStep(1e-4));
  TimeStepChoice small_fixed;
  small_fixed.time_step = 1e-9;
  EXPECT_EQ(report.note("s", 0, 1, small_fixed), "");
}

}  // namespace
}  // namespace argine
