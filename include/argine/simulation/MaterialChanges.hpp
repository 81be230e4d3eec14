#pragma once
/// @file MaterialChanges.hpp
/// A stage's `Material Changes` (SPEC: a stage may change material parameters, e.g. the
/// cohesion 20 -> 2 kPa): new values written into the current material list, which the
/// Simulation then hands to ExplicitTwoPhaseSolver::setMaterials at the stage start.

#include <string>
#include <vector>

#include "argine/input/Deck.hpp"

namespace argine {

/// Applies `changes` to `materials` (matched by name) and returns one log line per changed
/// value, "material 'clay': cohesion 20000 -> 2000 Pa". A new permeability sets both kappa
/// and k_sat (k_sat = kappa rho_L g / mu_L, g = 9.81 m/s2, as the deck reader does).
/// Throws InputError("Stages/<stage>/Material Changes/<name>") for an unknown material.
std::vector<std::string> applyMaterialChanges(const std::string& stage,
                                              const std::vector<MaterialChangeSpec>& changes,
                                              std::vector<MaterialSpec>& materials);

}  // namespace argine
