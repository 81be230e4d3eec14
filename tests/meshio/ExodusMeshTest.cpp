#include <exodusII.h>
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "argine/core/Error.hpp"
#include "argine/meshio/ExodusMesh.hpp"

namespace argine {
namespace {

std::string scratchFile(const std::string& name) {
  return std::string(ARGINE_BINARY_DIR) + "/tests/meshio_" + name;
}

/// A mesh from plain lists; connectivity is stored as given (not reoriented).
Mesh makeMesh(ElementType type, const std::vector<std::array<double, 2>>& nodes,
              const std::vector<std::vector<int>>& elements,
              const std::vector<ElementBlock>& blocks) {
  Mesh mesh;
  mesh.type = type;
  const int nv = nodesPerElement(type);
  mesh.coordinates = Kokkos::View<Real* [kDim], MemSpace>("x", nodes.size());
  mesh.connectivity = Kokkos::View<int**, MemSpace>("conn", elements.size(), nv);
  mesh.element_block = Kokkos::View<int*, MemSpace>("block", elements.size());
  for (std::size_t n = 0; n < nodes.size(); ++n) {
    mesh.coordinates(n, 0) = nodes[n][0];
    mesh.coordinates(n, 1) = nodes[n][1];
  }
  for (std::size_t e = 0; e < elements.size(); ++e)
    for (int k = 0; k < nv; ++k) mesh.connectivity(e, k) = elements[e][k];
  mesh.blocks = blocks;
  for (std::size_t b = 0; b < blocks.size(); ++b)
    for (int e : blocks[b].elements) mesh.element_block(e) = static_cast<int>(b);
  return mesh;
}

/// Two unit quads side by side, one block each (and an empty block), with node and side
/// sets (one of them empty).
///   3---4---5
///   | 0 | 1 |
///   0---1---2
Mesh twoQuads() {
  Mesh mesh = makeMesh(
      ElementType::Quad4, {{0, 0}, {1, 0}, {2, 0}, {0, 1}, {1, 1}, {2, 1}},
      {{0, 1, 4, 3}, {1, 2, 5, 4}},
      {{"clay", 3, {0}}, {"a_block_name_longer_than_32_characters", 7, {1}}, {"unused", 8, {}}});
  mesh.node_sets = {{"base", 1, {0, 1, 2}}, {"left", 2, {0, 3}}};
  mesh.side_sets = {{"base", 4, {0, 1}, {0, 0}}, {"riverside", 5, {1}, {1}}, {"none", 6, {}, {}}};
  return mesh;
}

void expectSameMesh(const Mesh& a, const Mesh& b) {
  EXPECT_EQ(a.type, b.type);
  ASSERT_EQ(a.numNodes(), b.numNodes());
  ASSERT_EQ(a.numElements(), b.numElements());
  for (int n = 0; n < a.numNodes(); ++n)
    for (int d = 0; d < kDim; ++d) EXPECT_EQ(a.coordinates(n, d), b.coordinates(n, d));
  for (int e = 0; e < a.numElements(); ++e) {
    EXPECT_EQ(a.element_block(e), b.element_block(e));
    for (int k = 0; k < a.nodesPerElement(); ++k)
      EXPECT_EQ(a.connectivity(e, k), b.connectivity(e, k));
  }
  ASSERT_EQ(a.blocks.size(), b.blocks.size());
  for (std::size_t i = 0; i < a.blocks.size(); ++i) {
    EXPECT_EQ(a.blocks[i].name, b.blocks[i].name);
    EXPECT_EQ(a.blocks[i].id, b.blocks[i].id);
    EXPECT_EQ(a.blocks[i].elements, b.blocks[i].elements);
  }
  ASSERT_EQ(a.node_sets.size(), b.node_sets.size());
  for (std::size_t i = 0; i < a.node_sets.size(); ++i) {
    EXPECT_EQ(a.node_sets[i].name, b.node_sets[i].name);
    EXPECT_EQ(a.node_sets[i].id, b.node_sets[i].id);
    EXPECT_EQ(a.node_sets[i].nodes, b.node_sets[i].nodes);
  }
  ASSERT_EQ(a.side_sets.size(), b.side_sets.size());
  for (std::size_t i = 0; i < a.side_sets.size(); ++i) {
    EXPECT_EQ(a.side_sets[i].name, b.side_sets[i].name);
    EXPECT_EQ(a.side_sets[i].id, b.side_sets[i].id);
    EXPECT_EQ(a.side_sets[i].elements, b.side_sets[i].elements);
    EXPECT_EQ(a.side_sets[i].sides, b.side_sets[i].sides);
  }
}

/// Writes a file with the raw exodus API: blocks of the given types over a unit square.
void writeRawFile(const std::string& path, int dims, const std::vector<std::string>& types) {
  int comp_ws = 8, io_ws = 8;
  const int exoid = ex_create(path.c_str(), EX_CLOBBER, &comp_ws, &io_ws);
  ASSERT_GE(exoid, 0);
  const int num_blocks = static_cast<int>(types.size());
  ASSERT_EQ(ex_put_init(exoid, "raw", dims, 5, num_blocks, num_blocks, 0, 0), 0);
  std::vector<double> x{0, 1, 1, 0, 2}, y{0, 0, 1, 1, 0}, z(5, 0.0);
  ASSERT_EQ(ex_put_coord(exoid, x.data(), y.data(), dims == 3 ? z.data() : nullptr), 0);
  for (int b = 0; b < num_blocks; ++b) {
    const bool tri = types[b][0] == 'T' || types[b][0] == 't';
    ASSERT_EQ(ex_put_block(exoid, EX_ELEM_BLOCK, b + 10, types[b].c_str(), 1, tri ? 3 : 4, 0, 0, 0),
              0);
    std::vector<int> conn = tri ? std::vector<int>{2, 5, 3} : std::vector<int>{1, 2, 3, 4};
    ASSERT_EQ(ex_put_conn(exoid, EX_ELEM_BLOCK, b + 10, conn.data(), nullptr, nullptr), 0);
  }
  ex_close(exoid);
}

TEST(ExodusMesh, QuadMeshRoundTripKeepsEverything) {
  const Mesh mesh = twoQuads();
  const std::string path = scratchFile("two_quads.e");
  writeExodusMesh(path, mesh, "two quads");
  EXPECT_FALSE(std::ifstream(path + ".tmp").good());  // renamed, not left behind
  expectSameMesh(mesh, readExodusMesh(path));
}

TEST(ExodusMesh, TriangleMeshRoundTripAndUnnamedSetsGetDefaultNames) {
  // Unit square split along 0-2; empty names are written as "" and read back as defaults.
  Mesh mesh = makeMesh(ElementType::Tri3, {{0, 0}, {1, 0}, {1, 1}, {0, 1}}, {{0, 1, 2}, {0, 2, 3}},
                       {{"soil", 1, {0, 1}}});
  mesh.node_sets = {{"", 9, {3, 2}}};
  mesh.side_sets = {{"", 4, {1, 0}, {1, 1}}};
  const std::string path = scratchFile("two_triangles.e");
  writeExodusMesh(path, mesh);
  const Mesh read = readExodusMesh(path);
  mesh.node_sets[0].name = "nodelist_9";
  mesh.side_sets[0].name = "surface_4";
  expectSameMesh(mesh, read);
}

TEST(ExodusMesh, BlocksAreWrittenInBlockOrder) {
  // Block "b" lists element 1 first, so the file numbers element 1 before element 0.
  Mesh mesh = makeMesh(ElementType::Quad4, {{0, 0}, {1, 0}, {2, 0}, {0, 1}, {1, 1}, {2, 1}},
                       {{0, 1, 4, 3}, {1, 2, 5, 4}}, {{"b", 1, {1, 0}}});
  mesh.side_sets = {{"right", 1, {1}, {1}}};
  EXPECT_EQ(exodusElementOrder(mesh), (std::vector<int>{1, 0}));
  const std::string path = scratchFile("reordered.e");
  writeExodusMesh(path, mesh);
  const Mesh read = readExodusMesh(path);
  ASSERT_EQ(read.numElements(), 2);
  EXPECT_EQ(read.connectivity(0, 0), 1);  // file element 1 = mesh element 1 (nodes 1 2 5 4)
  EXPECT_EQ(read.connectivity(1, 0), 0);
  EXPECT_EQ(read.side_sets[0].elements, std::vector<int>{0});  // still the right-hand quad
  EXPECT_EQ(read.side_sets[0].sides, std::vector<int>{1});
}

TEST(ExodusMesh, ClockwiseElementsAreReorderedWithTheirSides) {
  // Quad 0 given clockwise (0 3 4 1); its side 0 joins nodes 0-3 (the left edge).
  // Counter-clockwise it becomes (0 1 4 3), where the left edge 3-0 is side 3.
  // Triangle case below: (0 2 1) -> (0 1 2); side 2 (1-0, the base) -> side 0.
  Mesh quads = makeMesh(ElementType::Quad4, {{0, 0}, {1, 0}, {2, 0}, {0, 1}, {1, 1}, {2, 1}},
                        {{0, 3, 4, 1}, {1, 2, 5, 4}}, {{"soil", 1, {0, 1}}});
  quads.side_sets = {{"left", 1, {0}, {0}}};
  const std::string path = scratchFile("clockwise.e");
  writeExodusMesh(path, quads);
  const Mesh read = readExodusMesh(path);
  EXPECT_EQ(read.connectivity(0, 0), 0);
  EXPECT_EQ(read.connectivity(0, 1), 1);
  EXPECT_EQ(read.connectivity(0, 2), 4);
  EXPECT_EQ(read.connectivity(0, 3), 3);
  EXPECT_EQ(read.side_sets[0].sides, std::vector<int>{3});
  EXPECT_EQ(read.connectivity(1, 1), 2);  // the counter-clockwise quad is untouched

  Mesh tri = makeMesh(ElementType::Tri3, {{0, 0}, {1, 0}, {0, 1}}, {{0, 2, 1}}, {{"s", 1, {0}}});
  tri.side_sets = {{"base", 1, {0}, {2}}};
  writeExodusMesh(path, tri);
  const Mesh read_tri = readExodusMesh(path);
  EXPECT_EQ(read_tri.connectivity(0, 1), 1);
  EXPECT_EQ(read_tri.connectivity(0, 2), 2);
  EXPECT_EQ(read_tri.side_sets[0].sides, std::vector<int>{0});
}

TEST(ExodusMesh, MissingFileIsAnInputErrorNamingTheFile) {
  const std::string path = scratchFile("does_not_exist.e");
  try {
    readExodusMesh(path);
    FAIL() << "expected an InputError";
  } catch (const InputError& error) {
    EXPECT_EQ(error.where(), path);
  }
}

TEST(ExodusMesh, TextFileIsAnInputError) {
  const std::string path = scratchFile("not_exodus.e");
  std::ofstream(path) << "this is not a netCDF file\n";
  try {
    readExodusMesh(path);
    FAIL() << "expected an InputError";
  } catch (const InputError& error) {
    EXPECT_EQ(error.where(), path);
  }
}

TEST(ExodusMesh, ThreeDimensionalFileIsRejected) {
  const std::string path = scratchFile("three_d.e");
  writeRawFile(path, 3, {"QUAD4"});
  try {
    readExodusMesh(path);
    FAIL() << "expected an InputError";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("only 2D meshes are supported"), std::string::npos)
        << error.what();
  }
}

TEST(ExodusMesh, MixedElementTypesAreRejectedNamingBothBlocks) {
  const std::string path = scratchFile("mixed.e");
  writeRawFile(path, 2, {"QUAD", "TRI3"});
  try {
    readExodusMesh(path);
    FAIL() << "expected an InputError";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what())
                  .find("mixed element types are not supported: block block_10 is QUAD4, "
                        "block block_11 is TRI3"),
              std::string::npos)
        << error.what();
  }
}

