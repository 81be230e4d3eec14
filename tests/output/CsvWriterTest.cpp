#include "argine/output/CsvWriter.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include "OutputTestData.hpp"
#include "argine/core/Error.hpp"

namespace argine {
namespace {

std::string contents(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// A directory of the test's own: ctest runs these tests in parallel processes, and a shared
// one was removed by one test while another wrote into it ("cannot remove: Directory not
// empty", seen once in CI).
std::string csvPath(const std::string& name) {
  const std::string dir = test::freshDirectory(
      std::string("csv_") + ::testing::UnitTest::GetInstance()->current_test_info()->name());
  std::filesystem::create_directories(dir);
  return dir + "/" + name;
}

TEST(CsvWriter, WritesTheHeaderOnceAndEachRowAtOnce) {
  const std::string path = csvPath("energy.csv");
  CsvWriter csv(path, {"time", "kinetic_energy", "dt"});
  EXPECT_EQ(contents(path), "time,kinetic_energy,dt\n");
  csv.writeRow({0.0, 1.5, 1e-4});
  // Flushed: readable before the writer is closed. Shortest exact form: 1e-4 -> "1e-04".
  EXPECT_EQ(contents(path), "time,kinetic_energy,dt\n0,1.5,1e-04\n");
  csv.writeRow({0.1, -2.0, 2.5e-4});
  EXPECT_EQ(contents(path), "time,kinetic_energy,dt\n0,1.5,1e-04\n0.1,-2,0.00025\n");
}

TEST(CsvWriter, NumbersReadBackExactly) {
  const std::string path = csvPath("exact.csv");
  const double third = 1.0 / 3.0;
  {
    CsvWriter csv(path, {"a", "b", "c"});
    csv.writeRow({third, 6.02214076e23, -1.0e-300});
  }
  std::ifstream in(path);
  std::string header;
  std::getline(in, header);
  double a = 0, b = 0, c = 0;
  char comma = 0;
  in >> a >> comma >> b >> comma >> c;
  EXPECT_EQ(a, third);
  EXPECT_EQ(b, 6.02214076e23);
  EXPECT_EQ(c, -1.0e-300);
}

TEST(CsvWriter, WritesNonFiniteValuesAsNanAndInf) {
  const std::string path = csvPath("nan.csv");
  CsvWriter csv(path, {"x", "y"});
  csv.writeRow(
      {std::numeric_limits<double>::quiet_NaN(), -std::numeric_limits<double>::infinity()});
  EXPECT_EQ(contents(path), "x,y\nnan,-inf\n");
}

TEST(CsvWriter, QuotesColumnNamesThatNeedIt) {
  const std::string path = csvPath("quoted.csv");
  CsvWriter csv(path, {"flux, river", "say \"hi\""});
  EXPECT_EQ(contents(path), "\"flux, river\",\"say \"\"hi\"\"\"\n");
}

TEST(CsvWriter, RejectsARowOfTheWrongLength) {
  const std::string path = csvPath("short.csv");
  CsvWriter csv(path, {"time", "mass"});
  EXPECT_THROW(csv.writeRow({1.0}), std::invalid_argument);
  EXPECT_THROW(csv.writeRow({1.0, 2.0, 3.0}), std::invalid_argument);
  EXPECT_EQ(contents(path), "time,mass\n");
}

TEST(CsvWriter, NamesTheFileItCannotOpen) {
  const std::string path = csvPath("missing_dir") + "/diagnostics.csv";
  try {
    CsvWriter csv(path, {"time"});
    FAIL() << "expected InputError";
  } catch (const InputError& error) {
    EXPECT_EQ(error.where(), path);
  }
}

}  // namespace
}  // namespace argine
