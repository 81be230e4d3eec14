#pragma once
/// @file Setup.hpp
/// Everything that happens before the first time step: the background mesh the deck asks
/// for (Exodus or gmsh file, or built-in generator), its checks against the deck, and the material
/// points seeded in each material's block. Every failure here is an InputError.

#include <string>

#include "argine/input/Deck.hpp"
#include "argine/mesh/Mesh.hpp"
#include "argine/points/MaterialPoints.hpp"

namespace argine {

/// The mesh a deck's Mesh section describes (generated, or read from its Exodus or gmsh
/// file), unchecked against the deck.
Mesh readDeckMesh(const MeshSpec& spec);

/// Where that mesh comes from, for messages: "Mesh/Generate" or the file's path.
std::string meshSource(const MeshSpec& spec);

/// Reads or generates the mesh of `deck`, checks element quality and that every block and
/// set the deck names exists, and resolves the boundary conditions of every explicit stage
/// (StageBoundaryConditions) so that a condition the mesh cannot carry fails here.
Mesh loadMesh(const Deck& deck);

/// Seeds `Points Per Element` points in every element of each material's block.
MaterialPoints seedPoints(const Deck& deck, const Mesh& mesh);

}  // namespace argine
