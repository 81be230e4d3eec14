/// @file GmshMesh.cpp
/// A Mesh from a gmsh file's physical groups (GmshMesh.hpp), and .geo files meshed by the
/// gmsh program.
#include "argine/meshio/GmshMesh.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <set>
#include <sstream>
#include <unordered_map>

#include "argine/core/Error.hpp"
#include "argine/meshio/MeshAssembly.hpp"

extern char** environ;

namespace argine {

namespace {

const char* groupKind(int dim) {
  switch (dim) {
    case 0:
      return "point";
    case 1:
      return "curve";
    case 2:
      return "surface";
    default:
      return "volume";
  }
}

const char* geoKeyword(int dim) {
  switch (dim) {
    case 0:
      return "Physical Point";
    case 1:
      return "Physical Curve";
    case 2:
      return "Physical Surface";
    default:
      return "Physical Volume";
  }
}

/// Builds the Mesh of a GmshFile; every refusal names the file.
class GmshMeshBuilder {
 public:
  GmshMeshBuilder(const std::string& path, const GmshFile& file) : path_(path), file_(file) {}

  Mesh build() {
    refuseVolumes();
    const std::map<int, std::vector<const GmshElementBlock*>> surfaces = surfaceGroups();
    numberNodes(surfaces);
    std::vector<RawElementBlock> blocks;
    std::set<std::string> block_names;
    for (const auto& [tag, entity_blocks] : surfaces) {
      RawElementBlock block{physicalName(2, tag), tag, {}};
      if (!block_names.insert(block.name).second)
        fail("two physical surfaces are named '" + block.name + "'; block names must be unique");
      for (const GmshElementBlock* entity_block : entity_blocks)
        for (const std::uint64_t node : entity_block->node_tags)
          block.connectivity.push_back(
              nodeIndex(node, "an element of physical surface '" + block.name + "'"));
      blocks.push_back(std::move(block));
    }
    AssembledMesh assembled = assembleMesh(path_, type_, x_, y_, blocks);
    mesh_ = &assembled.mesh;
    indexSides();
    addCurveSets();
    addPointSets();
    return std::move(assembled.mesh);
  }

 private:
  [[noreturn]] void fail(const std::string& problem) const { throw InputError(path_, problem); }

  void refuseVolumes() const {
    for (const auto& block : file_.element_blocks)
      if (block.entity_dim == 3)
        fail("a 3D mesh (volume " + std::to_string(block.entity_tag) + " has " +
             gmshElementName(block.element_type) +
             " elements); argine takes 2D sections in the xy plane: mesh with gmsh -2");
  }

  /// The physical group's name; an unnamed group is refused.
  std::string physicalName(int dim, int tag) const {
    const auto found = file_.physical_names.find({dim, tag});
    if (found == file_.physical_names.end() || found->second.empty())
      fail(std::string("physical ") + groupKind(dim) + " " + std::to_string(tag) +
           " has no name; argine refers to groups by name: give it one in the .geo file (" +
           geoKeyword(dim) + "(\"name\") = {...})");
    return found->second;
  }

  const std::vector<int>& physicalsOf(int dim, int tag) const {
    const auto found = file_.entity_physicals.find({dim, tag});
    if (found == file_.entity_physicals.end())
      fail(std::string("$Elements has elements of ") + groupKind(dim) + " " + std::to_string(tag) +
           ", which $Entities does not list");
    return found->second;
  }

