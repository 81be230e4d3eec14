#include "DeckSection.hpp"

#include <stdexcept>

#include "EntryValues.hpp"
#include "ValueText.hpp"
#include "argine/input/DeckValidator.hpp"

namespace argine::input_detail {

namespace {
const Teuchos::ParameterList& emptyList() {
  static const Teuchos::ParameterList empty;
  return empty;
}
}  // namespace

DeckSection::DeckSection(const Teuchos::ParameterList& list, const ListSchema& schema,
                         std::string path, std::string base_directory, std::string name)
    : list_(&list),
      schema_(&schema),
      path_(std::move(path)),
      base_directory_(std::move(base_directory)),
      name_(std::move(name)) {}

std::string DeckSection::pathOf(const std::string& key) const {
  return path_.empty() ? key : path_ + "/" + key;
}

const KeySpec& DeckSection::spec(const std::string& key, KeyType type) const {
  const KeySpec* found = schema_->find(key);
  if (!found) throw std::logic_error("deck reader: '" + pathOf(key) + "' is not in the schema");
  if (found->type != type)
    throw std::logic_error("deck reader: '" + pathOf(key) + "' read with the wrong type");
  return *found;
}

const Teuchos::ParameterEntry* DeckSection::entry(const std::string& key) const {
  return list_->getEntryPtr(key);
}

void DeckSection::missing(const std::string& key) const {
  throw std::logic_error("deck reader: '" + pathOf(key) + "' is absent and has no default");
}

bool DeckSection::has(const std::string& key) const {
  if (!schema_->find(key))
    throw std::logic_error("deck reader: '" + pathOf(key) + "' is not in the schema");
  return list_->isParameter(key);
}

double DeckSection::real(const std::string& key) const {
  const KeySpec& s = spec(key, KeyType::Real);
  if (const auto* e = entry(key)) return *entryReal(*e);
  if (!s.hasDefault()) missing(key);
  return std::get<double>(s.default_value);
}

long long DeckSection::integer(const std::string& key) const {
  const KeySpec& s = spec(key, KeyType::Integer);
  if (const auto* e = entry(key)) return static_cast<long long>(*entryReal(*e));
  if (!s.hasDefault()) missing(key);
  return std::get<long long>(s.default_value);
}

bool DeckSection::boolean(const std::string& key) const {
  const KeySpec& s = spec(key, KeyType::Bool);
  if (const auto* e = entry(key)) return Teuchos::any_cast<bool>(e->getAny(false));
  if (!s.hasDefault()) missing(key);
  return std::get<bool>(s.default_value);
}

std::string DeckSection::text(const std::string& key) const {
  const KeySpec& s = spec(key, KeyType::String);
  if (const auto* e = entry(key)) return trim(*entryText(*e));
  if (!s.hasDefault()) missing(key);
  return std::get<std::string>(s.default_value);
}

std::string DeckSection::word(const std::string& key) const {
  const KeySpec& s = spec(key, KeyType::Enum);
  if (const auto* e = entry(key)) return matchWord(s.words, *entryText(*e));
  if (!s.hasDefault()) missing(key);
  return std::get<std::string>(s.default_value);
}

std::vector<std::string> DeckSection::words(const std::string& key) const {
  const KeySpec& s = spec(key, KeyType::WordList);
  if (const auto* e = entry(key)) {
    const std::vector<std::string> given = *entryWords(*e);
    std::vector<std::string> canonical;
    for (const auto& item : given) canonical.push_back(matchWord(s.words, item));
    return canonical;
  }
  if (!s.hasDefault()) missing(key);
  return std::get<std::vector<std::string>>(s.default_value);
}

std::vector<double> DeckSection::reals(const std::string& key) const {
  const KeySpec& s = spec(key, KeyType::RealList);
  if (const auto* e = entry(key)) return *entryReals(*e);
  if (!s.hasDefault()) missing(key);
  return std::get<std::vector<double>>(s.default_value);
}

std::string DeckSection::file(const std::string& key) const {
  spec(key, KeyType::FilePath);
  if (const auto* e = entry(key)) return resolveDeckFile(base_directory_, trim(*entryText(*e)));
  missing(key);
}

DeckSection DeckSection::section(const std::string& key) const {
  const KeySpec& s = spec(key, KeyType::Sublist);
  const auto* e = entry(key);
  const auto& list = e ? Teuchos::any_cast<Teuchos::ParameterList>(e->getAny(false)) : emptyList();
  return DeckSection(list, *s.children, pathOf(key), base_directory_);
}

std::vector<DeckSection> DeckSection::entries(const std::string& key) const {
  const KeySpec& s = spec(key, KeyType::NamedSublists);
  std::vector<DeckSection> sections;
  const auto* e = entry(key);
  if (!e) return sections;
  const auto& map = Teuchos::any_cast<Teuchos::ParameterList>(e->getAny(false));
  for (auto it = map.begin(); it != map.end(); ++it)
    sections.emplace_back(Teuchos::any_cast<Teuchos::ParameterList>(map.entry(it).getAny(false)),
                          *s.children, pathOf(key) + "/" + map.name(it), base_directory_,
                          map.name(it));
  return sections;
}

}  // namespace argine::input_detail
