#include "argine/input/DeckValidator.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <set>

#include <Teuchos_ParameterList.hpp>

#include "EntryValues.hpp"
#include "ValueText.hpp"
#include "argine/core/Error.hpp"

namespace argine {

using namespace input_detail;

std::string resolveDeckFile(const std::string& base_directory, const std::string& file) {
  namespace fs = std::filesystem;
  fs::path path(file);
  if (path.is_relative()) path = fs::path(base_directory.empty() ? "." : base_directory) / path;
  return fs::absolute(path).lexically_normal().string();
}

namespace {

std::string join(const std::string& path, const std::string& key) {
  return path.empty() ? key : path + "/" + key;
}

/// "Duration (s)" -> "Duration": users often get the unit suffix wrong or leave it out.
std::string withoutUnit(const std::string& key) {
  const auto open = key.rfind(" (");
  return open != std::string::npos && key.back() == ')' ? key.substr(0, open) : key;
}

/// The key of `names` the user probably meant by `word`, or "".
std::string suggestKey(const std::string& word, const std::vector<std::string>& names) {
  std::vector<std::string> stems;
  for (const auto& name : names) stems.push_back(withoutUnit(name));
  const std::string stem = closestMatch(withoutUnit(word), stems);
  if (!stem.empty())
    for (std::size_t i = 0; i < names.size(); ++i)
      if (stems[i] == stem) return names[i];
  return closestMatch(word, names);
}

/// One list being validated and its schema, for conditions on enclosing lists.
struct Frame {
  const Teuchos::ParameterList* list;
  const ListSchema* schema;
};

class Validator {
 public:
  explicit Validator(std::string base_directory) : base_directory_(std::move(base_directory)) {}

  void validateList(const Teuchos::ParameterList& list, const ListSchema& schema,
                    const std::string& path) {
    frames_.push_back(Frame{&list, &schema});
    // Enum keys first: other keys' applicability may depend on them (Model, Type, ...).
    std::set<std::string> done;
    for (auto it = list.begin(); it != list.end(); ++it) {
      const KeySpec* key = schema.find(list.name(it));
      if (key && key->type == KeyType::Enum && applies(*key)) {
        validateEntry(list.entry(it), *key, join(path, key->name));
        done.insert(key->name);
      }
    }
    for (const auto& key : schema.keys)
      if (key.type == KeyType::Enum && !list.isParameter(key.name)) checkPresence(key, path);

    // Alternatives given twice are reported before their values are checked.
    for (const auto& group : schema.exactly_one_of) checkOneOf(list, group, path, true);

    for (auto it = list.begin(); it != list.end(); ++it) {
      const std::string& name = list.name(it);
      if (done.count(name)) continue;
      const KeySpec* key = schema.find(name);
      const std::string key_path = join(path, name);
      if (!key) throw InputError(key_path, unknownKeyMessage(name, schema));
      if (!applies(*key)) throw InputError(key_path, notApplicableMessage(*key));
      validateEntry(list.entry(it), *key, key_path);
    }
    for (const auto& key : schema.keys)
      if (!list.isParameter(key.name)) checkPresence(key, path);
    for (const auto& group : schema.exactly_one_of) checkOneOf(list, group, path, false);
    frames_.pop_back();
  }

 private:
  // ---------------------------------------------------------------- conditions

  /// The canonical word of the Enum key `name` in the nearest enclosing list declaring it
  /// (its default when absent, "" when absent without default).
  std::string conditionValue(const std::string& name) const {
    for (auto frame = frames_.rbegin(); frame != frames_.rend(); ++frame) {
      const KeySpec* key = frame->schema->find(name);
      if (!key) continue;
      if (frame->list->isParameter(name)) {
        const auto text = entryText(frame->list->getEntry(name));
        return text ? matchWord(key->words, *text) : std::string();
      }
      return key->hasDefault() ? std::get<std::string>(key->default_value) : std::string();
    }
    return "";
  }

