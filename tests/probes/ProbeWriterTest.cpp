// Probes: nearest point, distance to a segment, point probes followed by id after the points
// are permuted, band and profile sections, against hand-computed values.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "CsvRows.hpp"
#include "argine/core/Error.hpp"
#include "argine/points/MaterialPoints.hpp"
#include "argine/probes/ProbeWriter.hpp"

namespace argine {
namespace {

/// Three points: id 0 at (0, 0), id 1 at (1, 0), id 2 at (0, 1); p_L 10, 20, 30 Pa;
/// S_L 1, 0.5, 0.8; all carry liquid. `reversed` stores them in reverse index order (as a
/// sort may), with the same ids.
MaterialPoints threePoints(bool reversed) {
  MaterialPoints points;
  points.allocate(3);
  auto id = Kokkos::create_mirror_view(points.id);
  auto x = Kokkos::create_mirror_view(points.position);
  auto u = Kokkos::create_mirror_view(points.displacement);
  auto p = Kokkos::create_mirror_view(points.pressure_liquid);
  auto s = Kokkos::create_mirror_view(points.saturation);
  auto m = Kokkos::create_mirror_view(points.mass_liquid);
  const double xy[3][2] = {{0, 0}, {1, 0}, {0, 1}};
  const double pressure[3] = {10, 20, 30}, saturation[3] = {1, 0.5, 0.8};
  for (int k = 0; k < 3; ++k) {
    const int i = reversed ? 2 - k : k;
    id(i) = k;
    x(i, 0) = xy[k][0];
    x(i, 1) = xy[k][1];
    u(i, 0) = 0.001 * k;  // displacement x = id / 1000
    u(i, 1) = 0;
    p(i) = pressure[k];
    s(i) = saturation[k];
    m(i) = 1;
  }
  Kokkos::deep_copy(points.id, id);
  Kokkos::deep_copy(points.position, x);
  Kokkos::deep_copy(points.displacement, u);
  Kokkos::deep_copy(points.pressure_liquid, p);
  Kokkos::deep_copy(points.saturation, s);
  Kokkos::deep_copy(points.mass_liquid, m);
  return points;
}

std::string directory() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const auto dir = std::filesystem::path(::testing::TempDir()) / "argine_probes" / info->name();
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir.string();
}

TEST(ProbeGeometry, NearestPointAndSegmentDistance) {
  const ProbeSnapshot snapshot(threePoints(false));
  EXPECT_EQ(nearestPoint(snapshot, {0.9, 0.2}), 1);
  EXPECT_EQ(nearestPoint(snapshot, {0.1, 0.8}), 2);
  // Segment (0,0)-(2,0): (1, 3) projects to along 1, off 3; (3, 4) beyond the end: along 2,
  // off |(3,4)-(2,0)| = sqrt(17).
  SegmentDistance d = segmentDistance({0, 0}, {2, 0}, 1, 3);
  EXPECT_DOUBLE_EQ(d.along, 1);
  EXPECT_DOUBLE_EQ(d.off, 3);
  d = segmentDistance({0, 0}, {2, 0}, 3, 4);
  EXPECT_DOUBLE_EQ(d.along, 2);
  EXPECT_DOUBLE_EQ(d.off, std::sqrt(17.0));
}

TEST(ProbeWriter, FollowsPointsByIdAndWritesSections) {
  ProbesSpec spec;
  spec.points.push_back({"corner", {0.9, 0.1}, 0.2});
  SectionProbeSpec profile;
  profile.name = "bottom";
  profile.kind = SectionProbeSpec::Kind::Profile;
  profile.from = {0, 0};
  profile.to = {1, 0};
  profile.samples = 3;
  profile.band_width = 3;  // averaging radius 1.5: every point
  spec.sections.push_back(profile);
  SectionProbeSpec band;
  band.name = "left";
  band.kind = SectionProbeSpec::Kind::Band;
  band.from = {0, 0};
  band.to = {0, 1};
  band.band_width = 0.2;
  spec.sections.push_back(band);

  const std::string dir = directory();
  ProbeWriter writer(spec, dir, "run", threePoints(false));
  ASSERT_EQ(writer.pointIds().size(), 1u);
  EXPECT_EQ(writer.pointIds()[0], 1);
  writer.write(0.5, threePoints(true));  // indices permuted: the probe must follow id 1

  const auto point = readCsvRows(dir + "/run_probe_corner.csv");
  ASSERT_EQ(point.size(), 1u);
  EXPECT_EQ(point[0][0], 0.5);    // time
  EXPECT_EQ(point[0][1], 1);      // id
  EXPECT_EQ(point[0][2], 1);      // x
  EXPECT_EQ(point[0][4], 0.001);  // displacement x of id 1
  EXPECT_EQ(point[0][8], 20);     // p_L
  EXPECT_EQ(point[0][9], 0.5);    // S_L

  const auto rows = readCsvRows(dir + "/run_section_bottom.csv");
  ASSERT_EQ(rows.size(), 3u);
  // Sample 0 at (0,0) sits on point 0: its values. Sample 1 at (0.5, 0): distances 0.5, 0.5,
  // sqrt(1.25) = 1.1180340; inverse-distance weights 2, 2, 0.8944272 (sum 4.8944272):
  //   p_L = (10*2 + 20*2 + 30*0.8944272) / 4.8944272 = 17.741160
  //   S_L = (1*2 + 0.5*2 + 0.8*0.8944272) / 4.8944272 = 0.7591372
  EXPECT_DOUBLE_EQ(rows[0][5], 10);
  EXPECT_DOUBLE_EQ(rows[0][6], 1);
  EXPECT_DOUBLE_EQ(rows[1][2], 0.5);  // distance along
  EXPECT_NEAR(rows[1][5], 17.741160, 1e-6);
  EXPECT_NEAR(rows[1][6], 0.7591372, 1e-7);
  EXPECT_EQ(rows[1][7], 3);  // points averaged

  const auto left = readCsvRows(dir + "/run_section_left.csv");
  ASSERT_EQ(left.size(), 2u);  // ids 0 and 2 lie on x = 0; id 1 is 1 m away
  for (const auto& row : left) EXPECT_NE(row[1], 1);
}

TEST(ProbeWriter, PointBeyondToleranceIsAnInputError) {
  ProbesSpec spec;
  spec.points.push_back({"far", {0.5, 0.5}, 0.1});  // nearest is 0.7071 m away
  try {
    ProbeWriter writer(spec, directory(), "run", threePoints(false));
    ADD_FAILURE() << "no InputError";
  } catch (const InputError& error) {
    EXPECT_EQ(error.where(), "Probes/Points/far/Position (m)");
  }
}

}  // namespace
}  // namespace argine