  /// Surface element blocks by the physical surface holding their entity; fixes type_.
  std::map<int, std::vector<const GmshElementBlock*>> surfaceGroups() {
    std::map<int, std::vector<const GmshElementBlock*>> surfaces;
    const GmshElementBlock* first = nullptr;
    for (const auto& block : file_.element_blocks) {
      if (block.entity_dim != 2 || block.node_tags.empty()) continue;
      const std::string where = "surface " + std::to_string(block.entity_tag);
      if (block.element_type != 2 && block.element_type != 3)
        fail(where + " has " + gmshElementName(block.element_type) +
             " elements; argine takes 3-node triangles or 4-node quadrangles (first-order: "
             "Mesh.ElementOrder = 1)");
      const ElementType type = block.element_type == 2 ? ElementType::Tri3 : ElementType::Quad4;
      if (!first) {
        first = &block;
        type_ = type;
      } else if (type != type_) {
        fail("mixed element types: surface " + std::to_string(first->entity_tag) + " has " +
             gmshElementName(first->element_type) + "s, " + where + " " +
             gmshElementName(block.element_type) +
             "s; argine takes one type per mesh (recombine every surface, Mesh.RecombineAll = 1, "
             "or none)");
      }
      const std::vector<int>& physicals = physicalsOf(2, block.entity_tag);
      if (physicals.empty())
        fail(where + " (" + std::to_string(block.node_tags.size() / block.nodes_per_element) +
             " elements) is in no physical surface, so its elements would have no material; add "
             "it to one (Physical Surface(\"name\") = {" +
             std::to_string(block.entity_tag) + "})");
      if (physicals.size() > 1)
        fail(where + " is in physical surfaces '" + physicalName(2, physicals[0]) + "' and '" +
             physicalName(2, physicals[1]) + "'; an element belongs to one block");
      surfaces[physicals[0]].push_back(&block);
    }
    if (surfaces.empty())
      fail(
          "no surface elements in physical surfaces: argine makes an element block (a "
          "material's Block) of each physical surface; mesh in 2D (gmsh -2) and define one, "
          "Physical Surface(\"soil\") = {1}");
    return surfaces;
  }

  /// The nodes of surface elements, numbered in the order of their tags.
  void numberNodes(const std::map<int, std::vector<const GmshElementBlock*>>& surfaces) {
    std::vector<std::uint64_t> tags;
    for (const auto& [tag, blocks] : surfaces)
      for (const GmshElementBlock* block : blocks)
        tags.insert(tags.end(), block->node_tags.begin(), block->node_tags.end());
    std::sort(tags.begin(), tags.end());
    tags.erase(std::unique(tags.begin(), tags.end()), tags.end());
    Real z0 = 0, extent = 0;
    for (std::size_t n = 0; n < tags.size(); ++n) {
      const auto found = file_.nodes.find(tags[n]);
      if (found == file_.nodes.end())
        fail("an element refers to node " + std::to_string(tags[n]) + ", which $Nodes lacks");
      const auto& x = found->second;
      if (!std::isfinite(x[0]) || !std::isfinite(x[1]) || !std::isfinite(x[2]))
        fail("node " + std::to_string(tags[n]) + " has a non-finite coordinate");
      if (n == 0) z0 = x[2];
      extent = std::max({extent, std::abs(x[0]), std::abs(x[1])});
      index_.emplace(tags[n], static_cast<int>(n));
      x_.push_back(x[0]);
      y_.push_back(x[1]);
    }
    for (const std::uint64_t tag : tags) {
      const Real z = file_.nodes.at(tag)[2];
      if (std::abs(z - z0) > 1e-9 * std::max<Real>(extent, 1))
        fail("not a plane mesh in the xy plane: node " + std::to_string(tags.front()) +
             " has z = " + std::to_string(z0) + ", node " + std::to_string(tag) +
             " z = " + std::to_string(z) + "; argine takes 2D sections drawn in the xy plane");
    }
  }

  int nodeIndex(std::uint64_t tag, const std::string& who) const {
    const auto found = index_.find(tag);
    if (found == index_.end())
      fail(who + " refers to node " + std::to_string(tag) + ", which no surface element has");
    return found->second;
  }

  /// Each element side by its nodes (lower index first): (element, side) pairs.
  void indexSides() {
    const auto connectivity =
        Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), mesh_->connectivity);
    const int nv = mesh_->nodesPerElement();
    for (int e = 0; e < mesh_->numElements(); ++e)
      for (int s = 0; s < nv; ++s) {
        const int a = connectivity(e, s), b = connectivity(e, (s + 1) % nv);
        sides_[key(a, b)].push_back({e, s, a});
      }
  }