  bool holds(const Condition& condition) const {
    if (condition.always()) return true;
    const std::string value = conditionValue(condition.key);
    for (const auto& allowed : condition.values)
      if (value == allowed) return true;
    return false;
  }

  bool applies(const KeySpec& key) const { return holds(key.applies_when); }

  bool requiredHere(const KeySpec& key) const {
    return key.required && applies(key) && holds(key.required_when);
  }

  // ---------------------------------------------------------------- list-level checks

  void checkPresence(const KeySpec& key, const std::string& path) const {
    if (!requiredHere(key)) return;
    const std::string range = key.range.empty() ? "" : " " + key.range.text();
    std::string problem =
        "missing required key (" + key.doc + "; " + key.expectation() + range + ")";
    if (!key.required_when.always())
      problem += ", required when " + key.required_when.text();
    else if (!key.applies_when.always())
      problem += ", required when " + key.applies_when.text();
    throw InputError(join(path, key.name), problem);
  }

  /// Throws when several alternatives are given (`too_many`) or none (otherwise).
  void checkOneOf(const Teuchos::ParameterList& list, const OneOf& group, const std::string& path,
                  bool too_many) const {
    if (!holds(group.applies_when)) return;
    std::vector<std::string> given;
    for (const auto& name : group.keys)
      if (list.isParameter(name)) given.push_back("'" + name + "'");
    if (too_many ? given.size() <= 1 : !given.empty()) return;
    std::vector<std::string> quoted;
    for (const auto& name : group.keys) quoted.push_back("'" + name + "'");
    std::string problem = "give exactly one of " + joinWords(quoted, " or ");
    if (!group.applies_when.always()) problem += " when " + group.applies_when.text();
    problem += given.empty() ? " (found none)" : " (found " + joinWords(given, " and ") + ")";
    throw InputError(path.empty() ? "deck" : path, problem);
  }

  std::string unknownKeyMessage(const std::string& name, const ListSchema& schema) const {
    std::vector<std::string> applicable, all;
    for (const auto& key : schema.keys) {
      all.push_back(key.name);
      if (applies(key)) applicable.push_back(key.name);
    }
    std::string suggestion = suggestKey(name, applicable);
    if (suggestion.empty()) suggestion = suggestKey(name, all);
    if (!suggestion.empty())
      return "unknown key '" + name + "'; did you mean '" + suggestion + "'?";
    return "unknown key '" + name + "'; valid keys here: " + joinWords(applicable);
  }

  std::string notApplicableMessage(const KeySpec& key) const {
    const std::string current = conditionValue(key.applies_when.key);
    return "key '" + key.name + "' applies only when " + key.applies_when.text() + " (here " +
           key.applies_when.key + " is " + (current.empty() ? "not set" : current) +
           "); remove it or change " + key.applies_when.key;
  }

  // ---------------------------------------------------------------- values

  [[noreturn]] void wrongType(const Teuchos::ParameterEntry& entry, const KeySpec& key,
                              const std::string& path) const {
    throw InputError(path, "expected " + key.expectation() + ", got " + describeEntry(entry));
  }

  std::string unitSuffix(const KeySpec& key) const {
    return key.unit.empty() || key.unit == "-" ? "" : " " + key.unit;
  }

  void checkNumber(double value, const KeySpec& key, const std::string& path,
                   const std::string& what = "") const {
    if (!std::isfinite(value))
      throw InputError(path, what + "NaN and infinity are not allowed, got " + formatReal(value));
    if (!key.range.contains(value))
      throw InputError(path, what + "must be " + key.range.text() + unitSuffix(key) + ", got " +
                                 formatReal(value));
  }

  /// A string where a number was meant: say why it is not one.
  void rejectNumberText(const std::string& text, const KeySpec& key,
                        const std::string& path) const {
    if (namesNonFiniteNumber(text))
      throw InputError(path, "NaN and infinity are not allowed, got '" + text + "'");
    if (namesFiniteNumber(text))
      throw InputError(path, "expected " + key.expectation() + ", got the quoted text '" + text +
                                 "'; write numbers without quotes");
  }

