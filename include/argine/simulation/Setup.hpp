#pragma once
/// @file Setup.hpp
/// Everything that happens before the first time step: the background mesh the deck asks
/// for (Exodus file or built-in generator), its checks against the deck, and the material
/// points seeded in each material's block. Every failure here is an InputError.

#include "argine/input/Deck.hpp"
#include "argine/mesh/Mesh.hpp"
#include "argine/points/MaterialPoints.hpp"

namespace argine {

/// Reads or generates the mesh of `deck`, checks element quality and that every block and
/// set the deck names exists, and resolves the boundary conditions of every explicit stage
/// (StageBoundaryConditions) so that a condition the mesh cannot carry fails here.
Mesh loadMesh(const Deck& deck);

/// Seeds `Points Per Element` points in every element of each material's block.
MaterialPoints seedPoints(const Deck& deck, const Mesh& mesh);

}  // namespace argine
