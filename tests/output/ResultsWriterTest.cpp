// Round trip of the Exodus results: written with ResultsWriter, read back with the exodus API.
#include "argine/output/ResultsWriter.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "ExodusReadBack.hpp"
#include "OutputTestData.hpp"
#include "argine/core/Error.hpp"

namespace argine {
namespace {

using test::ExodusReadBack;
using test::makePoints;
using test::nodalValues;
using test::PointSpec;

const std::vector<std::string> kMaterials = {"clay", "sand", "empty"};

// Creation order is deliberately not the file order. File nodes are sorted by (material, id):
// node 0 = id 0 (clay), node 1 = id 2 (clay), node 2 = id 5 (sand), node 3 = id 7 (sand).
const std::vector<PointSpec> kStep1 = {
    {7, 1, 1.5, 0.5}, {2, 0, 0.25, 0.75}, {5, 1, 1.75, 0.25}, {0, 0, 0.5, 0.5}};
// The same points after a sort (another order) and some motion:
// id 0 moved by (0.1, -0.1), id 2 by (0, 0.1), id 5 not, id 7 by (-0.5, 0).
const std::vector<PointSpec> kStep2 = {
    {5, 1, 1.75, 0.25}, {0, 0, 0.6, 0.4}, {7, 1, 1.0, 0.5}, {2, 0, 0.25, 0.85}};

// Grid fields of the two-quad mesh (6 nodes) at a step: head = 10 s + node, p = -s.
std::vector<NodalField> gridFields(int s) {
  std::vector<double> head(6), pressure(6);
  for (int n = 0; n < 6; ++n) head[n] = 10.0 * s + n, pressure[n] = -s;
  return {{"pressure", nodalValues(pressure)}, {"head", nodalValues(head)}};
}

std::vector<std::string> gridFieldNames() {
  return {"head", "pressure"};
}

void expectNear(const std::vector<double>& actual, const std::vector<double>& expected) {
  ASSERT_EQ(actual.size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i)
    EXPECT_NEAR(actual[i], expected[i], 1e-12 * (1.0 + std::abs(expected[i]))) << "at node " << i;
}

class ResultsWriterTest : public ::testing::Test {
 protected:
  std::string dir =
      test::freshDirectory(::testing::UnitTest::GetInstance()->current_test_info()->name());
  Mesh mesh = test::twoQuadMesh();