  void validateReal(const Teuchos::ParameterEntry& entry, const KeySpec& key,
                    const std::string& path) const {
    if (const auto value = entryReal(entry)) return checkNumber(*value, key, path);
    if (entry.isType<std::string>() && !entry.isList())
      rejectNumberText(Teuchos::any_cast<std::string>(entry.getAny(false)), key, path);
    wrongType(entry, key, path);
  }

  void validateInteger(const Teuchos::ParameterEntry& entry, const KeySpec& key,
                       const std::string& path) const {
    const auto value = entryReal(entry);
    if (!value) {
      if (entry.isType<std::string>() && !entry.isList())
        rejectNumberText(Teuchos::any_cast<std::string>(entry.getAny(false)), key, path);
      wrongType(entry, key, path);
    }
    if (std::isfinite(*value) && std::trunc(*value) != *value) wrongType(entry, key, path);
    checkNumber(*value, key, path);
    // argine stores counts as int: a larger value would wrap around silently (P8).
    constexpr double kLargestInt = std::numeric_limits<int>::max();
    if (!(std::fabs(*value) <= kLargestInt))
      throw InputError(path, "must be an integer between -" + formatReal(kLargestInt) + " and " +
                                 formatReal(kLargestInt) + ", got " + formatReal(*value));
    if (key.allowed_integers.empty()) return;
    for (long long allowed : key.allowed_integers)
      if (static_cast<double>(allowed) == *value) return;
    std::vector<std::string> texts;
    for (long long allowed : key.allowed_integers) texts.push_back(std::to_string(allowed));
    throw InputError(path, "must be one of " + joinWords(texts) + ", got " + formatReal(*value));
  }

  void validateText(const Teuchos::ParameterEntry& entry, const KeySpec& key,
                    const std::string& path) const {
    const auto text = entryText(entry);
    if (!text) wrongType(entry, key, path);
    if (!key.allow_empty_text && trim(*text).empty()) throw InputError(path, "must not be empty");
    if (key.type != KeyType::FilePath) return;
    const std::string file = resolveDeckFile(base_directory_, *text);
    namespace fs = std::filesystem;
    std::error_code error;
    if (!fs::exists(file, error))
      throw InputError(path, "file '" + *text + "' not found (looked for " + file + ")");
    if (!fs::is_regular_file(file, error))
      throw InputError(path, "'" + *text + "' is not a regular file (" + file + ")");
    if (!std::ifstream(file).good())
      throw InputError(path, "file '" + *text + "' is not readable (" + file + ")");
  }

  std::string badWordMessage(const std::string& word, const KeySpec& key) const {
    std::string problem = "'" + word + "' is not allowed; allowed: " + joinWords(key.words);
    std::vector<std::string> suggestions;
    const std::string closest = closestMatch(word, key.words);
    if (!closest.empty()) suggestions.push_back("'" + closest + "'");
    // A shortened word ("elastic", "cfl") is probably part of the one meant.
    const std::string part = lower(trim(word));
    if (suggestions.empty() && !part.empty())
      for (const auto& allowed : key.words)
        if (lower(allowed).find(part) != std::string::npos)
          suggestions.push_back("'" + allowed + "'");
    if (!suggestions.empty() && suggestions.size() <= 3)
      problem += "; did you mean " + joinWords(suggestions, " or ") + "?";
    return problem;
  }

  void validateEnum(const Teuchos::ParameterEntry& entry, const KeySpec& key,
                    const std::string& path) const {
    const auto text = entryText(entry);
    if (!text) wrongType(entry, key, path);
    if (matchWord(key.words, *text).empty()) throw InputError(path, badWordMessage(*text, key));
  }

