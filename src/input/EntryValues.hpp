#pragma once
// Reading values out of Teuchos parameter entries (private to the input room). YAML gives
// ints for whole numbers, Array<int> for lists of them and strings for what it cannot
// type; these helpers accept every form the schema allows and say what was found.

#include <optional>
#include <string>
#include <vector>

#include <Teuchos_ParameterList.hpp>

namespace argine::input_detail {

/// "string 'abc'", "integer 3", "real number 2.5", "list [1, 2]", "a sublist",
/// "an empty value" (YAML `Key:` with nothing after it), for messages.
std::string describeEntry(const Teuchos::ParameterEntry& entry);

/// The entry as a real number when it is an int, long long or double.
std::optional<double> entryReal(const Teuchos::ParameterEntry& entry);

/// The entry as text when it is a string, or an integer written as text ("2024").
std::optional<std::string> entryText(const Teuchos::ParameterEntry& entry);

/// The entry as a list of reals when it is an Array of double, int or long long.
std::optional<std::vector<double>> entryReals(const Teuchos::ParameterEntry& entry);

/// The entry's words: an Array<string> or a comma-separated string, items trimmed.
std::optional<std::vector<std::string>> entryWords(const Teuchos::ParameterEntry& entry);

/// The items of an Array<string> entry, if it is one (to spot ".nan" inside number lists).
std::optional<std::vector<std::string>> entryTextList(const Teuchos::ParameterEntry& entry);

}  // namespace argine::input_detail
