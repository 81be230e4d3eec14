#pragma once
/// @file DeckValidator.hpp
/// Checks a Teuchos parameter list against a schema before anything runs: unknown keys
/// (with "did you mean"), keys that do not apply to the chosen model, wrong types, missing
/// required keys, values out of range, NaN or infinity, words not allowed, alternatives
/// given twice or not at all, and files that do not exist. The first problem in deck order
/// is thrown as an InputError whose `where` is the key path
/// ("Stages/flood/Boundary Conditions/river/Pressure (Pa)").

#include <string>

#include "argine/input/DeckSchema.hpp"

namespace Teuchos {
class ParameterList;
}

namespace argine {

/// Validates `list` (the keys inside `argine:`) against `schema`. File keys are resolved
/// relative to `base_directory`; `path` prefixes every reported key path ("" at the top).
void validateParameters(const Teuchos::ParameterList& list, const ListSchema& schema,
                        const std::string& base_directory, const std::string& path = "");

/// `file` as an absolute, normalised path: relative names are taken from `base_directory`.
std::string resolveDeckFile(const std::string& base_directory, const std::string& file);

}  // namespace argine
