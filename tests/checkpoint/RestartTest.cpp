// [Checkpoint] Kill -9 and restart, end to end through the argine program: a run stopped at a
// known step (ARGINE_FAULT_STOP_AT_STEP makes it SIGSTOP itself; the test then SIGKILLs it, so
// nothing is flushed or closed), its files read back as they were left (crash-safe output),
// then `argine run --restart` from its last checkpoint; the final Exodus fields and CSVs must
// equal those of an uninterrupted run bit for bit (the restart re-derives nothing from the
// deck that the run had changed, and keeps the points' order, so every sum is the same).
// A corrupted, truncated or other-deck checkpoint is refused with exit code 2 naming the file,
// before any output file is touched.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "../output/ExodusReadBack.hpp"
#include "DrySlopeDeck.hpp"
#include "WetColumnDeck.hpp"
#include "argine/checkpoint/CheckpointFile.hpp"
#include "argine/simulation/Checkpoint.hpp"

extern char** environ;

namespace argine {
namespace {

namespace fs = std::filesystem;
using test::ExodusReadBack;

// A saturated column 0.2 m x 1 m (20 quads, 80 points), Mohr-Coulomb, K0 state; a falling
// river head on top (boundary flux file), two explicit stages (240 + 120 steps), the second
// changing the cohesion; time step recomputed every 7 / 5 steps (the controller's cached
// choice must survive a restart); points sorted every 50 steps; three probe files; a
// checkpoint every 50 steps.
const char* kDeck = R"(argine:
  Title: restart test column
  Mesh:
    Generate: {Type: rectangle, Element: quad4, Element Size (m): 0.1, Lower Left (m): [0.0, 0.0], Upper Right (m): [0.2, 1.0]}
  Materials:
    soil:
      Block: soil
      Points Per Element: 4
      Porosity: 0.4
      Solid Density (kg/m3): 2700
      Solid: {Model: Mohr-Coulomb, Young's Modulus (Pa): 1.0e6, Poisson's Ratio: 0.3, Cohesion (Pa): 2000, Friction Angle (deg): 30}
      Liquid: {Bulk Modulus (Pa): 1.0e7}
      Conductivity: {Saturated Conductivity (m/s): 1.0e-3}
      Initial State: {K0: 0.5}
  Initialisation: {Method: K0 procedure, Ground Surface (m): [0.0, 1.0], Phreatic Surface (m): [0.0, 1.0]}
  Stages:
    drawdown:
      Solver: explicit
      Duration (s): 0.04
      Local Damping: 0.1
      Output Interval (s): 0.001
      Time Step: {Mode: automatic, Safety Factor: 0.5, Update Interval: 7}
      Boundary Conditions:
        base: {Type: solid fixity, Node Set: bottom, Direction: both}
        left: {Type: solid fixity, Node Set: left, Direction: x}
        right: {Type: solid fixity, Node Set: right, Direction: x}
        river: {Type: total head, Side Set: top, Total Head Table: [0, 1.2, 0.05, 0.9]}
    soften:
      Solver: explicit
      Duration (s): 0.02
      Local Damping: 0.1
      Output Interval (s): 0.0015
      Time Step: {Mode: automatic, Safety Factor: 0.5, Update Interval: 5}
      Material Changes:
        soil: {Cohesion (Pa): 500}
      Boundary Conditions:
        base: {Type: solid fixity, Node Set: bottom, Direction: both}
        left: {Type: solid fixity, Node Set: left, Direction: x}
        right: {Type: solid fixity, Node Set: right, Direction: x}
        river: {Type: total head, Side Set: top, Total Head Table: [0, 0.9, 1, 0.8]}
  Probes:
    Interval (s): 0.0005
    Points:
      middle: {Position (m): [0.05, 0.5], Tolerance (m): 0.05}
    Sections:
      axis: {Type: profile, From (m): [0.1, 0.0], To (m): [0.1, 1.0], Width (m): 0.1, Samples: 5}
      band: {Type: band, From (m): [0.0, 0.75], To (m): [0.2, 0.75], Width (m): 0.1}
  Output:
    Name: column
    Checkpoint: {Every Steps: 50}
)";

const std::vector<std::string> kCsvFiles = {"column_diagnostics.csv", "column_boundary_flux.csv",
                                            "column_probe_middle.csv", "column_section_axis.csv",
                                            "column_section_band.csv"};
const std::vector<std::string> kExodusFiles = {"column_grid.e", "column_points.e"};

std::string readAll(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

struct Outcome {
  int exit_code = -1;  ///< -1 when killed
  int signal = 0;      ///< the signal that ended it
  std::string output;  ///< stdout and stderr
};

// Runs the argine program with `arguments`; stop_at > 0: sets ARGINE_FAULT_STOP_AT_STEP, waits
// until the process has stopped itself there, and kills it with SIGKILL. The environment is
// passed on without the MPI variables of this (MPI-initialised) test process.
Outcome runArgine(const std::vector<std::string>& arguments, const fs::path& log, int stop_at = 0) {
  std::vector<std::string> words{ARGINE_BINARY_DIR "/argine"};
  words.insert(words.end(), arguments.begin(), arguments.end());
  std::vector<char*> argv;
  for (auto& word : words) argv.push_back(word.data());
  argv.push_back(nullptr);
  std::vector<std::string> variables;
  for (char** e = environ; *e != nullptr; ++e) {
    const std::string variable = *e;
    const bool mpi = variable.rfind("OMPI_", 0) == 0 || variable.rfind("PMIX_", 0) == 0 ||
                     variable.rfind("OPAL_", 0) == 0 || variable.rfind("PRTE_", 0) == 0;
    const bool allowed = variable.rfind("OMPI_ALLOW_RUN_AS_ROOT", 0) == 0;
    if ((!mpi || allowed) && variable.rfind("ARGINE_FAULT_", 0) != 0) variables.push_back(variable);
  }
  if (stop_at > 0) variables.push_back("ARGINE_FAULT_STOP_AT_STEP=" + std::to_string(stop_at));
  std::vector<char*> envp;
  for (auto& variable : variables) envp.push_back(variable.data());
  envp.push_back(nullptr);

  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, 1, 2);
  pid_t pid = 0;
  const int spawned = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), envp.data());
  posix_spawn_file_actions_destroy(&actions);
  Outcome outcome;
  if (spawned != 0) {
    ADD_FAILURE() << "cannot start " << argv[0] << ": " << std::strerror(spawned);
    return outcome;
  }
  int status = 0;
  waitpid(pid, &status, stop_at > 0 ? WUNTRACED : 0);
  if (stop_at > 0) {
    EXPECT_TRUE(WIFSTOPPED(status)) << "the run did not stop at step " << stop_at << "\n"
                                    << readAll(log);
    kill(pid, SIGKILL);  // the fault: no destructor, no flush, no close
    waitpid(pid, &status, 0);
  }
  if (WIFEXITED(status)) outcome.exit_code = WEXITSTATUS(status);
  if (WIFSIGNALED(status)) outcome.signal = WTERMSIG(status);
  outcome.output = readAll(log);
  return outcome;
}

