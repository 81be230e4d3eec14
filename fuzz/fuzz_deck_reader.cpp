// libFuzzer target: the bytes are a deck file. It is read as `argine check` reads it (YAML ->
// schema validation -> Deck structs -> cross-key checks -> every time series -> the mesh it
// names, generated or read -> deck against mesh). The only allowed failure is an InputError
// with a place; crashes, hangs, other exceptions and sanitizer reports are findings.
//
// The working directory holds the files a deck may name: `gauge.csv` (a valid time series)
// and `mesh.exo` (a 2x1 quad mesh with blocks soil, node and side sets left/right/bottom/top),
// so seeds that name them get past the file checks.
#include <cmath>

#include "FuzzSupport.hpp"
#include "argine/boundary/DeckTimeSeriesCheck.hpp"
#include "argine/input/DeckReader.hpp"
#include "argine/mesh/MeshGeometry.hpp"
#include "argine/meshio/ExodusMesh.hpp"
#include "argine/meshio/MeshGenerators.hpp"

namespace {

std::filesystem::path deck_path;

/// Elements a generator would make; the fuzzer skips generating meshes larger than this
/// (argine's own limit, checked by checkDeck, is much larger and is tested by unit tests).
constexpr double kLargestFuzzedMesh = 2e4;

double generatedElements(const argine::GeneratorSpec& generator) {
  const double h = generator.element_size;
  const double nx = (generator.upper_right[0] - generator.lower_left[0]) / h;
  const double ny = (generator.upper_right[1] - generator.lower_left[1]) / h;
  return nx * ny;
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  argine::fuzz::startKokkos();
  const auto directory = argine::fuzz::workDirectory("deck");
  deck_path = directory / "deck.yaml";
  std::ofstream(directory / "gauge.csv") << "time (s), head (m)\n0, 1.0\n10, 2.0\n20, 1.5\n";
  argine::GeneratorSpec generator;
  generator.element_size = 0.5;
  generator.upper_right = {1.0, 0.5};
  argine::writeExodusMesh((directory / "mesh.exo").string(), argine::generateMesh(generator));
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const unsigned char* data, std::size_t size) {
  argine::fuzz::writeBytes(deck_path, data, size);
  try {
    const argine::Deck deck = argine::readDeck(deck_path.string());
    argine::checkDeckTimeSeries(deck);
    if (deck.mesh.generate && !(generatedElements(deck.mesh.generator) <= kLargestFuzzedMesh))
      return 0;
    const argine::Mesh mesh = deck.mesh.generate ? argine::generateMesh(deck.mesh.generator)
                                                 : argine::readExodusMesh(deck.mesh.exodus_file);
    argine::checkMeshQuality(mesh, "mesh");
    argine::checkDeckAgainstMesh(deck, mesh);
  } catch (const argine::InputError& error) {
    argine::fuzz::checkInputError(error);
  }
  return 0;
}
