// The deck against the mesh: every block and set a deck names must exist.
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

}  // namespace

void checkDeckAgainstMesh(const Deck& deck, const Mesh& mesh) {
  for (const MaterialSpec& material : deck.materials)
    if (!mesh.findBlock(material.block))
      throw InputError("Materials/" + material.name + "/Block",
                       absentMessage("element block", material.block, mesh.blockNames()));
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
