#include "argine/simulation/Setup.hpp"

#include "argine/input/DeckReader.hpp"
#include "argine/mesh/MeshGeometry.hpp"
#include "argine/meshio/ExodusMesh.hpp"
#include "argine/meshio/MeshGenerators.hpp"
#include "argine/points/Seeding.hpp"

namespace argine {

Mesh loadMesh(const Deck& deck) {
  Mesh mesh = deck.mesh.generate ? generateMesh(deck.mesh.generator)
                                 : readExodusMesh(deck.mesh.exodus_file);
  const std::string source = deck.mesh.generate ? "Mesh/Generate" : deck.mesh.exodus_file;
  checkMeshQuality(mesh, source);
  mesh.shape_functions = deck.mesh.shape_functions;  // checkMeshSpec: on a structured grid
  checkDeckAgainstMesh(deck, mesh);
  return mesh;
}

MaterialPoints seedPoints(const Deck& deck, const Mesh& mesh) {
  std::vector<SeedRequest> requests;
  for (std::size_t m = 0; m < deck.materials.size(); ++m) {
    const MaterialSpec& material = deck.materials[m];
    const auto block = std::distance(mesh.blocks.data(), mesh.findBlock(material.block));
    requests.push_back(SeedRequest{static_cast<int>(block), static_cast<int>(m),
                                   material.points_per_element,
                                   "Materials/" + material.name + "/Points Per Element"});
  }
  return seedMaterialPoints(mesh, requests);
}

}  // namespace argine
