// doc/deck-reference.md, rendered from the schema (`argine schema` prints it).
#include <sstream>

#include "ValueText.hpp"
#include "argine/input/DeckSchema.hpp"

namespace argine {

using namespace input_detail;

namespace {

constexpr const char* kIntroduction =
    R"(# Deck reference

<!-- Generated from the deck schema (src/input/DeckKeys.cpp) by `argine schema`.
     Do not edit by hand: run `argine schema > doc/deck-reference.md`. -->

An argine deck is a YAML file holding one map, `argine:`, with the keys below. The deck is
checked completely before anything runs; any problem stops `argine` with exit code 2 and a
message naming the key path (for example
`Stages/flood/Boundary Conditions/river/Pressure (Pa)`) and what was expected.

- **Units** are SI and part of the key name (`Young's Modulus (Pa)`); angles are in degrees
  (`(deg)`), converted to radians on reading. Unit `-` means dimensionless.
- **Numbers**: integers are accepted where real numbers are meant (`3600`); an integer key
  rejects a fractional part. NaN and infinity are rejected. Write `0.5` and `-0.5`, not
  `.5` or `-.5` (the YAML reader of Teuchos cannot read those).
- **Words** (type *word*) are matched ignoring case. A list of words is a YAML list
  (`[cfl dry, consolidation]`) or one comma-separated string (`"cfl dry, consolidation"`).
- **Named sublists**: `Materials`, `Stages`, `Boundary Conditions` and `Regions` map names
  you choose (written `<material>`, `<stage>`, ... below) to sublists that all have the same
  keys. Stages run in the order written. (Teuchos YAML has no lists of maps.)
- **Keys not listed are rejected**, with a suggestion when one is close. A key whose *When*
  column is filled is allowed only then (a cohesion makes no sense for a linear elastic
  solid) and a required key is required only then.
- **Files** are relative to the deck's directory and must exist.
- **Sign conventions**: stresses are tension positive; liquid pressure p_L is compression
  positive; suction s = -p_L where p_L < 0.
)";

std::string cell(std::string text) {
  std::string escaped;
  for (char c : text) {
    if (c == '|') escaped += '\\';
    escaped += c;
  }
  return escaped;
}

std::string code(const std::string& text) {
  return "`" + text + "`";
}

std::string typeName(const KeySpec& key) {
  switch (key.type) {
    case KeyType::Real:
      return "real";
    case KeyType::Integer:
      return "integer";
    case KeyType::Bool:
      return "true/false";
    case KeyType::String:
      return "name";
    case KeyType::FilePath:
      return "file";
    case KeyType::Enum:
      return "word";
    case KeyType::WordList:
      return "words";
    case KeyType::RealList:
      return key.list_size ? "list of " + std::to_string(key.list_size) + " reals"
                           : std::string("list of reals");
    case KeyType::Sublist:
      return "sublist";
    case KeyType::NamedSublists:
      return "named sublists";
  }
  return "";
}

std::string allowed(const KeySpec& key) {
  if (key.type == KeyType::Enum || key.type == KeyType::WordList) {
    std::vector<std::string> words;
    for (const auto& word : key.words) words.push_back(code(word));
    return joinWords(words);
  }
  if (!key.allowed_integers.empty()) {
    std::vector<std::string> values;
    for (long long value : key.allowed_integers) values.push_back(std::to_string(value));
    return joinWords(values);
  }
  if (key.type == KeyType::NamedSublists && key.needs_entry) return "at least one";
  if (key.type == KeyType::RealList && !key.range.empty()) return "each " + key.range.text();
  return key.range.text();
}

std::string requirement(const KeySpec& key) {
  if (key.required)
    return key.required_when.always() ? std::string("**required**")
                                      : "required when " + key.required_when.text();
  if (key.hasDefault()) {
    const std::string value = formatDefault(key.default_value);
    return value.empty() ? std::string("\"\"") : code(value);
  }
  return "optional";
}

std::string childPath(const std::string& path, const KeySpec& key) {
  const std::string base = path.empty() ? key.name : path + "/" + key.name;
  return key.type == KeyType::NamedSublists ? base + "/<" + key.entry_label + ">" : base;
}

void renderList(std::ostringstream& out, const ListSchema& schema, const std::string& path) {
  // In back quotes, so that Markdown keeps `<material>` instead of reading an HTML tag.
  out << "\n## " << code(path.empty() ? std::string("argine") : "argine/" + path) << "\n\n";
  out << "| Key | Type | Unit | Default | Allowed | When | Description |\n";
  out << "|---|---|---|---|---|---|---|\n";
  for (const auto& key : schema.keys) {
    std::string doc = key.doc;
    if (key.children) doc += "; see " + code("argine/" + childPath(path, key));
    out << "| " << cell(code(key.name)) << " | " << typeName(key) << " | " << cell(key.unit)
        << " | " << cell(requirement(key)) << " | " << cell(allowed(key)) << " | "
        << cell(key.applies_when.always() ? "" : key.applies_when.text()) << " | " << cell(doc)
        << " |\n";
  }
  for (const auto& group : schema.exactly_one_of) {
    std::vector<std::string> names;
    for (const auto& name : group.keys) names.push_back(code(name));
    out << "\nGive exactly one of " << joinWords(names, " or ");
    if (!group.applies_when.always()) out << " when " << group.applies_when.text();
    out << ".\n";
  }
  for (const auto& key : schema.keys)
    if (key.children) renderList(out, *key.children, childPath(path, key));
}

}  // namespace

std::string deckReferenceMarkdown() {
  std::ostringstream out;
  out << kIntroduction;
  renderList(out, deckSchema(), "");
  return out.str();
}

}  // namespace argine
