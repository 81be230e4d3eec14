#include "ValueText.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace argine::input_detail {

std::string lower(std::string text) {
  for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

std::string formatReal(double value) {
  if (!std::isfinite(value)) return std::isnan(value) ? "nan" : (value > 0 ? "inf" : "-inf");
  char buffer[64];
  int precision = 1;
  for (; precision < 17; ++precision) {
    std::snprintf(buffer, sizeof buffer, "%.*g", precision, value);
    if (std::strtod(buffer, nullptr) == value) break;
  }
  // Numbers below a million read better without exponent: 90, 1000, 101325.
  const int exponent = value == 0 ? 0 : static_cast<int>(std::floor(std::log10(std::abs(value))));
  if (exponent >= 0 && exponent < 6) precision = std::max(precision, exponent + 1);
  std::snprintf(buffer, sizeof buffer, "%.*g", precision, value);
  // %g writes "2.2e+09"; the reference reads better as "2.2e9".
  std::string text = buffer;
  const auto e = text.find('e');
  if (e != std::string::npos) {
    std::string mantissa = text.substr(0, e);
    std::string exponent = text.substr(e + 1);
    std::string sign;
    if (exponent[0] == '+' || exponent[0] == '-') {
      if (exponent[0] == '-') sign = "-";
      exponent = exponent.substr(1);
    }
    while (exponent.size() > 1 && exponent[0] == '0') exponent = exponent.substr(1);
    text = mantissa + "e" + sign + exponent;
  }
  return text;
}

std::string formatDefault(const DefaultValue& value) {
  struct Visitor {
    std::string operator()(std::monostate) const { return ""; }
    std::string operator()(double v) const { return formatReal(v); }
    std::string operator()(long long v) const { return std::to_string(v); }
    std::string operator()(bool v) const { return v ? "true" : "false"; }
    std::string operator()(const std::string& v) const { return v; }
    std::string operator()(const std::vector<double>& v) const {
      std::vector<std::string> items;
      for (double x : v) items.push_back(formatReal(x));
      return "[" + joinWords(items) + "]";
    }
    std::string operator()(const std::vector<std::string>& v) const { return joinWords(v); }
  };
  return std::visit(Visitor{}, value);
}

std::string joinWords(const std::vector<std::string>& words, const std::string& separator) {
  std::string text;
  for (std::size_t i = 0; i < words.size(); ++i) text += (i ? separator : "") + words[i];
  return text;
}

std::string trim(const std::string& text) {
  const auto first = text.find_first_not_of(" \t\r\n");
  if (first == std::string::npos) return "";
  const auto last = text.find_last_not_of(" \t\r\n");
  return text.substr(first, last - first + 1);
}

std::string matchWord(const std::vector<std::string>& words, const std::string& value) {
  const std::string wanted = lower(trim(value));
  for (const auto& word : words)
    if (lower(word) == wanted) return word;
  return "";
}

std::vector<std::string> splitCommaList(const std::string& text) {
  std::vector<std::string> items;
  std::size_t start = 0;
  while (start <= text.size()) {
    const auto comma = text.find(',', start);
    const std::string item =
        trim(text.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
    if (!item.empty()) items.push_back(item);
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return items;
}

bool namesNonFiniteNumber(const std::string& text) {
  std::string word = lower(trim(text));
  if (!word.empty() && (word[0] == '+' || word[0] == '-')) word = word.substr(1);
  if (!word.empty() && word[0] == '.') word = word.substr(1);
  if (word == "nan" || word == "inf" || word == "infinity") return true;
  // Numbers beyond the range of a double ("1e999") are infinite too.
  const std::string trimmed = trim(text);
  if (trimmed.empty()) return false;
  char* end = nullptr;
  errno = 0;
  const double value = std::strtod(trimmed.c_str(), &end);
  return *end == '\0' && (!std::isfinite(value) || errno == ERANGE) && value != 0.0;
}

bool namesFiniteNumber(const std::string& text) {
  const std::string trimmed = trim(text);
  if (trimmed.empty()) return false;
  char* end = nullptr;
  const double value = std::strtod(trimmed.c_str(), &end);
  return *end == '\0' && std::isfinite(value) && !namesNonFiniteNumber(trimmed);
}

}  // namespace argine::input_detail
