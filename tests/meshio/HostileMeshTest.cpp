// [Meshio] Hostile mesh files (issue P8): an inverted element among counter-clockwise ones
// (the reader reorders it, and the mesh then overlaps), empty, truncated and non-Exodus
// files. Each gives an InputError naming the file.
#include <gtest/gtest.h>
#include <netcdf.h>

#include <array>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "argine/core/Error.hpp"
#include "argine/mesh/MeshGeometry.hpp"
#include "argine/meshio/ExodusMesh.hpp"
#include "argine/meshio/MeshGenerators.hpp"

namespace argine {
namespace {

std::string scratchFile(const std::string& name) {
  return std::string(ARGINE_BINARY_DIR) + "/tests/meshio_hostile_" + name;
}

/// Two triangles (0 1 2) and (1 3 2) sharing the side 1-2, with node 3 at `corner`.
Mesh twoTriangles(std::array<double, 2> corner) {
  const std::vector<std::array<double, 2>> nodes{{0, 0}, {1, 0}, {0, 1}, corner};
  Mesh mesh;
  mesh.type = ElementType::Tri3;
  mesh.coordinates = Kokkos::View<Real* [kDim], MemSpace>("x", nodes.size());
  mesh.connectivity = Kokkos::View<int**, MemSpace>("conn", 2, 3);
  mesh.element_block = Kokkos::View<int*, MemSpace>("block", 2);
  for (std::size_t n = 0; n < nodes.size(); ++n)
    for (int d = 0; d < 2; ++d) mesh.coordinates(n, d) = nodes[n][d];
  const int conn[2][3] = {{0, 1, 2}, {1, 3, 2}};
  for (int e = 0; e < 2; ++e)
    for (int k = 0; k < 3; ++k) mesh.connectivity(e, k) = conn[e][k];
  mesh.blocks = {{"soil", 1, {0, 1}}};
  return mesh;
}

/// Writes argine's generated 0.5 m rectangle mesh to scratch file `name` and returns the
/// file's bytes (a valid Exodus file to damage).
std::string goodMeshBytes(const std::string& name) {
  GeneratorSpec generator;
  generator.element_size = 0.5;
  const std::string path = scratchFile(name);
  writeExodusMesh(path, generateMesh(generator));
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

TEST(HostileMesh, AnInvertedElementAmongCounterClockwiseOnesIsReported) {
  const std::string path = scratchFile("inverted.exo");
  // Node 3 at (1, 1): both triangles counter-clockwise; the file reads and passes.
  writeExodusMesh(path, twoTriangles({1, 1}));
  EXPECT_NO_THROW(checkMeshQuality(readExodusMesh(path), path));
  // Node 3 at (0.2, 0.2), on node 0's side of 1-2: triangle 2 is inverted (signed area
  // (1/2)((0.2-1)(1-0) - (0.2-0)(0-1)) = (1/2)(-0.8 + 0.2) = -0.3). Reordered on reading,
  // it runs 1 -> 2 like triangle 1, so the two overlap.
  writeExodusMesh(path, twoTriangles({0.2, 0.2}));
  try {
    checkMeshQuality(readExodusMesh(path), path);
    ADD_FAILURE() << "an overlapping (inverted) element was accepted";
  } catch (const InputError& error) {
    EXPECT_EQ(error.where(), path);
    const std::string message = error.what();
    EXPECT_NE(message.find("element 1 (block soil) and element 2 (block soil)"), std::string::npos)
        << message;
    EXPECT_NE(message.find("from node 2 to node 3"), std::string::npos) << message;
    EXPECT_NE(message.find("inverted"), std::string::npos) << message;
  }
}

TEST(HostileMesh, EmptyTruncatedAndForeignFilesNameTheFile) {
  const std::string bytes = goodMeshBytes("good.exo");
  ASSERT_GT(bytes.size(), 64u);
  const std::vector<std::string> contents{
      "",                                 // empty
      bytes.substr(0, bytes.size() / 2),  // truncated in the data
      bytes.substr(0, 40),                // truncated in the header
      "argine:\n  Title: a deck, not a mesh\n",
      std::string(4096, '\0'),
  };
  for (std::size_t k = 0; k < contents.size(); ++k) {
    SCOPED_TRACE(k);
    const std::string path = scratchFile("bad" + std::to_string(k) + ".exo");
    std::ofstream(path, std::ios::binary) << contents[k];
    try {
      checkMeshQuality(readExodusMesh(path), path);
      ADD_FAILURE() << "a bad mesh file was read";
    } catch (const InputError& error) {
      EXPECT_EQ(error.where(), path) << error.what();
    }
  }
}

TEST(HostileMesh, AHeaderClaimingMoreThanTheFileHoldsNamesTheFile) {
  std::string bytes = goodMeshBytes("header.exo");
  // netCDF header: the dimension name "num_nodes" (9 bytes, padded to 12), then its length
  // as a 4-byte big-endian integer. Claim 2^31 - 1 nodes (32 GiB of coordinates).
  const auto at = bytes.find("num_nodes");
  ASSERT_NE(at, std::string::npos);
  bytes.replace(at + 12, 4, std::string("\x7f\xff\xff\xff", 4));
  const std::string path = scratchFile("huge_header.exo");
  std::ofstream(path, std::ios::binary) << bytes;
  try {
    readExodusMesh(path);
    ADD_FAILURE() << "a header of 2^31 - 1 nodes was accepted";
  } catch (const InputError& error) {
    EXPECT_EQ(error.where(), path) << error.what();
  }
}

TEST(HostileMesh, ADamagedNetcdfHeaderFoundByFuzzingIsRejectedBeforeNetcdfOpensIt) {
  // fuzz/fuzz_exodus_reader's first finding: 963 bytes whose header counts made libnetcdf's
  // nc_open allocate and clear 1.7 GB for over 10 s. Now an InputError naming the file.
  const std::string path =
      std::string(ARGINE_SOURCE_DIR) + "/tests/meshio/damaged_netcdf_header.exo";
  try {
    readExodusMesh(path);
    ADD_FAILURE() << "the damaged header was read";
  } catch (const InputError& error) {
    EXPECT_EQ(error.where(), path);
    EXPECT_NE(std::string(error.what()).find("damaged netCDF header"), std::string::npos)
        << error.what();
  }
}

/// Replaces variable `name` of an Exodus file by an integer variable of the same name over
/// `dimensions` (the old one is renamed aside), as a damaged or hostile writer could.
void redefineVariable(const std::string& path, const std::string& name,
                      const std::vector<std::string>& dimensions) {
  int ncid = -1, varid = -1;
  ASSERT_EQ(nc_open(path.c_str(), NC_WRITE, &ncid), NC_NOERR);
  ASSERT_EQ(nc_redef(ncid), NC_NOERR);
  ASSERT_EQ(nc_inq_varid(ncid, name.c_str(), &varid), NC_NOERR);
  ASSERT_EQ(nc_rename_var(ncid, varid, (name + "_old").c_str()), NC_NOERR);
  std::vector<int> dims;
  std::size_t entries = 1;
  for (const auto& dimension : dimensions) {
    int id = -1;
    std::size_t length = 0;
    ASSERT_EQ(nc_inq_dimid(ncid, dimension.c_str(), &id), NC_NOERR) << dimension;
    ASSERT_EQ(nc_inq_dimlen(ncid, id, &length), NC_NOERR);
    dims.push_back(id);
    entries *= length;
  }
  ASSERT_EQ(
      nc_def_var(ncid, name.c_str(), NC_INT, static_cast<int>(dims.size()), dims.data(), &varid),
      NC_NOERR);
  ASSERT_EQ(nc_enddef(ncid), NC_NOERR);
  const std::vector<int> values(entries, 1);  // node 1, id 1: valid values, wrong shape
  ASSERT_EQ(nc_put_var_int(ncid, varid, values.data()), NC_NOERR);
  ASSERT_EQ(nc_close(ncid), NC_NOERR);
}

TEST(HostileMesh, VariablesOfAnotherShapeThanTheExodusLayoutAreRejectedBeforeExodusReadsThem) {
  // fuzz/fuzz_exodus_reader's heap corruption (CI, session 4): libexoIIv2c sizes its id
  // buffer from the dimension num_el_blk and then reads the whole variable eb_prop1. With
  // eb_prop1 over num_nodes (25 entries for 1 block) it wrote past the buffer; the same holds
  // for a block's connectivity and a set's entries, read into buffers argine sizes.
  GeneratorSpec generator;
  generator.element_size = 0.5;
  const Mesh mesh = generateMesh(generator);
  struct Case {
    std::string variable;
    std::vector<std::string> dimensions;
  };
  const std::vector<Case> cases{{"eb_prop1", {"num_nodes"}},
                                {"connect1", {"num_nodes", "num_nod_per_el1"}},
                                {"node_ns1", {"num_nodes"}}};
  for (const auto& c : cases) {
    SCOPED_TRACE(c.variable);
    const std::string path = scratchFile("layout_" + c.variable + ".exo");
    writeExodusMesh(path, mesh);
    ASSERT_NO_THROW(readExodusMesh(path));
    redefineVariable(path, c.variable, c.dimensions);
    try {
      readExodusMesh(path);
      ADD_FAILURE() << c.variable << " of another shape was accepted";
    } catch (const InputError& error) {
      EXPECT_EQ(error.where(), path);
      EXPECT_NE(std::string(error.what()).find("variable " + c.variable + " has"),
                std::string::npos)
          << error.what();
    }
  }
}

TEST(HostileMesh, AnInt64StatusAttributeDoesNotMakeTheLibraryWrite64BitIntegers) {
  // fuzz/fuzz_exodus_reader (session 9): ex_open takes the API's integer sizes from the
  // file's int64_status attribute too, and ex_get_ids then wrote 64-bit ids into argine's
  // array of ints (a heap overflow valgrind showed in ncx_getn_int_longlong). The reader now
  // sets 32-bit integers for the API: the mesh reads as without the attribute.
  GeneratorSpec generator;
  generator.element_size = 0.5;
  const Mesh mesh = generateMesh(generator);
  const std::string path = scratchFile("int64_status.exo");
  writeExodusMesh(path, mesh);
  int ncid = -1;
  ASSERT_EQ(nc_open(path.c_str(), NC_WRITE, &ncid), NC_NOERR);
  ASSERT_EQ(nc_redef(ncid), NC_NOERR);
  const int all_int64_api = 0x8000 | 0x4000 | 0x2000 | 0x1000;  // EX_ALL_INT64_API
  ASSERT_EQ(nc_put_att_int(ncid, NC_GLOBAL, "int64_status", NC_INT, 1, &all_int64_api), NC_NOERR);
  ASSERT_EQ(nc_enddef(ncid), NC_NOERR);
  ASSERT_EQ(nc_close(ncid), NC_NOERR);
  const Mesh read = readExodusMesh(path);
  ASSERT_EQ(read.numElements(), mesh.numElements());
  ASSERT_EQ(read.blocks.size(), mesh.blocks.size());
  EXPECT_EQ(read.blocks[0].id, mesh.blocks[0].id);
  for (int e = 0; e < mesh.numElements(); ++e)
    for (int a = 0; a < mesh.nodesPerElement(); ++a)
      ASSERT_EQ(read.connectivity(e, a), mesh.connectivity(e, a)) << "element " << e;
}

}  // namespace
}  // namespace argine
