// The deck against a small hand-built mesh: names the deck uses must exist in the mesh.
#include "DeckTestSupport.hpp"

namespace argine::test {

namespace {

/// A mesh with only names (no nodes): blocks soil and clay, node sets bottom and left,
/// side set top.
Mesh namedMesh() {
  Mesh mesh;
  mesh.blocks = {ElementBlock{"soil", 1, {}}, ElementBlock{"clay", 2, {}}};
  mesh.node_sets = {NodeSet{"bottom", 1, {}}, NodeSet{"left", 2, {}}};
  mesh.side_sets = {SideSet{"top", 1, {}, {}}};
  return mesh;
}

}  // namespace

TEST(DeckMeshCheck, MatchingMeshPasses) {
  EXPECT_NO_THROW(checkDeckAgainstMesh(parseText(kBaseDeck), namedMesh()));
}

TEST(DeckMeshCheck, MissingBlockListsTheMeshBlocks) {
  const Deck deck = parseText(replaced(kBaseDeck, "Block: soil", "Block: sand"));
  expectInputError([&] { checkDeckAgainstMesh(deck, namedMesh()); }, "Materials/soil/Block",
                   "the mesh has no element block 'sand'. The mesh has element blocks: soil, clay");
  const Deck typo = parseText(replaced(kBaseDeck, "Block: soil", "Block: sol"));
  expectInputError([&] { checkDeckAgainstMesh(typo, namedMesh()); }, "Materials/soil/Block",
                   "no element block 'sol'; did you mean 'soil'?");
}

TEST(DeckMeshCheck, MissingNodeSetSuggestsAndLists) {
  const Deck deck = parseText(replaced(kBaseDeck, "Node Set: bottom", "Node Set: botom"));
  expectInputError([&] { checkDeckAgainstMesh(deck, namedMesh()); },
                   "Stages/load/Boundary Conditions/base/Node Set",
                   "no node set 'botom'; did you mean 'bottom'? The mesh has node sets: bottom, "
                   "left");
}

TEST(DeckMeshCheck, MissingSideSet) {
  const Deck deck = parseText(
      replaced(kBaseDeck, "base: {Type: solid fixity, Node Set: bottom, Direction: both}",
               "base: {Type: solid fixity, Node Set: bottom, Direction: both}\n"
               "        drained: {Type: liquid pressure, Side Set: right, Pressure (Pa): 0.0}"));
  expectInputError([&] { checkDeckAgainstMesh(deck, namedMesh()); },
                   "Stages/load/Boundary Conditions/drained/Side Set",
                   "the mesh has no side set 'right'. The mesh has side sets: top");
  Mesh bare = namedMesh();
  bare.side_sets.clear();
  expectInputError([&] { checkDeckAgainstMesh(deck, bare); },
                   "Stages/load/Boundary Conditions/drained/Side Set",
                   "The mesh has no side sets.");
}

TEST(DeckMeshCheck, TwoMaterialsOnOneBlock) {
  Deck deck = parseText(kBaseDeck);  // built in code: the reader would have caught it
  MaterialSpec second = deck.materials[0];
  second.name = "other";
  deck.materials.push_back(second);
  expectInputError([&] { checkDeckAgainstMesh(deck, namedMesh()); }, "Materials/other/Block",
                   "block 'soil' already holds material 'soil'");
}

}  // namespace argine::test