class Restart : public ::testing::Test {
 protected:
  void SetUp() override {
    // one folder per test and process: two suites run at once (two build trees, CI beside a
    // developer's run) must not remove each other's files
    dir_ = fs::path(::testing::TempDir()) /
           ("argine_restart_" +
            std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) + "_" +
            std::to_string(getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    deck_ = dir_ / "column.yaml";
    std::ofstream(deck_) << kDeck;
  }
  // kept when the test failed, for a look at the runs' logs
  void TearDown() override {
    if (!HasFailure()) fs::remove_all(dir_);
  }
  // The uninterrupted run, once per test (it takes a fraction of a second).
  fs::path reference() {
    const fs::path out = dir_ / "reference";
    const Outcome run = runArgine({"run", deck_.string(), "--output", out.string(), "--quiet"},
                                  dir_ / "reference.log");
    EXPECT_EQ(run.exit_code, 0) << run.output;
    return out;
  }
  // A run killed (SIGKILL) after step `stop_at`.
  fs::path killedAt(int stop_at) {
    const fs::path out = dir_ / "killed";
    const Outcome run = runArgine({"run", deck_.string(), "--output", out.string(), "--quiet"},
                                  dir_ / "killed.log", stop_at);
    EXPECT_EQ(run.signal, SIGKILL) << run.output;
    return out;
  }
  Outcome restart(const fs::path& out, const fs::path& checkpoint) {
    return runArgine(
        {"run", deck_.string(), "--output", out.string(), "--restart", checkpoint.string()},
        dir_ / "restart.log");
  }
  CheckpointState checkpointOf(const fs::path& out) {
    CheckpointState state;
    state.points.allocate(80);
    readCheckpoint((out / "column.checkpoint").string(), fileHash(deck_.string()), state);
    return state;
  }
  fs::path dir_, deck_;
};

// Every step of `killed` (an Exodus file left by a killed run) is readable and equals the
// same step of the uninterrupted run bit for bit; returns the number of steps.
int expectCompletedStepsReadable(const fs::path& killed, const fs::path& reference) {
  ExodusReadBack k(killed.string()), r(reference.string());
  EXPECT_TRUE(k.ok()) << killed;
  if (!k.ok() || !r.ok()) return 0;
  const int steps = k.numSteps();
  EXPECT_LE(steps, r.numSteps());
  const auto names = k.nodalVariableNames();
  EXPECT_EQ(names, r.nodalVariableNames());
  for (int step = 1; step <= steps; ++step) {
    EXPECT_EQ(k.time(step), r.time(step)) << killed << " step " << step;
    for (const auto& name : names) {
      const auto a = k.nodal(name, step), b = r.nodal(name, step);
      EXPECT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof(double)), 0)
          << killed << " step " << step << " " << name;
    }
  }
  return steps;
}

