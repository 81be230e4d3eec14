#include "argine/mesh/MeshFolds.hpp"

#include <sstream>
#include <unordered_map>

#include "argine/core/Error.hpp"

namespace argine {

namespace {

std::string elementText(const Mesh& mesh, const Kokkos::View<int*, Kokkos::HostSpace>& block,
                        int e) {
  const int b = e < static_cast<int>(block.extent(0)) ? block(e) : -1;
  const bool named = b >= 0 && b < static_cast<int>(mesh.blocks.size());
  return "element " + std::to_string(e + 1) + " (block " +
         (named ? mesh.blocks[static_cast<std::size_t>(b)].name : std::string("?")) + ")";
}

}  // namespace

void checkNoFoldedElements(const Mesh& mesh, const std::string& source) {
  const int elements = mesh.numElements(), per = mesh.nodesPerElement();
  const long long nodes = mesh.numNodes();
  const auto connectivity =
      Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), mesh.connectivity);
  const auto block = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), mesh.element_block);
  std::unordered_map<long long, int> runs;  // directed side (from * nodes + to) -> element
  runs.reserve(static_cast<std::size_t>(elements) * per);
  for (int e = 0; e < elements; ++e)
    for (int a = 0; a < per; ++a) {
      const long long from = connectivity(e, a), to = connectivity(e, (a + 1) % per);
      const auto [at, first] = runs.emplace(from * nodes + to, e);
      if (first) continue;
      std::ostringstream out;
      out << elementText(mesh, block, at->second) << " and " << elementText(mesh, block, e)
          << " both run their side from node " << from + 1 << " to node " << to + 1
          << " in the same direction, so they overlap: one of them is inverted relative to "
             "its neighbour (a node on the wrong side, or listed clockwise among "
             "counter-clockwise elements)";
      throw InputError(source, out.str());
    }
}

}  // namespace argine