  struct Side {
    int element, side, from;  ///< from: the node the side starts at, counter-clockwise
  };
  static std::uint64_t key(int a, int b) {
    return (static_cast<std::uint64_t>(std::min(a, b)) << 32) |
           static_cast<std::uint32_t>(std::max(a, b));
  }

  /// Segments of each physical curve, in file order: side sets and node sets of its name.
  void addCurveSets() {
    std::map<int, std::vector<std::pair<int, int>>> curves;  // physical tag -> segments
    for (const auto& block : file_.element_blocks) {
      if (block.entity_dim != 1 || block.node_tags.empty()) continue;
      const std::vector<int>& physicals = physicalsOf(1, block.entity_tag);
      if (physicals.empty()) continue;  // a curve no condition refers to
      if (block.element_type != 1)
        fail("curve " + std::to_string(block.entity_tag) + " has " +
             gmshElementName(block.element_type) +
             " elements; argine takes 2-node lines (first-order: Mesh.ElementOrder = 1)");
      for (const int physical : physicals) {
        const std::string who = "physical curve '" + physicalName(1, physical) + "'";
        for (std::size_t k = 0; k + 1 < block.node_tags.size(); k += 2)
          curves[physical].push_back(
              {nodeIndex(block.node_tags[k], who), nodeIndex(block.node_tags[k + 1], who)});
      }
    }
    for (const auto& [tag, segments] : curves) {
      const std::string name = physicalName(1, tag);
      SideSet side_set{name, tag, {}, {}};
      std::set<std::pair<int, int>> taken;
      std::set<int> nodes;
      for (const auto& [a, b] : segments) {
        const auto found = sides_.find(key(a, b));
        if (found == sides_.end())
          fail("physical curve '" + name + "': its segment from node " + std::to_string(a + 1) +
               " to node " + std::to_string(b + 1) +
               " is not an element side (is the curve part of a meshed surface's boundary or "
               "embedded in it?)");
        // On the mesh's boundary the one element; inside it the element on the segment's
        // left, whose counter-clockwise side runs the same way (a to b).
        const Side* chosen = &found->second.front();
        for (const Side& side : found->second)
          if (side.from == a) chosen = &side;
        if (taken.insert({chosen->element, chosen->side}).second) {
          side_set.elements.push_back(chosen->element);
          side_set.sides.push_back(chosen->side);
        }
        nodes.insert(a);
        nodes.insert(b);
      }
      mesh_->side_sets.push_back(std::move(side_set));
      addNodeSet(NodeSet{name, tag, std::vector<int>(nodes.begin(), nodes.end())}, 1);
    }
  }

  /// Physical points: node sets of their names.
  void addPointSets() {
    std::map<int, std::set<int>> points;
    for (const auto& block : file_.element_blocks) {
      if (block.entity_dim != 0 || block.node_tags.empty()) continue;
      for (const int physical : physicalsOf(0, block.entity_tag)) {
        const std::string who = "physical point '" + physicalName(0, physical) + "'";
        for (const std::uint64_t node : block.node_tags)
          points[physical].insert(nodeIndex(node, who));
      }
    }
    for (const auto& [tag, nodes] : points)
      addNodeSet(NodeSet{physicalName(0, tag), tag, std::vector<int>(nodes.begin(), nodes.end())},
                 0);
  }

  void addNodeSet(NodeSet set, int dim) {
    for (const auto& [other, other_dim] : node_set_dims_)
      if (other == set.name)
        fail(std::string("physical ") + groupKind(other_dim) + " and physical " + groupKind(dim) +
             " are both named '" + set.name + "' (each makes a node set); names must be unique");
    node_set_dims_.push_back({set.name, dim});
    mesh_->node_sets.push_back(std::move(set));
  }

