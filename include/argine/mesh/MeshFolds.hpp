#pragma once
/// @file MeshFolds.hpp
/// Overlapping (folded, tangled) elements. In a valid mesh of counter-clockwise elements every
/// interior side is run once in each direction by the two elements that share it. When two
/// elements run the same side in the same direction, they lie on the same side of it: one of
/// them is inverted relative to its neighbour (a node moved across the opposite side, or
/// the element was listed clockwise among counter-clockwise ones and reordered when read).

#include <string>

#include "argine/mesh/Mesh.hpp"

namespace argine {

/// Throws InputError(source, ...) naming both elements (1-based, with blocks) and the nodes
/// (1-based) of the first side run twice in the same direction. Expects connectivity entries
/// in range (checkMeshQuality checks them first and calls this).
void checkNoFoldedElements(const Mesh& mesh, const std::string& source);

}  // namespace argine