  void validateWordList(const Teuchos::ParameterEntry& entry, const KeySpec& key,
                        const std::string& path) const {
    const auto words = entryWords(entry);
    if (!words) wrongType(entry, key, path);
    if (words->empty()) throw InputError(path, "needs at least one of: " + joinWords(key.words));
    std::set<std::string> seen;
    for (const auto& word : *words) {
      const std::string canonical = matchWord(key.words, word);
      if (canonical.empty()) throw InputError(path, badWordMessage(word, key));
      if (!seen.insert(canonical).second)
        throw InputError(path, "'" + canonical + "' is listed twice");
    }
  }

  void validateRealList(const Teuchos::ParameterEntry& entry, const KeySpec& key,
                        const std::string& path) const {
    const auto values = entryReals(entry);
    if (!values) {
      // YAML makes the whole list text when one item is not a number: name that item.
      if (const auto texts = entryTextList(entry))
        for (std::size_t i = 0; i < texts->size(); ++i)
          if (namesNonFiniteNumber((*texts)[i]))
            throw InputError(path, "item " + std::to_string(i + 1) + " ('" + (*texts)[i] +
                                       "'): NaN and infinity are not allowed");
      wrongType(entry, key, path);
    }
    if (key.list_size && values->size() != key.list_size)
      throw InputError(path, "expected " + key.expectation() + ", got a list of " +
                                 std::to_string(values->size()));
    for (std::size_t i = 0; i < values->size(); ++i)
      checkNumber((*values)[i], key, path, "item " + std::to_string(i + 1) + ": ");
  }

  void validateNamedSublists(const Teuchos::ParameterEntry& entry, const KeySpec& key,
                             const std::string& path) {
    if (!entry.isList()) wrongType(entry, key, path);
    const auto& map = Teuchos::any_cast<Teuchos::ParameterList>(entry.getAny(false));
    if (key.needs_entry && map.numParams() == 0)
      throw InputError(path,
                       "needs at least one " + key.entry_label + " (" + key.expectation() + ")");
    for (auto it = map.begin(); it != map.end(); ++it) {
      const std::string& name = map.name(it);
      const auto& item = map.entry(it);
      if (!item.isList()) {
        std::string problem =
            "expected a sublist (one " + key.entry_label + "), got " + describeEntry(item);
        if (key.children->find(name))
          problem += "; '" + name + "' is a key of a " + key.entry_label + ": put it inside a " +
                     "named entry, e.g. " + key.name + "/<name>/" + name;
        throw InputError(join(path, name), problem);
      }
      validateList(Teuchos::any_cast<Teuchos::ParameterList>(item.getAny(false)), *key.children,
                   join(path, name));
    }
  }

  void validateEntry(const Teuchos::ParameterEntry& entry, const KeySpec& key,
                     const std::string& path) {
    switch (key.type) {
      case KeyType::Real:
        return validateReal(entry, key, path);
      case KeyType::Integer:
        return validateInteger(entry, key, path);
      case KeyType::Bool:
        if (entry.isList() || !entry.isType<bool>()) wrongType(entry, key, path);
        return;
      case KeyType::String:
      case KeyType::FilePath:
        return validateText(entry, key, path);
      case KeyType::Enum:
        return validateEnum(entry, key, path);
      case KeyType::WordList:
        return validateWordList(entry, key, path);
      case KeyType::RealList:
        return validateRealList(entry, key, path);
      case KeyType::Sublist:
        if (!entry.isList()) wrongType(entry, key, path);
        return validateList(Teuchos::any_cast<Teuchos::ParameterList>(entry.getAny(false)),
                            *key.children, path);
      case KeyType::NamedSublists:
        return validateNamedSublists(entry, key, path);
    }
  }

  std::string base_directory_;
  std::vector<Frame> frames_;
};

}  // namespace

void validateParameters(const Teuchos::ParameterList& list, const ListSchema& schema,
                        const std::string& base_directory, const std::string& path) {
  Validator(base_directory).validateList(list, schema, path);
}

}  // namespace argine
