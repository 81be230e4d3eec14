#pragma once
// Typed read access to a validated parameter list (private to the input room). Every read
// names a key of the schema: absent keys give their declared default, so defaults live
// only in the schema. Reading an undeclared key, or an absent key without default, is a
// bug in the reader and throws std::logic_error.

#include <string>
#include <vector>

#include <Teuchos_ParameterList.hpp>

#include "argine/input/DeckSchema.hpp"

namespace argine::input_detail {

class DeckSection {
 public:
  /// `list` must have passed validateParameters against `schema`.
  DeckSection(const Teuchos::ParameterList& list, const ListSchema& schema, std::string path,
              std::string base_directory, std::string name = "");

  /// Key path of this section ("Materials/soil"); "" at the top.
  const std::string& path() const { return path_; }
  /// Key path of a key of this section.
  std::string pathOf(const std::string& key) const;
  /// The entry's name in its map of named sublists ("" for other sections).
  const std::string& name() const { return name_; }

  bool has(const std::string& key) const;
  double real(const std::string& key) const;
  long long integer(const std::string& key) const;
  bool boolean(const std::string& key) const;
  std::string text(const std::string& key) const;
  /// The canonical word of an Enum key.
  std::string word(const std::string& key) const;
  /// The canonical words of a WordList key, in the order given.
  std::vector<std::string> words(const std::string& key) const;
  std::vector<double> reals(const std::string& key) const;
  /// A FilePath key as an absolute path.
  std::string file(const std::string& key) const;
  /// A Sublist key (empty, so all defaults, when absent).
  DeckSection section(const std::string& key) const;
  /// The entries of a NamedSublists key, in deck order (none when absent).
  std::vector<DeckSection> entries(const std::string& key) const;

 private:
  const KeySpec& spec(const std::string& key, KeyType type) const;
  const Teuchos::ParameterEntry* entry(const std::string& key) const;
  [[noreturn]] void missing(const std::string& key) const;

  const Teuchos::ParameterList* list_;
  const ListSchema* schema_;
  std::string path_;
  std::string base_directory_;
  std::string name_;
};

}  // namespace argine::input_detail