// Same steps, times and nodal fields bit for bit.
void expectSameExodus(const fs::path& a, const fs::path& b) {
  ExodusReadBack x(a.string()), y(b.string());
  ASSERT_TRUE(x.ok() && y.ok());
  ASSERT_EQ(x.numSteps(), y.numSteps()) << a;
  ASSERT_EQ(x.nodalVariableNames(), y.nodalVariableNames());
  const auto tx = x.times(), ty = y.times();
  EXPECT_EQ(std::memcmp(tx.data(), ty.data(), tx.size() * sizeof(double)), 0) << a;
  int different = 0;
  for (int step = 1; step <= x.numSteps(); ++step)
    for (const auto& name : x.nodalVariableNames()) {
      const auto u = x.nodal(name, step), v = y.nodal(name, step);
      if (std::memcmp(u.data(), v.data(), u.size() * sizeof(double)) != 0) {
        ++different;
        ADD_FAILURE() << a << " step " << step << " " << name << " differs";
      }
    }
  EXPECT_EQ(different, 0);
}

void expectSameResults(const fs::path& out, const fs::path& reference) {
  for (const auto& name : kExodusFiles) expectSameExodus(out / name, reference / name);
  for (const auto& name : kCsvFiles)
    EXPECT_EQ(readAll(out / name), readAll(reference / name)) << name;
}

