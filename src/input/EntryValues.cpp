#include "EntryValues.hpp"

#include <Teuchos_Array.hpp>

#include "ValueText.hpp"

namespace argine::input_detail {

namespace {

template <class T>
const T* entryAs(const Teuchos::ParameterEntry& entry) {
  if (entry.isList() || !entry.isType<T>()) return nullptr;
  return &Teuchos::any_cast<T>(entry.getAny(false));
}

template <class T, class Format>
std::string listText(const Teuchos::Array<T>& items, Format format) {
  std::vector<std::string> texts;
  for (const auto& item : items) texts.push_back(format(item));
  return "list [" + joinWords(texts) + "]";
}

}  // namespace

std::string describeEntry(const Teuchos::ParameterEntry& entry) {
  if (entry.isList()) {
    const auto& list = Teuchos::any_cast<Teuchos::ParameterList>(entry.getAny(false));
    return list.numParams() == 0 ? "an empty value" : "a sublist";
  }
  if (const auto* v = entryAs<std::string>(entry)) return "string '" + *v + "'";
  if (const auto* v = entryAs<double>(entry)) return "real number " + formatReal(*v);
  if (const auto* v = entryAs<int>(entry)) return "integer " + std::to_string(*v);
  if (const auto* v = entryAs<long long>(entry)) return "integer " + std::to_string(*v);
  if (const auto* v = entryAs<bool>(entry)) return *v ? "boolean true" : "boolean false";
  if (const auto* v = entryAs<Teuchos::Array<double>>(entry))
    return listText(*v, [](double x) { return formatReal(x); });
  if (const auto* v = entryAs<Teuchos::Array<int>>(entry))
    return listText(*v, [](int x) { return std::to_string(x); });
  if (const auto* v = entryAs<Teuchos::Array<long long>>(entry))
    return listText(*v, [](long long x) { return std::to_string(x); });
  if (const auto* v = entryAs<Teuchos::Array<std::string>>(entry))
    return listText(*v, [](const std::string& x) { return x; });
  return "a value of type " + entry.getAny(false).typeName();
}

std::optional<double> entryReal(const Teuchos::ParameterEntry& entry) {
  if (const auto* v = entryAs<double>(entry)) return *v;
  if (const auto* v = entryAs<int>(entry)) return static_cast<double>(*v);
  if (const auto* v = entryAs<long long>(entry)) return static_cast<double>(*v);
  return std::nullopt;
}

std::optional<std::string> entryText(const Teuchos::ParameterEntry& entry) {
  if (const auto* v = entryAs<std::string>(entry)) return *v;
  if (const auto* v = entryAs<int>(entry)) return std::to_string(*v);
  if (const auto* v = entryAs<long long>(entry)) return std::to_string(*v);
  return std::nullopt;
}

std::optional<std::vector<double>> entryReals(const Teuchos::ParameterEntry& entry) {
  if (const auto* v = entryAs<Teuchos::Array<double>>(entry))
    return std::vector<double>(v->begin(), v->end());
  if (const auto* v = entryAs<Teuchos::Array<int>>(entry))
    return std::vector<double>(v->begin(), v->end());
  if (const auto* v = entryAs<Teuchos::Array<long long>>(entry))
    return std::vector<double>(v->begin(), v->end());
  return std::nullopt;
}

std::optional<std::vector<std::string>> entryWords(const Teuchos::ParameterEntry& entry) {
  if (const auto* v = entryAs<std::string>(entry)) return splitCommaList(*v);
  if (const auto* v = entryAs<Teuchos::Array<std::string>>(entry)) {
    std::vector<std::string> words;
    for (const auto& item : *v)
      if (!trim(item).empty()) words.push_back(trim(item));
    return words;
  }
  return std::nullopt;
}

std::optional<std::vector<std::string>> entryTextList(const Teuchos::ParameterEntry& entry) {
  if (const auto* v = entryAs<Teuchos::Array<std::string>>(entry))
    return std::vector<std::string>(v->begin(), v->end());
  return std::nullopt;
}

}  // namespace argine::input_detail
