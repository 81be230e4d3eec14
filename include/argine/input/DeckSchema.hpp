#pragma once
/// @file DeckSchema.hpp
/// The deck schema: every key of an argine deck is declared once, with its type, unit,
/// default or requirement, allowed range and a one-line description. The validator
/// (DeckValidator.hpp) checks a parameter list against it before anything runs, the reader
/// takes defaults from it, and deckReferenceMarkdown() renders it as the user guide's key
/// table (doc/deck-reference.md).

#include <cstddef>
#include <memory>
#include <string>
#include <variant>
#include <vector>

namespace argine {

/// What a key holds.
enum class KeyType {
  Real,           ///< a real number; integers are accepted (YAML keeps `3600` an int)
  Integer,        ///< an integer; reals are accepted only without a fractional part
  Bool,           ///< true or false
  String,         ///< free text (a name)
  FilePath,       ///< a file, relative to the deck's directory; must exist and be readable
  Enum,           ///< one word out of `words` (case-insensitive)
  WordList,       ///< several words out of `words`: a YAML list or one comma-separated string
  RealList,       ///< a list of real numbers (Teuchos Array<double>), `list_size` long if > 0
  Sublist,        ///< a nested list of keys, `children`
  NamedSublists,  ///< a map name -> sublist, each entry following `children`
};

/// Bounds of a number; either side may be absent, open bounds exclude the bound itself.
struct Range {
  bool has_min = false;   ///< a lower bound is set
  bool has_max = false;   ///< an upper bound is set
  bool min_open = false;  ///< lower bound excluded
  bool max_open = false;  ///< upper bound excluded
  double min = 0;         ///< lower bound
  double max = 0;         ///< upper bound

  bool empty() const { return !has_min && !has_max; }
  /// True when `value` lies inside (NaN never does).
  bool contains(double value) const;
  /// "in (0, 1)", "> 0", ">= 1", "<= 0"; "" when unbounded.
  std::string text() const;
};

/// "`key` is one of `values`": `key` is looked up in the list holding the condition or,
/// failing that, in its enclosing lists (nearest first), so keys of a material's
/// `Initial State` can depend on the material's `Phase Model`. An empty key always holds.
struct Condition {
  std::string key;                  ///< an Enum key; empty: always true
  std::vector<std::string> values;  ///< canonical words for which the condition holds

  bool always() const { return key.empty(); }
  /// "Model is Mohr-Coulomb or suction Mohr-Coulomb".
  std::string text() const;
};

/// A default value of the type of its key (monostate: no default).
using DefaultValue = std::variant<std::monostate, double, long long, bool, std::string,
                                  std::vector<double>, std::vector<std::string>>;

struct ListSchema;

/// The declaration of one key. Built with the factories and chained setters, e.g.
/// `KeySpec::real("Porosity", "-", "initial porosity n0").above(0).below(1).require()`.
struct KeySpec {
  std::string name;              ///< the key as written in the deck
  KeyType type = KeyType::Real;  ///< what it holds
  std::string unit;              ///< SI unit ("Pa", "m/s", "-", "deg"); "" for non-numbers
  std::string doc;               ///< one-line description
  bool required = false;         ///< must be given (when it applies, see required_when)
  Condition applies_when;        ///< the key is allowed only when this holds
  Condition required_when;       ///< if set, `required` holds only when this holds too
  DefaultValue default_value;    ///< used when the key is absent
  Range range;                   ///< bounds of a Real/Integer/RealList element
  std::vector<long long> allowed_integers;     ///< if non-empty, the only integers allowed
  std::vector<std::string> words;              ///< Enum/WordList: the allowed words
  std::size_t list_size = 0;                   ///< RealList: exact length (0: any)
  bool allow_empty_text = false;               ///< String: "" is allowed
  bool needs_entry = false;                    ///< NamedSublists: at least one entry
  std::shared_ptr<const ListSchema> children;  ///< Sublist/NamedSublists: their keys
  std::string entry_label;                     ///< NamedSublists: what an entry is ("material")

  /// Factories, one per type.
  static KeySpec real(std::string name, std::string unit, std::string doc);
  static KeySpec integer(std::string name, std::string doc);
  static KeySpec boolean(std::string name, std::string doc);
  static KeySpec text(std::string name, std::string doc);
  static KeySpec file(std::string name, std::string doc);
  static KeySpec choice(std::string name, std::vector<std::string> words, std::string doc);
  static KeySpec choices(std::string name, std::vector<std::string> words, std::string doc);
  static KeySpec reals(std::string name, std::string unit, std::size_t size, std::string doc);
  static KeySpec sublist(std::string name, ListSchema children, std::string doc);
  static KeySpec namedSublists(std::string name, std::string entry_label, ListSchema children,
                               std::string doc);

  /// Chained setters.
  KeySpec& require();
  KeySpec& requireWhen(std::string key, std::vector<std::string> values);
  KeySpec& when(std::string key, std::vector<std::string> values);
  KeySpec& byDefault(DefaultValue value);
  KeySpec& above(double bound);    ///< > bound
  KeySpec& atLeast(double bound);  ///< >= bound
  KeySpec& below(double bound);    ///< < bound
  KeySpec& atMost(double bound);   ///< <= bound
  KeySpec& onlyIntegers(std::vector<long long> allowed);
  KeySpec& allowEmpty();
  KeySpec& atLeastOneEntry();

  /// True when a default value is declared.
  bool hasDefault() const { return default_value.index() != 0; }
  /// "a real number (Pa)", "one of: x, y, both", ... for messages.
  std::string expectation() const;
};

/// "Exactly one of these keys" (e.g. `Exodus File` or `Generate`), when `applies_when`.
struct OneOf {
  std::vector<std::string> keys;  ///< the alternatives
  Condition applies_when;         ///< the rule holds only when this holds
};

/// The keys of one (sub)list.
struct ListSchema {
  std::vector<KeySpec> keys;          ///< in documentation order
  std::vector<OneOf> exactly_one_of;  ///< alternative groups

  /// Adds a key; returns *this for chaining.
  ListSchema& add(KeySpec key);
  /// Adds an "exactly one of" group.
  ListSchema& exactlyOneOf(std::vector<std::string> keys, Condition applies_when = {});
  /// The key named `name`, or nullptr.
  const KeySpec* find(const std::string& name) const;
};

/// Checks a schema for mistakes of its author (conditions naming unknown keys or words,
/// defaults of the wrong type or out of range, alternatives naming unknown keys). Throws
/// std::logic_error; deckSchema() runs it once.
void checkSchema(const ListSchema& schema);

/// The schema of an argine deck: the keys inside the top-level `argine:` map.
const ListSchema& deckSchema();

/// The whole deck schema as Markdown tables (the content of doc/deck-reference.md, printed
/// by `argine schema`).
std::string deckReferenceMarkdown();

}  // namespace argine