  const std::string& path_;
  const GmshFile& file_;
  ElementType type_ = ElementType::Tri3;
  std::unordered_map<std::uint64_t, int> index_;
  std::vector<Real> x_, y_;
  Mesh* mesh_ = nullptr;
  std::unordered_map<std::uint64_t, std::vector<Side>> sides_;
  std::vector<std::pair<std::string, int>> node_set_dims_;
};

/// The gmsh program: $ARGINE_GMSH, or `gmsh` on the PATH; empty when there is none.
std::string gmshProgram() {
  if (const char* chosen = std::getenv("ARGINE_GMSH"); chosen && *chosen) return chosen;
  const char* path = std::getenv("PATH");
  std::stringstream directories(path ? path : "");
  for (std::string directory; std::getline(directories, directory, ':');) {
    const std::filesystem::path candidate = std::filesystem::path(directory) / "gmsh";
    if (!directory.empty() && ::access(candidate.c_str(), X_OK) == 0) return candidate.string();
  }
  return "";
}

/// The last `count` lines of a text file.
std::string lastLines(const std::string& path, int count) {
  std::ifstream in(path);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  std::string text;
  for (std::size_t k = lines.size() > static_cast<std::size_t>(count) ? lines.size() - count : 0;
       k < lines.size(); ++k)
    text += "\n  " + lines[k];
  return text;
}

}  // namespace

Mesh gmshMesh(const std::string& path, const GmshFile& file) {
  return GmshMeshBuilder(path, file).build();
}

Mesh readGmshMesh(const std::string& path) {
  return gmshMesh(path, readGmshFile(path));
}

Mesh meshGeoFile(const std::string& geo_path) {
  if (!std::ifstream(geo_path).good())
    throw InputError(geo_path, "cannot open the .geo file (missing or unreadable)");
  const std::string program = gmshProgram();
  if (program.empty())
    throw InputError(geo_path,
                     "a .geo file needs the gmsh program to mesh it, and there is none (install "
                     "it: apt-get install gmsh; or set ARGINE_GMSH), or give the mesh as an "
                     ".msh file (gmsh -2 -format msh41 file.geo)");
  char pattern[] = "/tmp/argine-gmsh-XXXXXX";
  const char* directory = ::mkdtemp(pattern);
  if (!directory) throw InputError(geo_path, "cannot make a temporary directory for gmsh");
  const std::filesystem::path work(directory);
  const std::string msh = (work / "mesh.msh").string(), log = (work / "gmsh.log").string();
  std::vector<std::string> arguments{program, "-2", "-format", "msh41", "-o", msh, geo_path};
  std::vector<char*> argv;
  for (auto& argument : arguments) argv.push_back(argument.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, 1, 2);
  pid_t child = 0;
  const int spawned =
      ::posix_spawn(&child, program.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  int status = 0;
  const bool ran = spawned == 0 && ::waitpid(child, &status, 0) == child;
  const bool meshed =
      ran && WIFEXITED(status) && WEXITSTATUS(status) == 0 && std::filesystem::exists(msh);
  const std::string messages = lastLines(log, 8);
  std::error_code ignored;
  if (!meshed) {
    std::filesystem::remove_all(work, ignored);
    throw InputError(geo_path, "gmsh (" + program + ") could not mesh it" +
                                   (messages.empty() ? std::string(" (no messages)")
                                                     : "; its last messages:" + messages));
  }
  try {
    std::ifstream stream(msh, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(stream)),
                            std::istreambuf_iterator<char>());
    Mesh mesh = gmshMesh(geo_path, parseGmshFile(geo_path, bytes));
    std::filesystem::remove_all(work, ignored);
    return mesh;
  } catch (...) {
    std::filesystem::remove_all(work, ignored);
    throw;
  }
}

Mesh loadGmshMesh(const std::string& path) {
  const std::string extension = std::filesystem::path(path).extension().string();
  return extension == ".geo" ? meshGeoFile(path) : readGmshMesh(path);
}

}  // namespace argine