TEST_F(Restart, KilledMidStageRestartsToTheUninterruptedResults) {
  const fs::path reference_dir = reference();
  // Killed 30 steps after the checkpoint of step 100, in the first stage.
  const fs::path killed = killedAt(130);

  // Crash-safe output: every step the killed run completed reads back, equal to the
  // uninterrupted run's; every CSV is a prefix of the uninterrupted one ending in a full row.
  const int grid_steps =
      expectCompletedStepsReadable(killed / "column_grid.e", reference_dir / "column_grid.e");
  const int points_steps =
      expectCompletedStepsReadable(killed / "column_points.e", reference_dir / "column_points.e");
  EXPECT_GE(grid_steps, 20);  // outputs every 1 ms, dt ~0.17 ms: ~22 by step 130
  EXPECT_EQ(points_steps, grid_steps);
  for (const auto& name : kCsvFiles) {
    const std::string rows = readAll(killed / name), all = readAll(reference_dir / name);
    EXPECT_EQ(all.compare(0, rows.size(), rows), 0) << name;
    EXPECT_EQ(rows.back(), '\n') << name;
  }

  // The checkpoint on disk is that of step 100, inside the first stage, and the killed run
  // wrote output after it, which the restart must drop.
  const CheckpointState state = checkpointOf(killed);
  EXPECT_EQ(state.steps, 100);
  EXPECT_EQ(state.stage_index, 0);
  EXPECT_TRUE(state.mid_stage);
  EXPECT_LT(state.results.grid_steps, grid_steps);
  EXPECT_LT(state.diagnostics_bytes, fs::file_size(killed / "column_diagnostics.csv"));

  // The restart runs on through the stage boundary to the end.
  const Outcome resumed = restart(killed, killed / "column.checkpoint");
  ASSERT_EQ(resumed.exit_code, 0) << resumed.output;
  expectSameResults(killed, reference_dir);
}

TEST_F(Restart, KilledInTheSecondStageReappliesItsMaterialChange) {
  const fs::path reference_dir = reference();
  // The checkpoint of step 300 lies 60 steps into 'soften', after its cohesion change.
  const fs::path killed = killedAt(320);
  const CheckpointState state = checkpointOf(killed);
  EXPECT_EQ(state.steps, 300);
  EXPECT_EQ(state.stage_index, 1);
  const Outcome resumed = restart(killed, killed / "column.checkpoint");
  ASSERT_EQ(resumed.exit_code, 0) << resumed.output;
  EXPECT_NE(resumed.output.find("restarted from " + (killed / "column.checkpoint").string() +
                                ": inside stage 'soften'"),
            std::string::npos)
      << resumed.output;
  expectSameResults(killed, reference_dir);
}

// An implicit seepage stage (12 implicit steps, not checkpointed inside) and an explicit one:
// the step count passes 10 during the implicit stage, so a checkpoint is written at the stage
// boundary ("before 'settle'"); killed at step 17, before the next one (step 20).
const std::string kHybridDeck = test_decks::wetColumnDeckHead() + R"(    rain:
      Solver: implicit seepage
      Duration (s): 20
      Gravity (m/s2): 9.81
      Output Interval (s): 10
      Implicit Seepage:
        Initial Step (s): 0.5
        Maximum Step (s): 2.0
      Boundary Conditions:
        rain: {Type: infiltration, Side Set: top, Flux (m/s): 1.0e-4}
        sealed base: {Type: impermeable, Side Set: bottom}
    settle:
      Solver: explicit
      Duration (s): 0.004
      Gravity (m/s2): 9.81
      Local Damping: 0.1
      Output Interval (s): 0.001
)" + test_decks::wetColumnExplicitConditions() +
                                R"(  Output:
    Name: column
    Checkpoint: {Every Steps: 10}
)";