TEST(ExodusMesh, AlternativeTypeNamesAreAccepted) {
  const std::string path = scratchFile("triangle.e");
  writeRawFile(path, 2, {"TRIANGLE", "tri"});
  const Mesh mesh = readExodusMesh(path);
  EXPECT_EQ(mesh.type, ElementType::Tri3);
  EXPECT_EQ(mesh.numElements(), 2);
  writeRawFile(path, 2, {"SHELL4"});
  EXPECT_THROW(readExodusMesh(path), InputError);
}

TEST(ExodusMesh, ZeroAreaElementIsRejectedNamingElementAndBlock) {
  // Second triangle has three collinear nodes.
  Mesh mesh = makeMesh(ElementType::Tri3, {{0, 0}, {1, 0}, {0, 1}, {2, 0}}, {{0, 1, 2}, {0, 1, 3}},
                       {{"levee", 1, {0, 1}}});
  const std::string path = scratchFile("degenerate.e");
  writeExodusMesh(path, mesh);
  try {
    readExodusMesh(path);
    FAIL() << "expected an InputError";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("element 2 (block levee) has zero area"),
              std::string::npos)
        << error.what();
  }
}

TEST(ExodusMesh, NonConvexQuadIsRejected) {
  // Node 2 at (0.2, 0.2) makes a reflex corner although the quad's area is positive.
  Mesh mesh = makeMesh(ElementType::Quad4, {{0, 0}, {1, 0}, {0.2, 0.2}, {0, 1}}, {{0, 1, 2, 3}},
                       {{"q", 1, {0}}});
  const std::string path = scratchFile("reflex.e");
  writeExodusMesh(path, mesh);
  EXPECT_THROW(readExodusMesh(path), InputError);
}

TEST(ExodusMesh, UnwritableDirectoryIsAnInputError) {
  EXPECT_THROW(writeExodusMesh("/nonexistent_directory/mesh.e", twoQuads()), InputError);
}

}  // namespace
}  // namespace argine
