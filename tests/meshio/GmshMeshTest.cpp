// [Meshio] gmsh meshes (issue P10): MSH 4.1 files written by gmsh 4.8 (tests/meshio/gmsh/,
// from two_layers.geo) become Meshes whose blocks, side sets and node sets are the physical
// groups, the same from ASCII and binary files and after a round trip through Exodus; and
// every kind of file argine cannot use is refused with an InputError naming the file and
// the problem.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iterator>
#include <set>
#include <string>
#include <vector>

#include "argine/core/Error.hpp"
#include "argine/mesh/MeshGeometry.hpp"
#include "argine/meshio/ExodusMesh.hpp"
#include "argine/meshio/GmshMesh.hpp"

namespace argine {
namespace {

std::string dataFile(const std::string& name) {
  return std::string(ARGINE_SOURCE_DIR) + "/tests/meshio/gmsh/" + name;
}

std::string bytesOf(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

Real elementArea(const Mesh& mesh, int e) {
  const int nv = mesh.nodesPerElement();
  Real twice = 0;
  for (int k = 0; k < nv; ++k) {
    const int a = mesh.connectivity(e, k), b = mesh.connectivity(e, (k + 1) % nv);
    twice += mesh.coordinates(a, 0) * mesh.coordinates(b, 1) -
             mesh.coordinates(b, 0) * mesh.coordinates(a, 1);
  }
  return twice / 2;
}

Real blockArea(const Mesh& mesh, const std::string& name) {
  Real area = 0;
  for (int e : mesh.findBlock(name)->elements) area += elementArea(mesh, e);
  return area;
}

/// The two end nodes of side `s` of element `e`, counter-clockwise.
std::array<int, 2> sideNodes(const Mesh& mesh, int e, int s) {
  return {mesh.connectivity(e, s), mesh.connectivity(e, (s + 1) % mesh.nodesPerElement())};
}

void expectTwoLayers(const Mesh& mesh, ElementType type) {
  EXPECT_EQ(mesh.type, type);
  ASSERT_EQ(mesh.blockNames(), (std::vector<std::string>{"clay", "sand"}));
  EXPECT_EQ(mesh.blocks[0].id, 1);
  EXPECT_EQ(mesh.blocks[1].id, 2);
  // Every element counter-clockwise, each layer 1 m x 1 m, the clay left of x = 1.
  for (int e = 0; e < mesh.numElements(); ++e) EXPECT_GT(elementArea(mesh, e), 0) << e;
  EXPECT_NEAR(blockArea(mesh, "clay"), 1.0, 1e-12);
  EXPECT_NEAR(blockArea(mesh, "sand"), 1.0, 1e-12);
  for (int e : mesh.findBlock("clay")->elements)
    for (int k = 0; k < mesh.nodesPerElement(); ++k)
      EXPECT_LE(mesh.coordinates(mesh.connectivity(e, k), 0), 1.0 + 1e-12);
  ASSERT_EQ(mesh.sideSetNames(), (std::vector<std::string>{"base", "interface"}));
  ASSERT_EQ(mesh.nodeSetNames(), (std::vector<std::string>{"base", "interface", "corner"}));
  // base: the bottom's sides, 2 m in all, and its nodes, all on y = 0.
  const SideSet& base = *mesh.findSideSet("base");
  Real length = 0;
  for (std::size_t i = 0; i < base.elements.size(); ++i) {
    const auto [a, b] = sideNodes(mesh, base.elements[i], base.sides[i]);
    EXPECT_EQ(mesh.coordinates(a, 1), 0.0);
    EXPECT_EQ(mesh.coordinates(b, 1), 0.0);
    length += std::abs(mesh.coordinates(b, 0) - mesh.coordinates(a, 0));
  }
  EXPECT_NEAR(length, 2.0, 1e-12);
  const NodeSet& base_nodes = *mesh.findNodeSet("base");
  EXPECT_EQ(base_nodes.nodes.size(), base.elements.size() + 1);
  for (int n : base_nodes.nodes) EXPECT_EQ(mesh.coordinates(n, 1), 0.0);
  // interface: inside the mesh, oriented upwards (5 -> 6), so the sides of the elements on
  // its left, the clay's, running upwards along x = 1.
  const SideSet& interface = *mesh.findSideSet("interface");
  length = 0;
  for (std::size_t i = 0; i < interface.elements.size(); ++i) {
    EXPECT_EQ(mesh.element_block(interface.elements[i]), 0) << "a sand element";
    const auto [a, b] = sideNodes(mesh, interface.elements[i], interface.sides[i]);
    EXPECT_NEAR(mesh.coordinates(a, 0), 1.0, 1e-12);
    EXPECT_NEAR(mesh.coordinates(b, 0), 1.0, 1e-12);
    EXPECT_GT(mesh.coordinates(b, 1), mesh.coordinates(a, 1));
    length += mesh.coordinates(b, 1) - mesh.coordinates(a, 1);
  }
  EXPECT_NEAR(length, 1.0, 1e-12);
  const NodeSet& corner = *mesh.findNodeSet("corner");
  ASSERT_EQ(corner.nodes.size(), 1u);
  EXPECT_EQ(mesh.coordinates(corner.nodes[0], 0), 0.0);
  EXPECT_EQ(mesh.coordinates(corner.nodes[0], 1), 0.0);
  EXPECT_NO_THROW(checkMeshQuality(mesh, "two layers"));
}

/// `tolerance`: gmsh prints 16 significant digits in ASCII files, binary files have all 17.
void expectSameMesh(const Mesh& a, const Mesh& b, Real tolerance = 0) {
  ASSERT_EQ(a.numNodes(), b.numNodes());
  ASSERT_EQ(a.numElements(), b.numElements());
  for (int n = 0; n < a.numNodes(); ++n)
    for (int d = 0; d < kDim; ++d) EXPECT_NEAR(a.coordinates(n, d), b.coordinates(n, d), tolerance);
  for (int e = 0; e < a.numElements(); ++e)
    for (int k = 0; k < a.nodesPerElement(); ++k)
      EXPECT_EQ(a.connectivity(e, k), b.connectivity(e, k));
  ASSERT_EQ(a.side_sets.size(), b.side_sets.size());
  for (std::size_t s = 0; s < a.side_sets.size(); ++s) {
    EXPECT_EQ(a.side_sets[s].elements, b.side_sets[s].elements);
    EXPECT_EQ(a.side_sets[s].sides, b.side_sets[s].sides);
  }
  ASSERT_EQ(a.node_sets.size(), b.node_sets.size());
  for (std::size_t s = 0; s < a.node_sets.size(); ++s)
    EXPECT_EQ(a.node_sets[s].nodes, b.node_sets[s].nodes);
}

TEST(GmshMesh, PhysicalGroupsBecomeBlocksSideSetsAndNodeSets) {
  expectTwoLayers(readGmshMesh(dataFile("two_layers.msh")), ElementType::Tri3);
  expectTwoLayers(readGmshMesh(dataFile("two_layers_quad4.msh")), ElementType::Quad4);
}

TEST(GmshMesh, BinaryAndAsciiFilesGiveTheSameMesh) {
  const Mesh ascii = readGmshMesh(dataFile("two_layers.msh"));
  const Mesh binary = readGmshMesh(dataFile("two_layers_binary.msh"));
  expectSameMesh(ascii, binary, 1e-15);
  EXPECT_TRUE(parseGmshFile("x", bytesOf(dataFile("two_layers_binary.msh"))).binary);
}

TEST(GmshMesh, ExodusRoundTripKeepsEverything) {
  const Mesh mesh = readGmshMesh(dataFile("two_layers_quad4.msh"));
  const std::string path = std::string(ARGINE_BINARY_DIR) + "/tests/meshio_gmsh_two_layers.exo";
  writeExodusMesh(path, mesh);
  const Mesh again = readExodusMesh(path);
  expectSameMesh(mesh, again);
  EXPECT_EQ(again.blockNames(), mesh.blockNames());
  EXPECT_EQ(again.sideSetNames(), mesh.sideSetNames());
  EXPECT_EQ(again.nodeSetNames(), mesh.nodeSetNames());
}

// A unit square of two triangles, surface 1 in physical surface 2 "soil", curve 1 (the
// bottom, 1 -> 2) in physical curve 1 "base"; `replace` edits it into hostile variants.
const std::string kSquare = R"($MeshFormat
4.1 0 8
$EndMeshFormat
$PhysicalNames
2
1 1 "base"
2 2 "soil"
$EndPhysicalNames
$Entities
0 1 1 0
1 0 0 0 1 0 0 1 1 0
1 0 0 0 1 1 0 1 2 0
$EndEntities
$Nodes
1 4 1 4
2 1 0 4
1
2
3
4
0 0 0
1 0 0
1 1 0
0 1 0
$EndNodes
$Elements
2 3 1 3
1 1 1 1
1 1 2
2 1 2 2
2 1 2 3
3 1 3 4
$EndElements
)";

std::string replaced(const std::string& text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  std::string result = text;
  return at == std::string::npos ? result : result.replace(at, from.size(), to);
}

void expectRefused(const std::string& bytes, const std::string& expected) {
  try {
    (void)gmshMesh("hostile.msh", parseGmshFile("hostile.msh", bytes));
    ADD_FAILURE() << "accepted; expected: " << expected;
  } catch (const InputError& error) {
    EXPECT_EQ(error.where(), "hostile.msh");
    EXPECT_NE(std::string(error.what()).find(expected), std::string::npos) << error.what();
  }
}

TEST(GmshMesh, TheSmallSquareReads) {
  const Mesh mesh = gmshMesh("square.msh", parseGmshFile("square.msh", kSquare));
  EXPECT_EQ(mesh.numNodes(), 4);
  EXPECT_EQ(mesh.numElements(), 2);
  EXPECT_EQ(mesh.findSideSet("base")->elements, (std::vector<int>{0}));
  EXPECT_EQ(mesh.findSideSet("base")->sides, (std::vector<int>{0}));
  // Clockwise triangles are made counter-clockwise, their sides found all the same.
  const Mesh flipped = gmshMesh(
      "square.msh",
      parseGmshFile("square.msh", replaced(kSquare, "2 1 2 3\n3 1 3 4", "2 1 3 2\n3 1 4 3")));
  EXPECT_GT(elementArea(flipped, 0), 0);
  const auto [a, b] = sideNodes(flipped, flipped.findSideSet("base")->elements[0],
                                flipped.findSideSet("base")->sides[0]);
  EXPECT_EQ(a, 0);
  EXPECT_EQ(b, 1);
}

TEST(GmshMesh, FilesArgineCannotUseAreRefusedWithTheReason) {
  expectRefused("", "the file is empty");
  expectRefused("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n", "MSH version 2.2; argine reads MSH 4.1");
  expectRefused("solid cube\n", "not a gmsh MSH file");
  expectRefused(kSquare.substr(0, kSquare.size() / 2), "the file ends inside");
  expectRefused(replaced(kSquare, "1 4 1 4\n", "1 4000000 1 4\n"),
                "more than the rest of the file");
  expectRefused(replaced(kSquare, "2 3 1 3\n", "2 4 1 3\n"), "the blocks hold 3 elements");
  expectRefused(replaced(kSquare, "$EndNodes", "$EndNotes"), "$Nodes does not end with $EndNodes");
  expectRefused(
      replaced(kSquare, "$Nodes", "$PartitionedEntities\n$EndPartitionedEntities\n$Nodes"),
      "a partitioned mesh");
  // Element types.
  expectRefused(replaced(replaced(kSquare, "2 3 1 3\n", "2 2 1 2\n"), "2 1 2 2\n2 1 2 3\n3 1 3 4",
                         "2 1 9 1\n2 1 2 3 1 2 3"),
                "6-node second-order triangle elements; argine takes 3-node triangles");
  expectRefused(replaced(kSquare, "2 1 2 2", "2 1 77 2"), "type 77");
  expectRefused(replaced(replaced(replaced(kSquare, "0 1 1 0\n", "0 1 1 1\n"), "$EndEntities",
                                  "1 0 0 0 1 1 1 0 0\n$EndEntities"),
                         "2 3 1 3\n", "3 4 1 4\n3 1 4 1\n4 1 2 3 4\n"),
                "a 3D mesh");
  // Physical groups.
  expectRefused(replaced(kSquare, "2 2 \"soil\"", "2 3 \"soil\""),
                "physical surface 2 has no name");
  expectRefused(replaced(kSquare, "1 1 \"base\"", "1 5 \"base\""), "physical curve 1 has no name");
  expectRefused(replaced(kSquare, "1 0 0 0 1 1 0 1 2 0", "1 0 0 0 1 1 0 0 0"),
                "surface 1 (2 elements) is in no physical surface");
  expectRefused(replaced(replaced(kSquare, "1 0 0 0 1 1 0 1 2 0", "1 0 0 0 1 1 0 2 2 7 0"),
                         "2\n1 1", "3\n2 7 \"clay\"\n1 1"),
                "surface 1 is in physical surfaces 'soil' and 'clay'");
  expectRefused(replaced(kSquare, "2 3 1 3\n1 1 1 1\n1 1 2\n2 1 2 2\n2 1 2 3\n3 1 3 4\n",
                         "1 1 1 1\n1 1 1 1\n1 1 2\n"),
                "no surface elements in physical surfaces");
  // Geometry and references.
  expectRefused(replaced(kSquare, "1 1 0\n0 1 0", "1 1 0.5\n0 1 0"),
                "not a plane mesh in the xy plane");
  expectRefused(replaced(kSquare, "3 1 3 4", "3 1 3 9"), "refers to node 9, which $Nodes lacks");
  expectRefused(replaced(kSquare, "1 1 2\n", "1 2 4\n"),
                "physical curve 'base': its segment from node 2 to node 4 is not an element side");
  expectRefused(replaced(kSquare, "2 1 2 3\n3 1 3 4", "2 1 2 3\n3 1 3 1"), "zero area");
}

TEST(GmshMesh, GeoFilesAreMeshedByGmshWhenInstalled) {
  if (std::system("command -v gmsh > /dev/null 2>&1") != 0)
    GTEST_SKIP() << "gmsh is not installed (apt-get install gmsh)";
  const Mesh mesh = loadGmshMesh(dataFile("two_layers.geo"));
  expectTwoLayers(mesh, ElementType::Tri3);
}

TEST(GmshMesh, TheLeveeSceneMeshIsWhatItsGeoFileMakes) {
  if (std::system("command -v gmsh > /dev/null 2>&1") != 0)
    GTEST_SKIP() << "gmsh is not installed (apt-get install gmsh)";
  const std::string scene = std::string(ARGINE_SOURCE_DIR) + "/inputs/levee_layered/levee_layered";
  const Mesh committed = readGmshMesh(scene + ".msh");
  const Mesh meshed = loadGmshMesh(scene + ".geo");
  expectSameMesh(committed, meshed, 1e-12);
  EXPECT_EQ(committed.blockNames(), meshed.blockNames());
  EXPECT_EQ(committed.sideSetNames(), meshed.sideSetNames());
}

TEST(GmshMesh, AGeoFileWithoutGmshSaysWhatToDo) {
  const char* saved = std::getenv("ARGINE_GMSH");
  setenv("ARGINE_GMSH", "/nonexistent/gmsh", 1);
  try {
    (void)loadGmshMesh(dataFile("two_layers.geo"));
    ADD_FAILURE() << "meshed with a gmsh that does not exist";
  } catch (const InputError& error) {
    EXPECT_EQ(error.where(), dataFile("two_layers.geo"));
    EXPECT_NE(std::string(error.what()).find("could not mesh it"), std::string::npos)
        << error.what();
  }
  if (saved)
    setenv("ARGINE_GMSH", saved, 1);
  else
    unsetenv("ARGINE_GMSH");
}

}  // namespace
}  // namespace argine
