#include "argine/boundary/TimeSeries.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "argine/core/Error.hpp"

namespace argine {

namespace {

/// Splits a CSV line on commas, semicolons, tabs and spaces (empty fields dropped).
std::vector<std::string> fields(const std::string& line) {
  std::vector<std::string> out;
  std::string field;
  for (const char c : line) {
    if (c == ',' || c == ';' || c == '\t' || c == ' ' || c == '\r') {
      if (!field.empty()) out.push_back(field);
      field.clear();
    } else {
      field += c;
    }
  }
  if (!field.empty()) out.push_back(field);
  return out;
}

/// InputError(where, prefix + ...) unless times increase strictly.
void checkIncreasing(const std::vector<Real>& times, const std::string& where,
                     const std::string& prefix) {
  for (std::size_t k = 1; k < times.size(); ++k)
    if (!(times[k] > times[k - 1])) {
      std::ostringstream out;
      out << prefix << "times must increase strictly: row " << k + 1 << " has t = " << times[k]
          << " s after t = " << times[k - 1] << " s";
      throw InputError(where, out.str());
    }
}

bool parseNumber(const std::string& text, Real& value) {
  char* end = nullptr;
  value = std::strtod(text.c_str(), &end);
  return end != text.c_str() && *end == '\0' && std::isfinite(value);
}

}  // namespace

Real interpolateClamped(const std::vector<Real>& times, const std::vector<Real>& values,
                        Real time) {
  if (times.size() == 1 || time <= times.front()) return values.front();
  if (time >= times.back()) return values.back();
  // first row with t > time; the row before it has t <= time
  const auto upper = std::upper_bound(times.begin(), times.end(), time);
  const std::size_t k = static_cast<std::size_t>(upper - times.begin());
  const Real fraction = (time - times[k - 1]) / (times[k] - times[k - 1]);
  return values[k - 1] + fraction * (values[k] - values[k - 1]);
}

TimeSeries TimeSeries::constant(Real value) {
  TimeSeries series;
  series.values_ = {value};
  return series;
}

TimeSeries TimeSeries::fromRows(std::vector<Real> times, std::vector<Real> values,
                                const std::string& where) {
  if (times.empty() || times.size() != values.size())
    throw InputError(where, "a time series needs at least one (time, value) row");
  checkIncreasing(times, where, "");
  TimeSeries series;
  series.times_ = std::move(times);
  series.values_ = std::move(values);
  return series;
}

TimeSeries TimeSeries::fromPairs(const std::vector<Real>& pairs, const std::string& where) {
  if (pairs.size() < 2 || pairs.size() % 2 != 0)
    throw InputError(where,
                     "expected time, value pairs (an even count of at least 2 numbers), "
                     "got " +
                         std::to_string(pairs.size()) + " numbers");
  std::vector<Real> times, values;
  for (std::size_t k = 0; k < pairs.size(); k += 2) {
    times.push_back(pairs[k]);
    values.push_back(pairs[k + 1]);
  }
  return fromRows(std::move(times), std::move(values), where);
}

TimeSeries TimeSeries::fromCsvFile(const std::string& path, const std::string& where) {
  std::ifstream file(path);
  if (!file) throw InputError(where, "cannot open the time-series file '" + path + "'");
  std::vector<Real> times, values;
  std::string line;
  int number = 0;
  bool header_allowed = true;
  while (std::getline(file, line)) {
    ++number;
    const auto parts = fields(line);
    if (parts.empty() || parts[0][0] == '#') continue;
    Real t = 0, v = 0;
    const bool numbers = parts.size() >= 2 && parseNumber(parts[0], t) && parseNumber(parts[1], v);
    if (!numbers && header_allowed) {  // one header line before the first row
      header_allowed = false;
      continue;
    }
    if (!numbers || parts.size() != 2)
      throw InputError(where, "time-series file '" + path + "' line " + std::to_string(number) +
                                  ": expected two numbers 'time, value', got '" + line + "'");
    header_allowed = false;
    times.push_back(t);
    values.push_back(v);
  }
  if (times.empty())
    throw InputError(where, "time-series file '" + path + "' has no (time, value) rows");
  checkIncreasing(times, where, "time-series file '" + path + "': ");
  return fromRows(std::move(times), std::move(values), where);
}

Real TimeSeries::at(Real time) const {
  return interpolateClamped(times_, values_, time);
}

TimeSeries TimeSeries::shifted(Real offset) const {
  TimeSeries moved = *this;
  for (Real& t : moved.times_) t += offset;
  return moved;
}

}  // namespace argine