TEST_F(Restart, CheckpointAtAStageBoundaryAfterAnImplicitStage) {
  std::ofstream(deck_) << kHybridDeck;
  const fs::path reference_dir = reference();
  const fs::path killed = killedAt(17);
  CheckpointState state;
  state.points.allocate(60);
  readCheckpoint((killed / "column.checkpoint").string(), fileHash(deck_.string()), state);
  EXPECT_EQ(state.steps, 12);
  EXPECT_EQ(state.stage_index, 1);
  EXPECT_FALSE(state.mid_stage);
  const Outcome resumed = restart(killed, killed / "column.checkpoint");
  ASSERT_EQ(resumed.exit_code, 0) << resumed.output;
  for (const auto& name : kExodusFiles) expectSameExodus(killed / name, reference_dir / name);
  for (const char* name : {"column_diagnostics.csv", "column_boundary_flux.csv"})
    EXPECT_EQ(readAll(killed / name), readAll(reference_dir / name)) << name;
}

// (P12) An explicit stage with Hand Back At Rest: a wet column under rain settles (local
// damping); its windows of at least 0.05 s, judged at the outputs, begin at 0, 0.06 and 0.12 s,
// and the last is at rest, so the rest of the stage goes to the implicit path at the 0.18 s
// output (step ~7,660). The checkpoint of step 6000 (t ~ 0.14 s) lies inside that window: the
// restart must carry its start and the points' rest_reference, or it would judge another
// window and write other results.
const std::string kHandBackDeck = test_decks::wetColumnDeck(
    "0.3",
    "      Hand Back At Rest: {Largest Speed (m/s): 1.0e-3, Window (s): 0.05}\n"
    "      Implicit Seepage: {Initial Step (s): 0.01}\n",
    "    Checkpoint: {Every Steps: 1000}\n");

TEST_F(Restart, InsideTheWindowOfAHandBackAtRest) {
  std::ofstream(deck_) << kHandBackDeck;
  const fs::path reference_dir = reference();
  const fs::path killed = killedAt(6500);
  CheckpointState state;
  state.points.allocate(60);
  readCheckpoint((killed / "column.checkpoint").string(), fileHash(deck_.string()), state);
  EXPECT_EQ(state.steps, 6000);
  EXPECT_TRUE(state.mid_stage);
  EXPECT_NEAR(state.rest_window_start, 0.12, 1e-12);
  const Outcome resumed = restart(killed, killed / "column.checkpoint");
  ASSERT_EQ(resumed.exit_code, 0) << resumed.output;
  EXPECT_NE(resumed.output.find("stage 'settle': at rest at t = 0.18 s"), std::string::npos)
      << resumed.output;
  for (const auto& name : kExodusFiles) expectSameExodus(killed / name, reference_dir / name);
  for (const char* name : {"column_diagnostics.csv", "column_boundary_flux.csv"})
    EXPECT_EQ(readAll(killed / name), readAll(reference_dir / name)) << name;
}

// A dry slope (the strength-reduction tests' section, 1 m triangles) brought to rest, then two
// strength-reduction stages; a checkpoint is due at every stage boundary. The last one on disk
// is "before 'srm2'": a restart from it must continue the trials and mechanism CSVs that
// 'srm1' wrote, not start them again.
const std::string kStrengthReductionDeck = test_decks::drySlopeDeckHead("1.0") + R"(  Stages:
    gravity:
      Solver: quasi-static
      Duration (s): 2
      Local Damping: 0.7
      Relaxation: {Kinetic Energy Ratio: 1.0e-6, Window (s): 0.5}
      Boundary Conditions:
        base: {Type: solid fixity, Node Set: bottom, Direction: both}
        left: {Type: solid fixity, Node Set: left, Direction: x}
        right: {Type: solid fixity, Node Set: right, Direction: x}
    srm1:
      Solver: quasi-static
      Duration (s): 1
      Local Damping: 0.7
      Relaxation: {Kinetic Energy Ratio: 1.0e-6, Window (s): 0.5}
      Strength Reduction: {Factor Tolerance: 0.2}
      Boundary Conditions:
        base: {Type: solid fixity, Node Set: bottom, Direction: both}
        left: {Type: solid fixity, Node Set: left, Direction: x}
        right: {Type: solid fixity, Node Set: right, Direction: x}
    srm2:
      Solver: quasi-static
      Duration (s): 1
      Local Damping: 0.7
      Relaxation: {Kinetic Energy Ratio: 1.0e-6, Window (s): 0.5}
      Strength Reduction: {Factor Tolerance: 0.2, Failure Criterion: either}
      Boundary Conditions:
        base: {Type: solid fixity, Node Set: bottom, Direction: both}
        left: {Type: solid fixity, Node Set: left, Direction: x}
        right: {Type: solid fixity, Node Set: right, Direction: x}
  Output:
    Name: column
    Checkpoint: {Every Steps: 20}
)";

