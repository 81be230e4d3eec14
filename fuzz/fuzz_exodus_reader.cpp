// libFuzzer target: the bytes are an Exodus II mesh file (netCDF). readExodusMesh and the
// mesh quality check must either return a mesh or throw an InputError naming the file;
// crashes, hangs, other exceptions and sanitizer reports are findings. Seeds are small
// meshes written by argine (fuzz/corpus/exodus).
#include "FuzzSupport.hpp"
#include "argine/mesh/MeshGeometry.hpp"
#include "argine/meshio/ExodusMesh.hpp"

namespace {
std::filesystem::path mesh_path;
}

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  argine::fuzz::startKokkos();
  mesh_path = argine::fuzz::workDirectory("exodus") / "fuzzed.exo";
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const unsigned char* data, std::size_t size) {
  argine::fuzz::writeBytes(mesh_path, data, size);
  try {
    const argine::Mesh mesh = argine::readExodusMesh(mesh_path.string());
    argine::checkMeshQuality(mesh, mesh_path.string());
  } catch (const argine::InputError& error) {
    argine::fuzz::checkInputError(error);
  }
  return 0;
}
