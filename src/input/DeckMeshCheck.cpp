// The deck against the mesh: every block and set a deck names must exist.
#include <algorithm>

#include "DeckParts.hpp"
#include "ValueText.hpp"
#include "argine/core/Error.hpp"
#include "argine/input/DeckReader.hpp"

namespace argine {

namespace {

/// "mesh has no node set 'bottm'; did you mean 'bottom'? The mesh has node sets: a, b".
std::string absentMessage(const std::string& what, const std::string& name,
                          const std::vector<std::string>& available) {
  std::string message = "the mesh has no " + what + " '" + name + "'";
  const std::string suggestion = closestMatch(name, available);
  message += suggestion.empty() ? "." : "; did you mean '" + suggestion + "'?";
  message += available.empty()
                 ? " The mesh has no " + what + "s."
                 : " The mesh has " + what + "s: " + input_detail::joinWords(available);
  return message;
}

/// In a rectangle with Regions, the region blocks (those a material may fill).
std::vector<std::string> regionBlockNames(const Mesh& mesh) {
  std::vector<std::string> names;
  for (const BlockRegion& region : mesh.regions) {
    const std::string& name = mesh.blocks[region.block].name;
    if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
  }
  return names;
}

}  // namespace

void checkDeckAgainstMesh(const Deck& deck, const Mesh& mesh) {
  const std::vector<std::string> region_blocks = regionBlockNames(mesh);
  for (const MaterialSpec& material : deck.materials) {
    const std::string where = "Materials/" + material.name + "/Block";
    if (!mesh.findBlock(material.block))
      throw InputError(where, absentMessage("element block", material.block, mesh.blockNames()));
    // Region points are seeded in every element a region touches, so whole elements of the
    // rest of the box would hold a second material beside them.
    if (!region_blocks.empty() && std::find(region_blocks.begin(), region_blocks.end(),
                                            material.block) == region_blocks.end())
      throw InputError(where, "block '" + material.block +
                                  "' is the part of the box outside the regions; in a rectangle "
                                  "with Regions a material fills a region: " +
                                  input_detail::joinWords(region_blocks));
  }
  input_detail::checkOneMaterialPerBlock(deck);
  for (const StageSpec& stage : deck.stages) {
    for (const BoundarySpec& boundary : stage.boundaries) {
      const std::string path = "Stages/" + stage.name + "/Boundary Conditions/" + boundary.name;
      if (!boundary.node_set.empty() && !mesh.findNodeSet(boundary.node_set))
        throw InputError(path + "/Node Set",
                         absentMessage("node set", boundary.node_set, mesh.nodeSetNames()));
      if (!boundary.side_set.empty() && !mesh.findSideSet(boundary.side_set))
        throw InputError(path + "/Side Set",
                         absentMessage("side set", boundary.side_set, mesh.sideSetNames()));
    }
  }
}

}  // namespace argine
