// libFuzzer target: the bytes are a gmsh MSH file (ASCII or binary). The reader, the mesh
// built from its physical groups and the mesh quality check must either return a mesh or
// throw an InputError naming the file; crashes, hangs, other exceptions and sanitizer
// reports are findings. Seeds are small meshes written by gmsh (fuzz/corpus/gmsh).
#include <string>

#include "FuzzSupport.hpp"
#include "argine/mesh/MeshGeometry.hpp"
#include "argine/meshio/GmshMesh.hpp"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  argine::fuzz::startKokkos();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const unsigned char* data, std::size_t size) {
  const std::string path = "fuzzed.msh";
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  try {
    const argine::Mesh mesh = argine::gmshMesh(path, argine::parseGmshFile(path, bytes));
    argine::checkMeshQuality(mesh, path);
  } catch (const argine::InputError& error) {
    argine::fuzz::checkInputError(error);
  }
  return 0;
}