TEST_F(Restart, AfterAStrengthReductionStageTheNextOneContinuesItsFiles) {
  std::ofstream(deck_) << kStrengthReductionDeck;
  const fs::path reference_dir = reference();
  CheckpointState state;
  state.points.allocate(ExodusReadBack((reference_dir / "column_points.e").string()).numNodes());
  readCheckpoint((reference_dir / "column.checkpoint").string(), fileHash(deck_.string()), state);
  EXPECT_EQ(state.stage_index, 2);  // before 'srm2'
  EXPECT_FALSE(state.mid_stage);
  ASSERT_EQ(state.strength_reduction_bytes.size(), 2u);
  EXPECT_LT(state.strength_reduction_bytes[0],
            fs::file_size(reference_dir / "column_strength_reduction.csv"));
  // Restarted in a copy of the finished run's files: 'srm2' is run again from the checkpoint
  // and its rows replace those the run wrote after it.
  const fs::path again = dir_ / "again";
  fs::copy(reference_dir, again);
  const Outcome resumed = restart(again, again / "column.checkpoint");
  ASSERT_EQ(resumed.exit_code, 0) << resumed.output;
  for (const char* name : {"column_strength_reduction.csv", "column_strength_reduction_points.csv",
                           "column_diagnostics.csv"})
    EXPECT_EQ(readAll(again / name), readAll(reference_dir / name)) << name;
  for (const auto& name : kExodusFiles) expectSameExodus(again / name, reference_dir / name);
}

TEST_F(Restart, BadCheckpointsAreRefusedNamingTheFileBeforeAnyOutput) {
  const fs::path killed = killedAt(120);
  const fs::path good = killed / "column.checkpoint";
  const std::string bytes = readAll(good);
  const std::string diagnostics = readAll(killed / "column_diagnostics.csv");
  auto refused = [&](const std::string& name, const std::string& content, const std::string& what) {
    const fs::path bad = dir_ / name;
    std::ofstream(bad, std::ios::binary) << content;
    const Outcome run = restart(killed, bad);
    EXPECT_EQ(run.exit_code, 2) << run.output;
    EXPECT_NE(run.output.find(bad.string()), std::string::npos) << run.output;
    EXPECT_NE(run.output.find(what), std::string::npos) << run.output;
    EXPECT_EQ(readAll(killed / "column_diagnostics.csv"), diagnostics);  // untouched
  };
  refused("truncated.checkpoint", bytes.substr(0, bytes.size() / 2), "truncated");
  std::string corrupt = bytes;
  corrupt[corrupt.size() / 2] ^= 0x04;
  refused("corrupt.checkpoint", corrupt, "payload checksum");
  refused("empty.checkpoint", "", "truncated");

  // The same checkpoint with a changed deck (one parameter): another deck.
  std::string deck = kDeck;
  deck.replace(deck.find("Cohesion (Pa): 500"), 18, "Cohesion (Pa): 400");
  std::ofstream(deck_) << deck;
  const Outcome other = restart(killed, good);
  EXPECT_EQ(other.exit_code, 2) << other.output;
  EXPECT_NE(other.output.find(good.string()), std::string::npos) << other.output;
  EXPECT_NE(other.output.find("another deck"), std::string::npos) << other.output;
}

}  // namespace
}  // namespace argine
