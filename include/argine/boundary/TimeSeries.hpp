#pragma once
/// @file TimeSeries.hpp
/// A value that changes in time, as a table of (time, value) rows interpolated linearly and
/// clamped at both ends (thesis Sec. 4.1: "a series of hydraulic head values in time, like
/// the ones provided by water gauges readings ... computed by linear interpolation"). Used
/// by the hydraulic boundary conditions (head, pressure, infiltration flux) of the explicit
/// solver and meant for the implicit seepage solver too.
///
/// Sources: a constant, an inline table (t0, v0, t1, v1, ...) or a CSV file with two
/// columns `time, value` (an optional header line of non-numbers, `#` comment lines and
/// blank lines are skipped; separators comma, semicolon, tab or spaces). Times must
/// increase strictly. Errors are InputError with `where` = the deck key and the file named.

#include <string>
#include <vector>

#include "argine/core/Types.hpp"

namespace argine {

class TimeSeries {
 public:
  /// The constant 0.
  TimeSeries() = default;
  /// A constant value at all times.
  static TimeSeries constant(Real value);
  /// From rows (times strictly increasing, at least one row); InputError(where) otherwise.
  static TimeSeries fromRows(std::vector<Real> times, std::vector<Real> values,
                             const std::string& where);
  /// From a flat list t0, v0, t1, v1, ... (an even count, at least 2 numbers).
  static TimeSeries fromPairs(const std::vector<Real>& pairs, const std::string& where);
  /// From a two-column CSV file (see the file comment). InputError(where, "... <path> ...")
  /// for a missing or unreadable file, a row that is not two numbers, no rows, or times
  /// that do not increase.
  static TimeSeries fromCsvFile(const std::string& path, const std::string& where);

  /// The value at `time`: linear between rows, the first/last value before/after the table.
  Real at(Real time) const;
  /// The same rows with every time increased by `offset` (s): a table whose times count
  /// from a stage's start, moved onto the simulation clock (offset = the stage's start).
  TimeSeries shifted(Real offset) const;

  const std::vector<Real>& times() const { return times_; }
  const std::vector<Real>& values() const { return values_; }
  bool isConstant() const { return times_.size() <= 1; }

 private:
  std::vector<Real> times_{0.0};
  std::vector<Real> values_{0.0};
};

/// Linear interpolation clamped at the ends on rows (t, v) with t strictly increasing:
/// the formula behind TimeSeries::at, for one place to test it.
Real interpolateClamped(const std::vector<Real>& times, const std::vector<Real>& values, Real time);

}  // namespace argine
