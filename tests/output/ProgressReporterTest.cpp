#include "argine/output/ProgressReporter.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <sstream>

namespace argine {
namespace {

// A reporter on a string stream with a clock the test sets by hand.
struct FakeRun {
  std::ostringstream out;
  double now = 1000.0;
  ProgressReporter reporter;
  FakeRun(bool terminal, ProgressOptions options = {})
      : reporter(
            out, terminal, [this] { return now; }, options) {}
};

int countOf(const std::string& text, char c) {
  return static_cast<int>(std::count(text.begin(), text.end(), c));
}

TEST(ProgressReporter, FormatsWallDurationsForPeople) {
  EXPECT_EQ(formatWallDuration(42.4), "42s");
  EXPECT_EQ(formatWallDuration(59.6), "1m00s");
  EXPECT_EQ(formatWallDuration(185.0), "3m05s");   // 3*60 + 5
  EXPECT_EQ(formatWallDuration(3725.0), "1h02m");  // 3600 + 2*60 + 5
  EXPECT_EQ(formatWallDuration(2 * 86400.0 + 3 * 3600.0), "2d03h");
  EXPECT_EQ(formatWallDuration(-1.0), "--");
}

TEST(ProgressReporter, PlainModePrintsALineEveryIntervalWithTheExpectedFields) {
  FakeRun run(false);
  run.reporter.beginStage("flood", 100.0, 200.0);  // stage from t = 100 s to 300 s
  run.now = 1005.0;
  run.reporter.update(5, 125.0, 0.5, 1000);
  EXPECT_EQ(run.out.str(), "") << "nothing before 10 s of wall time";
  run.now = 1010.0;
  run.reporter.update(10, 150.0, 0.5, 1000);
  // 50 s of 200 s = 25 %; 10 s of wall for 25 % -> 30 s left; 2000 updates / 10 s = 200 /s.
  EXPECT_EQ(run.out.str(),
            "flood: t 50 s / 200 s (25.0%)  step 10  dt 0.5 s  ETA 30s  200 pt-upd/s\n");
  run.now = 1019.0;
  run.reporter.update(11, 155.0, 0.5, 1000);
  EXPECT_EQ(countOf(run.out.str(), '\n'), 1) << "next line only 10 s after the last";
  run.now = 1020.0;
  run.reporter.update(12, 160.0, 0.5, 1000);
  EXPECT_EQ(countOf(run.out.str(), '\n'), 2);
  EXPECT_EQ(run.out.str().find('\r'), std::string::npos);
}

TEST(ProgressReporter, EtaFollowsTheSimulatedRateSoFar) {
  FakeRun run(false, ProgressOptions{false, 1.0, 0.25});
  run.reporter.beginStage("collapse", 0.0, 60.0);
  run.now += 120.0;  // 2 min of wall for 6 s of 60 s (10 %): 18 min to go
  run.reporter.update(600, 6.0, 0.01, 0);
  EXPECT_NE(run.out.str().find("(10.0%)"), std::string::npos) << run.out.str();
  EXPECT_NE(run.out.str().find("ETA 18m00s"), std::string::npos) << run.out.str();
  // Nothing simulated yet: ETA unknown.
  EXPECT_NE(run.reporter.line(0, 0.0, 0.01, run.now).find("ETA --"), std::string::npos);
}

TEST(ProgressReporter, EtaOfAResumedStageFollowsTheRateSinceTheResume) {
  FakeRun run(false, ProgressOptions{false, 1.0, 0.25});
  // A 60 s stage resumed from a checkpoint at 30 s: 1 min of wall for 3 s more (33 s, 55 %)
  // leaves 27 s at 3 s a minute: 9 min (counting the 30 s before the resume: 49 s).
  run.reporter.beginStage("collapse", 0.0, 60.0, 30.0);
  run.now += 60.0;
  run.reporter.update(3300, 33.0, 0.01, 0);
  EXPECT_NE(run.out.str().find("(55.0%)"), std::string::npos) << run.out.str();
  EXPECT_NE(run.out.str().find("ETA 9m00s"), std::string::npos) << run.out.str();
}

TEST(ProgressReporter, StageEndPrintsTheFinalLineWithTheWallTimeTaken) {
  FakeRun run(false);
  run.reporter.beginStage("initialise", 0.0, 10.0);
  run.reporter.update(1, 5.0, 5.0, 40);
  run.now += 4.0;
  run.reporter.update(2, 10.0, 5.0, 40);
  run.reporter.endStage(2, 10.0, 5.0);
  // 80 updates in 4 s = 20 /s.
  EXPECT_EQ(run.out.str(),
            "initialise: t 10 s / 10 s (100.0%)  step 2  dt 5 s  wall 4s  20 pt-upd/s  done\n");
}

TEST(ProgressReporter, QuietPrintsNothing) {
  FakeRun run(false, ProgressOptions{true, 10.0, 0.25});
  run.reporter.beginStage("flood", 0.0, 100.0);
  for (int i = 1; i <= 100; ++i) {
    run.now += 1.0;
    run.reporter.update(i, i, 1.0, 10);
  }
  run.reporter.endStage(100, 100.0, 1.0);
  EXPECT_EQ(run.out.str(), "");
}

TEST(ProgressReporter, TerminalModeRedrawsOneLineAndEndsItAtStageEnd) {
  FakeRun run(true);
  run.reporter.beginStage("flood", 0.0, 100.0);
  run.now += 0.1;
  run.reporter.update(1, 1.0, 1.0, 10);
  EXPECT_EQ(run.out.str(), "") << "redraws are at most every 0.25 s";
  run.now += 0.2;
  run.reporter.update(2, 50.0, 1.0, 10);
  run.now += 0.3;
  run.reporter.update(3, 51.0, 1.0, 10);
  const std::string drawn = run.out.str();
  EXPECT_EQ(countOf(drawn, '\r'), 2);
  EXPECT_EQ(countOf(drawn, '\n'), 0);
  // 50 % -> 10 of the 20 bar characters.
  EXPECT_NE(drawn.find("\r[##########..........] flood: t 50 s / 100 s (50.0%)"), std::string::npos)
      << drawn;
  run.reporter.endStage(100, 100.0, 1.0);
  const std::string all = run.out.str();
  EXPECT_EQ(all.back(), '\n');
  EXPECT_NE(all.find("done"), std::string::npos);
}

TEST(ProgressReporter, TerminalRedrawClearsTheRestOfALongerPreviousLine) {
  FakeRun run(true);
  run.reporter.beginStage("s", 0.0, 1e6);
  run.now += 1.0;
  run.reporter.update(123456789, 5e5, 12345.678, 1'000'000'000);
  const std::size_t first = run.out.str().size();
  run.reporter.endStage(1, 1e6, 1.0);  // shorter text: padded with spaces to cover it
  const std::string second = run.out.str().substr(first);
  EXPECT_GE(second.size(), first + 1);  // '\r' + at least the old length, then '\n'
}

TEST(ProgressReporter, AnUpdateWithNoReportDueCostsWellUnderAMicrosecond) {
  // Called every step: with a real steady clock, 1e6 calls must take far less than a step.
  std::ostringstream out;
  ProgressReporter reporter(out, false, [] {
    using namespace std::chrono;
    return duration<double>(steady_clock::now().time_since_epoch()).count();
  });
  reporter.beginStage("s", 0.0, 1.0);
  const auto start = std::chrono::steady_clock::now();
  for (int i = 0; i < 1'000'000; ++i) reporter.update(i, 1e-7 * i, 1e-7, 100);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_LT(seconds, 0.5);  // typically ~0.03 s, i.e. ~30 ns per call
}

}  // namespace
}  // namespace argine
