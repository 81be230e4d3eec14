#include "argine/simulation/Setup.hpp"

#include "argine/boundary/BoundaryConditions.hpp"
#include "argine/input/DeckReader.hpp"
#include "argine/mesh/MeshGeometry.hpp"
#include "argine/meshio/ExodusMesh.hpp"
#include "argine/meshio/GmshMesh.hpp"
#include "argine/meshio/MeshGenerators.hpp"
#include "argine/points/Seeding.hpp"

namespace argine {

Mesh readDeckMesh(const MeshSpec& spec) {
  if (spec.generate) return generateMesh(spec.generator);
  if (!spec.gmsh_file.empty()) return loadGmshMesh(spec.gmsh_file);
  return readExodusMesh(spec.exodus_file);
}

std::string meshSource(const MeshSpec& spec) {
  if (spec.generate) return "Mesh/Generate";
  return spec.gmsh_file.empty() ? spec.exodus_file : spec.gmsh_file;
}

Mesh loadMesh(const Deck& deck) {
  Mesh mesh = readDeckMesh(deck.mesh);
  const std::string source = meshSource(deck.mesh);
  checkMeshQuality(mesh, source);
  mesh.shape_functions = deck.mesh.shape_functions;  // checkMeshSpec: on a structured grid
  checkDeckAgainstMesh(deck, mesh);
  // Each explicit stage's conditions resolved once now, not when the stage begins: a
  // condition the mesh's geometry cannot carry (an inclined impermeable side, a frictional
  // node set without a wall normal) is then an input error before anything runs or is
  // written, and `argine check` reports it.
  for (const StageSpec& stage : deck.stages)
    if (stage.solver != SolverKind::ImplicitSeepage) StageBoundaryConditions(mesh, stage);
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
