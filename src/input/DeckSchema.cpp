#include "argine/input/DeckSchema.hpp"

#include <cmath>
#include <stdexcept>

#include "ValueText.hpp"

namespace argine {

using input_detail::formatReal;
using input_detail::joinWords;

// ---------------------------------------------------------------- Range, Condition

bool Range::contains(double value) const {
  if (std::isnan(value)) return false;
  if (has_min && (min_open ? value <= min : value < min)) return false;
  if (has_max && (max_open ? value >= max : value > max)) return false;
  return true;
}

std::string Range::text() const {
  if (has_min && has_max)
    return "in " + std::string(min_open ? "(" : "[") + formatReal(min) + ", " + formatReal(max) +
           (max_open ? ")" : "]");
  if (has_min) return (min_open ? "> " : ">= ") + formatReal(min);
  if (has_max) return (max_open ? "< " : "<= ") + formatReal(max);
  return "";
}

std::string Condition::text() const {
  return key + " is " + joinWords(values, " or ");
}

// ---------------------------------------------------------------- KeySpec factories

namespace {
KeySpec makeKey(std::string name, KeyType type, std::string unit, std::string doc) {
  KeySpec key;
  key.name = std::move(name);
  key.type = type;
  key.unit = std::move(unit);
  key.doc = std::move(doc);
  return key;
}
}  // namespace

KeySpec KeySpec::real(std::string name, std::string unit, std::string doc) {
  return makeKey(std::move(name), KeyType::Real, std::move(unit), std::move(doc));
}
KeySpec KeySpec::integer(std::string name, std::string doc) {
  return makeKey(std::move(name), KeyType::Integer, "-", std::move(doc));
}
KeySpec KeySpec::boolean(std::string name, std::string doc) {
  return makeKey(std::move(name), KeyType::Bool, "", std::move(doc));
}
KeySpec KeySpec::text(std::string name, std::string doc) {
  return makeKey(std::move(name), KeyType::String, "", std::move(doc));
}
KeySpec KeySpec::file(std::string name, std::string doc) {
  return makeKey(std::move(name), KeyType::FilePath, "", std::move(doc));
}
KeySpec KeySpec::choice(std::string name, std::vector<std::string> words, std::string doc) {
  KeySpec key = makeKey(std::move(name), KeyType::Enum, "", std::move(doc));
  key.words = std::move(words);
  return key;
}
KeySpec KeySpec::choices(std::string name, std::vector<std::string> words, std::string doc) {
  KeySpec key = makeKey(std::move(name), KeyType::WordList, "", std::move(doc));
  key.words = std::move(words);
  return key;
}
KeySpec KeySpec::reals(std::string name, std::string unit, std::size_t size, std::string doc) {
  KeySpec key = makeKey(std::move(name), KeyType::RealList, std::move(unit), std::move(doc));
  key.list_size = size;
  return key;
}
KeySpec KeySpec::sublist(std::string name, ListSchema children, std::string doc) {
  KeySpec key = makeKey(std::move(name), KeyType::Sublist, "", std::move(doc));
  key.children = std::make_shared<const ListSchema>(std::move(children));
  return key;
}
KeySpec KeySpec::namedSublists(std::string name, std::string entry_label, ListSchema children,
                               std::string doc) {
  KeySpec key = makeKey(std::move(name), KeyType::NamedSublists, "", std::move(doc));
  key.entry_label = std::move(entry_label);
  key.children = std::make_shared<const ListSchema>(std::move(children));
  return key;
}

// ---------------------------------------------------------------- KeySpec setters

KeySpec& KeySpec::require() {
  required = true;
  return *this;
}
KeySpec& KeySpec::requireWhen(std::string key, std::vector<std::string> values) {
  required = true;
  required_when = Condition{std::move(key), std::move(values)};
  return *this;
}
KeySpec& KeySpec::when(std::string key, std::vector<std::string> values) {
  applies_when = Condition{std::move(key), std::move(values)};
  return *this;
}
KeySpec& KeySpec::byDefault(DefaultValue value) {
  default_value = std::move(value);
  return *this;
}
KeySpec& KeySpec::above(double bound) {
  range.has_min = true, range.min_open = true, range.min = bound;
  return *this;
}
KeySpec& KeySpec::atLeast(double bound) {
  range.has_min = true, range.min_open = false, range.min = bound;
  return *this;
}
KeySpec& KeySpec::below(double bound) {
  range.has_max = true, range.max_open = true, range.max = bound;
  return *this;
}
KeySpec& KeySpec::atMost(double bound) {
  range.has_max = true, range.max_open = false, range.max = bound;
  return *this;
}
KeySpec& KeySpec::onlyIntegers(std::vector<long long> allowed) {
  allowed_integers = std::move(allowed);
  return *this;
}
KeySpec& KeySpec::allowEmpty() {
  allow_empty_text = true;
  return *this;
}
KeySpec& KeySpec::atLeastOneEntry() {
  needs_entry = true;
  return *this;
}

std::string KeySpec::expectation() const {
  const bool has_unit = !unit.empty() && unit != "-";
  const std::string in_unit = has_unit ? " (" + unit + ")" : "";
  switch (type) {
    case KeyType::Real:
      return "a real number" + in_unit;
    case KeyType::Integer:
      return "an integer";
    case KeyType::Bool:
      return "true or false";
    case KeyType::String:
      return "a name (text)";
    case KeyType::FilePath:
      return "a file name (text)";
    case KeyType::Enum:
      return "one of: " + joinWords(words);
    case KeyType::WordList:
      return "a list of words out of: " + joinWords(words);
    case KeyType::RealList:
      return (list_size ? "a list of " + std::to_string(list_size) + " real numbers"
                        : std::string("a list of real numbers")) +
             in_unit;
    case KeyType::Sublist:
      return "a sublist of keys";
    case KeyType::NamedSublists:
      return "a map of named sublists (one per " + entry_label + ")";
  }
  return "";
}

// ---------------------------------------------------------------- ListSchema

ListSchema& ListSchema::add(KeySpec key) {
  if (find(key.name)) throw std::logic_error("deck schema: key '" + key.name + "' declared twice");
  keys.push_back(std::move(key));
  return *this;
}

ListSchema& ListSchema::exactlyOneOf(std::vector<std::string> alternatives,
                                     Condition applies_when) {
  exactly_one_of.push_back(OneOf{std::move(alternatives), std::move(applies_when)});
  return *this;
}

const KeySpec* ListSchema::find(const std::string& name) const {
  for (const auto& key : keys)
    if (key.name == name) return &key;
  return nullptr;
}

// ---------------------------------------------------------------- checkSchema

namespace {

void fail(const std::string& path, const std::string& problem) {
  throw std::logic_error("deck schema, " + path + ": " + problem);
}

/// The Enum key a condition names, searched from the innermost list outwards.
const KeySpec* conditionKey(const std::vector<const ListSchema*>& chain, const std::string& key) {
  for (auto it = chain.rbegin(); it != chain.rend(); ++it)
    if (const KeySpec* found = (*it)->find(key)) return found;
  return nullptr;
}

void checkCondition(const std::vector<const ListSchema*>& chain, const Condition& condition,
                    const std::string& path) {
  if (condition.always()) return;
  const KeySpec* key = conditionKey(chain, condition.key);
  if (!key || key->type != KeyType::Enum)
    fail(path, "condition names '" + condition.key + "', which is no enum key here");
  if (condition.values.empty()) fail(path, "condition on '" + condition.key + "' has no values");
  for (const auto& value : condition.values) {
    bool known = false;
    for (const auto& word : key->words) known = known || word == value;
    if (!known) fail(path, "condition value '" + value + "' is not a word of " + condition.key);
  }
}

bool defaultFitsType(const KeySpec& key) {
  const DefaultValue& value = key.default_value;
  switch (key.type) {
    case KeyType::Real:
      return std::holds_alternative<double>(value) && key.range.contains(std::get<double>(value));
    case KeyType::Integer:
      return std::holds_alternative<long long>(value) &&
             key.range.contains(static_cast<double>(std::get<long long>(value)));
    case KeyType::Bool:
      return std::holds_alternative<bool>(value);
    case KeyType::String:
    case KeyType::FilePath:
      return std::holds_alternative<std::string>(value);
    case KeyType::Enum:
      if (!std::holds_alternative<std::string>(value)) return false;
      for (const auto& word : key.words)
        if (word == std::get<std::string>(value)) return true;
      return false;
    case KeyType::WordList:
      if (!std::holds_alternative<std::vector<std::string>>(value)) return false;
      for (const auto& item : std::get<std::vector<std::string>>(value)) {
        bool known = false;
        for (const auto& word : key.words) known = known || word == item;
        if (!known) return false;
      }
      return true;
    case KeyType::RealList:
      return std::holds_alternative<std::vector<double>>(value) &&
             (key.list_size == 0 || std::get<std::vector<double>>(value).size() == key.list_size);
    case KeyType::Sublist:
    case KeyType::NamedSublists:
      return false;
  }
  return false;
}

/// True when `key` is required only under values of the group's condition key other than
/// those of the group (Node Set is required for solid fixities, an alternative otherwise).
bool requiredOnlyOutside(const KeySpec& key, const Condition& group) {
  if (key.required_when.always() || group.always() || key.required_when.key != group.key)
    return false;
  for (const auto& value : key.required_when.values)
    for (const auto& other : group.values)
      if (value == other) return false;
  return true;
}

void checkList(const ListSchema& schema, std::vector<const ListSchema*>& chain,
               const std::string& path) {
  chain.push_back(&schema);
  for (const auto& key : schema.keys) {
    const std::string key_path = path.empty() ? key.name : path + "/" + key.name;
    if (key.doc.empty()) fail(key_path, "no description");
    checkCondition(chain, key.applies_when, key_path);
    checkCondition(chain, key.required_when, key_path);
    if (key.hasDefault() && key.required) fail(key_path, "both required and defaulted");
    if (key.hasDefault() && !defaultFitsType(key))
      fail(key_path, "default value does not fit its type or range");
    const bool numeric =
        key.type == KeyType::Real || key.type == KeyType::Integer || key.type == KeyType::RealList;
    if (numeric && key.unit.empty()) fail(key_path, "numbers need a unit (\"-\" if none)");
    if ((key.type == KeyType::Enum || key.type == KeyType::WordList) && key.words.empty())
      fail(key_path, "no allowed words");
    const bool nested = key.type == KeyType::Sublist || key.type == KeyType::NamedSublists;
    if (nested != static_cast<bool>(key.children)) fail(key_path, "children mismatch");
    if (key.children) {
      const std::string child_path =
          key.type == KeyType::NamedSublists ? key_path + "/<" + key.entry_label + ">" : key_path;
      checkList(*key.children, chain, child_path);
    }
  }
  for (const auto& group : schema.exactly_one_of) {
    checkCondition(chain, group.applies_when, path);
    if (group.keys.size() < 2) fail(path, "an exactly-one-of group needs two keys");
    for (const auto& name : group.keys) {
      const KeySpec* key = schema.find(name);
      if (!key) fail(path, "exactly-one-of names unknown key '" + name + "'");
      if (key->hasDefault()) fail(path, "alternative '" + name + "' must have no default");
      if (key->required && !requiredOnlyOutside(*key, group.applies_when))
        fail(path, "alternative '" + name + "' is required where the group applies");
    }
  }
  chain.pop_back();
}

}  // namespace

void checkSchema(const ListSchema& schema) {
  std::vector<const ListSchema*> chain;
  checkList(schema, chain, "");
}

}  // namespace argine