  // Writes steps at t = 0, 0.5, 1.25 (points as kStep1, kStep2, kStep2) and closes the files.
  void writeThreeSteps() {
    auto points = makePoints(kStep1);
    ResultsWriter writer(dir, "run", mesh, kMaterials, gridFieldNames(), points);
    writer.write(0.0, points, gridFields(1));
    auto moved = makePoints(kStep2);
    writer.write(0.5, moved, gridFields(2));
    writer.write(1.25, moved, gridFields(3));
  }
  std::string pointsPath() const { return dir + "/run_points.e"; }
  std::string gridPath() const { return dir + "/run_grid.e"; }
};

TEST_F(ResultsWriterTest, PointsFileHasOneCircleBlockPerMaterialNamedAfterIt) {
  writeThreeSteps();
  ExodusReadBack file(pointsPath());
  ASSERT_TRUE(file.ok());
  EXPECT_EQ(file.blockNames(), kMaterials);
  EXPECT_EQ(file.blockIds(), (std::vector<int>{1, 2, 3}));
  const int expected_sizes[3] = {2, 2, 0};
  // Block connectivity (1-based nodes): clay = nodes 1, 2; sand = nodes 3, 4.
  const std::vector<int> expected_conn[3] = {{1, 2}, {3, 4}, {}};
  for (int b = 0; b < 3; ++b) {
    int num_elements = -1, nodes_per_element = -1;
    const std::string type = file.blockType(b + 1, &num_elements, &nodes_per_element);
    EXPECT_EQ(num_elements, expected_sizes[b]) << kMaterials[b];
    if (num_elements > 0) {
      EXPECT_EQ(type, "CIRCLE");
      EXPECT_EQ(nodes_per_element, 1);
    }
    EXPECT_EQ(file.connectivity(b + 1, num_elements), expected_conn[b]) << kMaterials[b];
  }
}

TEST_F(ResultsWriterTest, ReferenceCoordinatesArePositionsAtCreationOrderedByMaterialThenId) {
  writeThreeSteps();
  ExodusReadBack file(pointsPath());
  ASSERT_EQ(file.numNodes(), 4);
  // Nodes id 0, 2, 5, 7 at their kStep1 positions (not the moved kStep2 ones).
  expectNear(file.coordinate(0), {0.5, 0.25, 1.75, 1.5});
  expectNear(file.coordinate(1), {0.5, 0.75, 0.25, 0.5});
}

TEST_F(ResultsWriterTest, PointFieldsFollowPermanentIdsWhenPointsArePermuted) {
  writeThreeSteps();
  ExodusReadBack file(pointsPath());
  ASSERT_EQ(file.numNodes(), 4);
  for (int step = 1; step <= 3; ++step) {
    // Fields are functions of the id (OutputTestData.hpp); nodes hold ids 0, 2, 5, 7.
    expectNear(file.nodal("point_id", step), {0, 2, 5, 7});
    expectNear(file.nodal("material", step), {0, 0, 1, 1});
    expectNear(file.nodal("pressure_liquid", step), {-3000, -1000, 2000, 4000});
    // suction = max(0, -p_L)
    expectNear(file.nodal("suction", step), {3000, 1000, 0, 0});
    expectNear(file.nodal("velocity_solid_x", step), {0, 2, 5, 7});
    expectNear(file.nodal("velocity_solid_y", step), {0, -2, -5, -7});
    expectNear(file.nodal("velocity_liquid_x", step), {0, 4, 10, 14});
    expectNear(file.nodal("velocity_liquid_y", step), {0, 6, 15, 21});
    expectNear(file.nodal("saturation", step), {0, 0.2, 0.5, 0.7});
    expectNear(file.nodal("conductivity", step), {0, 2e-6, 5e-6, 7e-6});
    expectNear(file.nodal("porosity", step), {0.3, 0.32, 0.35, 0.37});
    expectNear(file.nodal("stress_eff_xx", step), {0, -20, -50, -70});
    expectNear(file.nodal("stress_eff_yy", step), {0, -40, -100, -140});
    expectNear(file.nodal("stress_eff_zz", step), {0, -60, -150, -210});
    expectNear(file.nodal("stress_eff_xy", step), {0, 10, 25, 35});
    expectNear(file.nodal("stress_eff_xz", step), {0, 0, 0, 0});
    expectNear(file.nodal("stress_eff_yz", step), {0, 0, 0, 0});
    expectNear(file.nodal("deviatoric_strain", step), {0, 0.02, 0.05, 0.07});
    expectNear(file.nodal("plastic_strain", step), {0, 0.002, 0.005, 0.007});
    expectNear(file.nodal("plastic_state", step), {0, 2, 2, 1});  // id % 3
    expectNear(file.nodal("volume", step), {0.25, 2.25, 5.25, 7.25});
    expectNear(file.nodal("displacement_x", step), {0, 1, 2.5, 3.5});
    expectNear(file.nodal("displacement_y", step), {0, -1, -2.5, -3.5});
  }
  // displ_ = position - reference: zero at step 1, the kStep2 motion at steps 2 and 3.
  expectNear(file.nodal("displ_x", 1), {0, 0, 0, 0});
  expectNear(file.nodal("displ_y", 1), {0, 0, 0, 0});
  for (int step = 2; step <= 3; ++step) {
    expectNear(file.nodal("displ_x", step), {0.1, 0, 0, -0.5});
    expectNear(file.nodal("displ_y", step), {-0.1, 0.1, 0, 0});
  }
}

TEST_F(ResultsWriterTest, PointVariableNamesAreTheDocumentedList) {
  writeThreeSteps();
  ExodusReadBack file(pointsPath());
  const std::vector<std::string> expected = {
      "displ_x",          "displ_y",          "displacement_x",    "displacement_y",
      "velocity_solid_x", "velocity_solid_y", "velocity_liquid_x", "velocity_liquid_y",
      "pressure_liquid",  "suction",          "saturation",        "conductivity",
      "porosity",         "stress_eff_xx",    "stress_eff_yy",     "stress_eff_zz",
      "stress_eff_xy",    "stress_eff_xz",    "stress_eff_yz",     "deviatoric_strain",
      "plastic_strain",   "plastic_state",    "material",          "volume",
      "point_id"};
  EXPECT_EQ(file.nodalVariableNames(), expected);
  EXPECT_EQ(pointVariableNames(), expected);
}

TEST_F(ResultsWriterTest, TimesAreWrittenToBothFiles) {
  writeThreeSteps();
  for (const auto& path : {pointsPath(), gridPath()}) {
    ExodusReadBack file(path);
    EXPECT_EQ(file.numSteps(), 3) << path;
    EXPECT_EQ(file.times(), (std::vector<double>{0.0, 0.5, 1.25})) << path;
    EXPECT_EQ(file.time(3), 1.25) << path;
  }
}

TEST_F(ResultsWriterTest, GridFileHasTheMeshAndNamedNodalFields) {
  writeThreeSteps();
  ExodusReadBack file(gridPath());
  ASSERT_EQ(file.numNodes(), 6);
  expectNear(file.coordinate(0), {0, 1, 2, 0, 1, 2});
  expectNear(file.coordinate(1), {0, 0, 0, 1, 1, 1});
  EXPECT_EQ(file.blockNames(), (std::vector<std::string>{"left", "right"}));
  EXPECT_EQ(file.count(EX_INQ_NODE_SETS), 1);
  EXPECT_EQ(file.count(EX_INQ_SIDE_SETS), 1);
  // Declared order, whatever order write() was given them in.
  EXPECT_EQ(file.nodalVariableNames(), gridFieldNames());
  for (int s = 1; s <= 3; ++s) {
    expectNear(file.nodal("head", s),
               {10.0 * s, 10.0 * s + 1, 10.0 * s + 2, 10.0 * s + 3, 10.0 * s + 4, 10.0 * s + 5});
    expectNear(file.nodal("pressure", s), std::vector<double>(6, -s));
  }
}

TEST_F(ResultsWriterTest, GridWriteRejectsMissingUndeclaredOrWrongSizeFields) {
  auto points = makePoints(kStep1);
  ResultsWriter writer(dir, "run", mesh, kMaterials, gridFieldNames(), points);
  auto fields = gridFields(1);
  EXPECT_THROW(writer.write(0.0, points, {fields[0]}), std::invalid_argument);  // head missing
  auto extra = fields;
  extra.push_back({"velocity", nodalValues(std::vector<double>(6, 0.0))});
  EXPECT_THROW(writer.write(0.0, points, extra), std::invalid_argument);
  auto short_field = fields;
  short_field[1].values = nodalValues({1.0, 2.0});
  EXPECT_THROW(writer.write(0.0, points, short_field), std::invalid_argument);
  EXPECT_THROW(GridFile(dir + "/twice.e", mesh, {"head", "head"}), std::invalid_argument);
  EXPECT_EQ(writer.steps(), 0);
}

TEST_F(ResultsWriterTest, StepsAreReadableWhileTheWriterIsStillOpen) {
  // A killed run never closes its files: each written step must already be on disk.
  auto points = makePoints(kStep1);
  ResultsWriter writer(dir, "run", mesh, kMaterials, gridFieldNames(), points);
  writer.write(0.0, points, gridFields(1));
  writer.write(2.0, points, gridFields(2));
  for (const auto& path : {pointsPath(), gridPath()}) {
    ExodusReadBack file(path);
    EXPECT_EQ(file.times(), (std::vector<double>{0.0, 2.0})) << path;
  }
  ExodusReadBack file(pointsPath());
  expectNear(file.nodal("pressure_liquid", 2), {-3000, -1000, 2000, 4000});
}

TEST_F(ResultsWriterTest, RemovedPointStartsTheNextFileOfTheSeries) {
  auto points = makePoints(kStep1);
  ResultsWriter writer(dir, "run", mesh, kMaterials, gridFieldNames(), points);
  writer.write(0.0, points, gridFields(1));
  writer.write(1.0, points, gridFields(2));
  // Point id 2 leaves; the others moved (kStep2 without id 2).
  auto fewer = makePoints({{5, 1, 1.75, 0.25}, {0, 0, 0.6, 0.4}, {7, 1, 1.0, 0.5}});
  writer.write(2.0, fewer, gridFields(3));
  writer.write(3.0, fewer, gridFields(4));
  EXPECT_EQ(writer.pointsFileCount(), 2);
  EXPECT_EQ(writer.pointsPath(), dir + "/run_points.e-s0002");
  EXPECT_EQ(ResultsWriter::pointsSeriesPath("out", "run", 12), "out/run_points.e-s0012");

  ExodusReadBack first(pointsPath());
  EXPECT_EQ(first.numNodes(), 4);
  EXPECT_EQ(first.times(), (std::vector<double>{0.0, 1.0}));
  ExodusReadBack second(dir + "/run_points.e-s0002");
  ASSERT_EQ(second.numNodes(), 3);
  EXPECT_EQ(second.times(), (std::vector<double>{2.0, 3.0}));
  // The new file's reference is the positions at its creation: ids 0, 5, 7.
  expectNear(second.coordinate(0), {0.6, 1.75, 1.0});
  expectNear(second.nodal("displ_x", 1), {0, 0, 0});
  expectNear(second.nodal("point_id", 2), {0, 5, 7});
  ExodusReadBack grid(gridPath());
  EXPECT_EQ(grid.numSteps(), 4);
}

TEST_F(ResultsWriterTest, CreatesMissingOutputDirectoriesAndLeavesNoTemporaryFiles) {
  const std::string nested = dir + "/a/b";
  auto points = makePoints(kStep1);
  ResultsWriter writer(nested, "run", mesh, kMaterials, gridFieldNames(), points);
  EXPECT_TRUE(std::filesystem::exists(nested + "/run_grid.e"));
  EXPECT_TRUE(std::filesystem::exists(nested + "/run_points.e"));
  for (const auto& entry : std::filesystem::directory_iterator(nested))
    EXPECT_EQ(entry.path().extension(), ".e") << entry.path();
}

TEST_F(ResultsWriterTest, ReportsAnOutputDirectoryThatCannotBeCreated) {
  std::filesystem::create_directories(dir);
  std::ofstream(dir + "/plain_file") << "not a directory";
  const std::string impossible = dir + "/plain_file/results";
  auto points = makePoints(kStep1);
  try {
    ResultsWriter writer(impossible, "run", mesh, kMaterials, {}, points);
    FAIL() << "expected InputError";
  } catch (const InputError& error) {
    EXPECT_EQ(error.where(), impossible);
    EXPECT_NE(std::string(error.what()).find("output directory"), std::string::npos);
  }
}

TEST_F(ResultsWriterTest, RemovesStaleSeriesFilesOfAnEarlierRun) {
  std::filesystem::create_directories(dir);
  std::ofstream(dir + "/run_points.e-s0002") << "stale";
  std::ofstream(dir + "/other_points.e-s0002") << "another stem";
  auto points = makePoints(kStep1);
  ResultsWriter writer(dir, "run", mesh, kMaterials, {}, points);
  EXPECT_FALSE(std::filesystem::exists(dir + "/run_points.e-s0002"));
  EXPECT_TRUE(std::filesystem::exists(dir + "/other_points.e-s0002"));
}

TEST_F(ResultsWriterTest, KeepsLongMaterialNames) {
  const std::vector<std::string> names = {"embankment_clay_upper_compacted_layer_2", "sand"};
  auto points = makePoints(kStep1);
  ResultsWriter writer(dir, "run", mesh, names, {}, points);
  writer.write(0.0, points, {});
  ExodusReadBack file(pointsPath());
  EXPECT_EQ(file.blockNames(), names);
}

TEST_F(ResultsWriterTest, RejectsAPointWhoseMaterialHasNoName) {
  auto points = makePoints({{0, 3, 0.5, 0.5}});
  EXPECT_THROW(ResultsWriter(dir, "run", mesh, kMaterials, {}, points), RunError);
}

TEST_F(ResultsWriterTest, WhenAllPointsAreGoneTheNextFileHasTimesOnly) {
  auto points = makePoints(kStep1);
  ResultsWriter writer(dir, "run", mesh, kMaterials, {}, points);
  writer.write(0.0, points, {});
  MaterialPoints none;
  none.allocate(0);
  writer.write(1.0, none, {});
  writer.write(2.0, none, {});
  EXPECT_EQ(writer.pointsFileCount(), 2);
  ExodusReadBack second(dir + "/run_points.e-s0002");
  EXPECT_EQ(second.numNodes(), 0);
  EXPECT_EQ(second.times(), (std::vector<double>{1.0, 2.0}));
}

}  // namespace
}  // namespace argine
