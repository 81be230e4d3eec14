#pragma once
/// @file Initialisation.hpp
/// The initial state of the seeded points as the deck's `Initialisation` asks: each
/// material's uniform Initial State (physics/PointInitialisation), then, for the K0
/// procedure, the geostatic stress and hydrostatic p_L of init/K0Procedure.hpp.

#include <string>

#include "argine/core/Types.hpp"

namespace argine {

struct Deck;
struct Mesh;
struct MaterialPoints;

/// Initialises `points` (seeded in `mesh`). The K0 procedure balances the gravity of the
/// first stage. Returns a one-line description for the log.
std::string initialisePoints(const Deck& deck, const Mesh& mesh, MaterialPoints& points);

}  // namespace argine
