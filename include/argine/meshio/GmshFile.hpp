#pragma once
/// @file GmshFile.hpp
/// The contents of a gmsh MSH 4.1 file (ASCII or binary) as written, before argine makes a
/// Mesh of them (GmshMesh.hpp): physical names, the entities' physical tags, nodes and element
/// blocks. Format: gmsh reference manual, "MSH file format" (version 4.1). Sections argine
/// does not use ($Periodic, $NodeData, ...) are skipped; partitioned files are refused.

#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "argine/core/Types.hpp"

namespace argine {

struct GmshElementBlock {
  int entity_dim = 0;
  int entity_tag = 0;
  int element_type = 0;  ///< gmsh type number (1 line, 2 triangle, 3 quad, 15 point)
  int nodes_per_element = 0;
  std::vector<std::uint64_t> node_tags;  ///< nodes_per_element per element, the file's tags
};

struct GmshFile {
  bool binary = false;
  /// (dimension, physical tag) -> name, from $PhysicalNames.
  std::map<std::pair<int, int>, std::string> physical_names;
  /// (dimension, entity tag) -> the entity's physical tags, from $Entities.
  std::map<std::pair<int, int>, std::vector<int>> entity_physicals;
  /// Node tag -> coordinates (x, y, z).
  std::map<std::uint64_t, std::array<Real, 3>> nodes;
  std::vector<GmshElementBlock> element_blocks;
};

/// The number of nodes of gmsh element type `type`, and its name ("3-node triangle"); 0 and
/// "" for a type this reader does not know.
int gmshNodesPerElement(int type);
std::string gmshElementName(int type);

/// Reads an MSH 4.1 file. Throws InputError naming `path` for a file that cannot be read, is
/// not MSH 4.1 (an MSH 2.2 file is told how to convert), is partitioned, or is truncated or
/// inconsistent (counts larger than the file, a section without its end, unknown element
/// types).
GmshFile readGmshFile(const std::string& path);

/// The same from bytes already in memory (`path` names them in errors).
GmshFile parseGmshFile(const std::string& path, const std::string& bytes);

}  // namespace argine
