// [Checkpoint] The checkpoint container: payload round trip, the header checks that reject a
// truncated, corrupted, foreign or other-deck file with a message naming it, the atomic write,
// the material points bit for bit; and the output files a restart continues (CSV, Exodus).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>

#include "argine/checkpoint/CheckpointFile.hpp"
#include "argine/core/Error.hpp"
#include "argine/output/CsvWriter.hpp"
#include "argine/points/MaterialPoints.hpp"

namespace argine {
namespace {

namespace fs = std::filesystem;

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::path(::testing::TempDir()) / ("argine_checkpoint_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string readAll(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void writeAll(const fs::path& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
}

// The InputError thrown by `run`, or "" when none.
template <class Run>
std::string inputError(Run&& run) {
  try {
    run();
  } catch (const InputError& error) {
    return error.what();
  }
  return "";
}

TEST(CheckpointFile, Fnv1aOfKnownStrings) {
  // FNV-1a 64 reference values (offset basis 0xcbf29ce484222325, prime 0x100000001b3):
  // "" -> the offset basis; "a" -> (basis ^ 0x61) * prime = 0xaf63dc4c8601ec8c.
  EXPECT_EQ(fnv1a64("", 0), 0xcbf29ce484222325ULL);
  EXPECT_EQ(fnv1a64("a", 1), 0xaf63dc4c8601ec8cULL);
}

TEST(CheckpointFile, PayloadRoundTripAndAtomicWrite) {
  const fs::path dir = scratch("roundtrip");
  const std::string path = (dir / "run.checkpoint").string();
  CheckpointWriter out;
  out.put<double>(0.1);
  out.put<std::int32_t>(-7);
  out.putString("stage 'a'");
  out.putVector(std::vector<double>{1.5, -0.0, std::numeric_limits<double>::denorm_min()});
  const auto size = writeCheckpointFile(path, 42, out.payload());
  EXPECT_EQ(size, kCheckpointHeaderBytes + out.payload().size());
  EXPECT_EQ(fs::file_size(path), size);
  EXPECT_FALSE(fs::exists(path + ".part"));  // renamed, not left behind

  CheckpointReader in(readCheckpointFile(path, 42), path);
  EXPECT_EQ(in.get<double>(), 0.1);
  EXPECT_EQ(in.get<std::int32_t>(), -7);
  EXPECT_EQ(in.getString(), "stage 'a'");
  const auto values = in.getVector<double>();
  ASSERT_EQ(values.size(), 3u);
  EXPECT_EQ(values[0], 1.5);
  EXPECT_TRUE(std::signbit(values[1]));
  EXPECT_EQ(values[2], std::numeric_limits<double>::denorm_min());
  in.expectEnd();
  // Reading past the end is an error naming the file, not undefined behaviour.
  EXPECT_NE(inputError([&] { in.get<double>(); }).find(path), std::string::npos);
}

TEST(CheckpointFile, RejectsTruncatedCorruptForeignAndOtherDeckFiles) {
  const fs::path dir = scratch("reject");
  const std::string path = (dir / "run.checkpoint").string();
  CheckpointWriter out;
  for (int k = 0; k < 100; ++k) out.put<double>(k);
  writeCheckpointFile(path, 7, out.payload());
  const std::string good = readAll(path);

  auto expectRejected = [&](const std::string& bytes, std::uint64_t hash, const char* what) {
    writeAll(path, bytes);
    const std::string message = inputError([&] { readCheckpointFile(path, hash); });
    EXPECT_NE(message.find(path), std::string::npos) << message;
    EXPECT_NE(message.find(what), std::string::npos) << message;
  };
  expectRejected(good.substr(0, 20), 7, "truncated");               // inside the header
  expectRejected(good.substr(0, good.size() - 8), 7, "truncated");  // payload cut short
  std::string flipped = good;
  flipped[kCheckpointHeaderBytes + 100] ^= 0x10;  // one bit of the payload
  expectRejected(flipped, 7, "payload checksum");
  std::string header = good;
  header[24] ^= 0x01;  // the payload size field
  expectRejected(header, 7, "header checksum");
  expectRejected("ARGINE? definitely not a checkpoint, but long enough for a header......", 7,
                 "not an argine checkpoint");
  expectRejected(good, 8, "another deck");
  const std::string missing = (dir / "nothere.checkpoint").string();
  EXPECT_NE(inputError([&] { readCheckpointFile(missing, 7); }).find(missing), std::string::npos);
}

TEST(CheckpointFile, MaterialPointsBitForBit) {
  MaterialPoints points;
  points.allocate(3);
  auto fill = [](auto view, double offset) {
    auto host = Kokkos::create_mirror_view(view);
    auto* data = host.data();
    for (std::size_t i = 0; i < host.span(); ++i)
      data[i] = static_cast<std::remove_pointer_t<decltype(data)>>(offset + 0.1 * i + 1e-17 * i);
    Kokkos::deep_copy(view, host);
  };
  fill(points.id, 5);
  fill(points.element, 1);
  fill(points.position, 0.3);
  fill(points.stress_effective, -1e4 / 3);
  fill(points.pressure_liquid, 1.0 / 3);
  fill(points.plastic_state, 2);
  CheckpointWriter out;
  putPoints(out, points);
  const fs::path dir = scratch("points");
  const std::string path = (dir / "p.checkpoint").string();
  writeCheckpointFile(path, 1, out.payload());

  MaterialPoints back;
  back.allocate(3);
  CheckpointReader in(readCheckpointFile(path, 1), path);
  getPoints(in, back);
  in.expectEnd();
  auto same = [](auto a, auto b) {
    auto ha = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), a);
    auto hb = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), b);
    ASSERT_EQ(ha.span(), hb.span());
    EXPECT_EQ(std::memcmp(ha.data(), hb.data(), ha.span() * sizeof(*ha.data())), 0);
  };
  same(points.id, back.id);
  same(points.element, back.element);
  same(points.position, back.position);
  same(points.stress_effective, back.stress_effective);
  same(points.pressure_liquid, back.pressure_liquid);
  same(points.plastic_state, back.plastic_state);

  MaterialPoints other;
  other.allocate(4);  // the deck seeds another number of points
  CheckpointReader again(readCheckpointFile(path, 1), path);
  EXPECT_NE(inputError([&] { getPoints(again, other); }).find("material points"),
            std::string::npos);
}

TEST(CsvResume, TruncatesToTheRecordedBytesAndAppends) {
  const fs::path dir = scratch("csv");
  const std::string path = (dir / "d.csv").string();
  std::uintmax_t mark = 0;
  {
    CsvWriter csv(path, {"time", "value"});
    csv.writeRow({0, 1});
    mark = csv.bytes();  // a checkpoint here
    EXPECT_EQ(mark, fs::file_size(path));
    csv.writeRow({1, 2});  // written by the run that is then killed
  }
  {
    CsvWriter csv(path, {"time", "value"}, CsvResume{mark});
    csv.writeRow({1, 3});
  }
  EXPECT_EQ(readAll(path), "time,value\n0,1\n1,3\n");
  // Another file than the checkpointed run's: shorter, or another header.
  EXPECT_NE(inputError([&] {
              CsvWriter(path, {"time", "value"}, CsvResume{1000});
            }).find(path),
            std::string::npos);
  EXPECT_NE(inputError([&] {
              CsvWriter(path, {"t", "value"}, CsvResume{mark});
            }).find("header"),
            std::string::npos);
}

}  // namespace
}  // namespace argine
