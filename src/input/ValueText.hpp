#pragma once
// Text helpers of the input room (private): number formatting, word matching, word lists.

#include <string>
#include <vector>

#include "argine/input/DeckSchema.hpp"

namespace argine::input_detail {

/// Shortest text that reads back as the same double ("0.001", "2.2e9", "101325").
std::string formatReal(double value);

/// A default value as the reference and messages show it.
std::string formatDefault(const DefaultValue& value);

/// "a, b, c" (or with another separator).
std::string joinWords(const std::vector<std::string>& words, const std::string& separator = ", ");

/// `text` in lower case.
std::string lower(std::string text);

/// `text` without leading and trailing white space.
std::string trim(const std::string& text);

/// The word of `words` equal to `value` ignoring case and surrounding spaces, or "".
std::string matchWord(const std::vector<std::string>& words, const std::string& value);

/// Items of a comma-separated list, trimmed, empty items dropped.
std::vector<std::string> splitCommaList(const std::string& text);

/// True for spellings of NaN or infinity that YAML readers leave as strings
/// (".nan", "NaN", ".inf", "-inf", "infinity", "1e999", ...).
bool namesNonFiniteNumber(const std::string& text);

/// True when `text` is a whole finite number ("3600", "1e-3"): a quoted number.
bool namesFiniteNumber(const std::string& text);

}  // namespace argine::input_detail
