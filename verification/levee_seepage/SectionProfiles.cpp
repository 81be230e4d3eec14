#include "SectionProfiles.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <tuple>

namespace argine::verification::v4 {

namespace {

std::vector<std::string> splitCsvLine(const std::string& line) {
  std::vector<std::string> cells;
  std::stringstream ss(line);
  std::string cell;
  while (std::getline(ss, cell, ',')) cells.push_back(cell);
  return cells;
}

/// The constant term a of the least-squares plane through the rows within half_height of y, for
/// p and S; NaN with fewer than 3 rows or a singular system.
std::pair<Real, Real> planeFit(const std::vector<const PointRow*>& rows, Real xs, Real y,
                               Real half_height) {
  Real A[3][3] = {}, bp[3] = {}, bs[3] = {};
  int count = 0;
  for (const PointRow* r : rows) {
    if (std::fabs(r->y - y) > half_height) continue;
    const Real phi[3] = {1, r->x - xs, r->y - y};
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) A[i][j] += phi[i] * phi[j];
      bp[i] += phi[i] * r->p;
      bs[i] += phi[i] * r->s;
    }
    ++count;
  }
  const Real nan = std::nan("");
  if (count < 3) return {nan, nan};
  // Cramer's rule for the constant term a (3 x 3).
  auto det = [](const Real m[3][3]) {
    return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
           m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
           m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
  };
  const Real d = det(A);
  if (std::fabs(d) < 1e-30) return {nan, nan};
  auto first = [&](const Real b[3]) {
    Real m[3][3];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) m[i][j] = j == 0 ? b[i] : A[i][j];
    return det(m) / d;
  };
  return {first(bp), first(bs)};
}

}  // namespace

std::vector<Real> sampleHeights() {
  std::vector<Real> y;
  for (int k = 0; k < 30; ++k) y.push_back(0.0125 + 0.025 * k);
  return y;
}

Samples fitRows(const std::vector<PointRow>& rows, Real half_height) {
  Samples out;
  const std::vector<Real> heights = sampleHeights();
  for (const Real t : kTimes)
    for (const auto& [name, xs] : kSections) {
      std::vector<const PointRow*> chosen;
      for (const PointRow& r : rows)
        if (std::fabs(r.t - t) < 1e-6 && r.section == name) chosen.push_back(&r);
      for (const Real y : heights) {
        const auto [p, s] = planeFit(chosen, xs, y, half_height);
        out.p.push_back(p);
        out.s.push_back(s);
      }
    }
  return out;
}

std::vector<PointRow> readSectionCsv(const std::string& path) {
  std::vector<PointRow> rows;
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);  // header
  while (std::getline(in, line)) {
    const std::vector<std::string> cells = splitCsvLine(line);
    if (cells.size() < 6) continue;
    rows.push_back({std::stod(cells[0]), std::stod(cells[2]), std::stod(cells[3]),
                    std::stod(cells[4]), std::stod(cells[5]), cells[1]});
  }
  return rows;
}

Samples readProfiles(const std::string& path, const std::string& run) {
  // (time, section, height index) -> (p, S)
  std::map<std::tuple<long, std::string, long>, std::pair<Real, Real>> found;
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);  // header
  while (std::getline(in, line)) {
    const std::vector<std::string> cells = splitCsvLine(line);
    if (cells.size() < 6 || cells[0] != run) continue;
    const long t = std::lround(std::stod(cells[1]));
    const long k = std::lround((std::stod(cells[3]) - 0.0125) / 0.025);
    found[{t, cells[2], k}] = {std::stod(cells[4]), std::stod(cells[5])};
  }
  Samples samples;
  if (found.empty()) return samples;
  const Real nan = std::nan("");
  for (const Real t : kTimes)
    for (const auto& section : kSections)
      for (long k = 0; k < static_cast<long>(sampleHeights().size()); ++k) {
        const auto it = found.find({std::lround(t), section.first, k});
        samples.p.push_back(it == found.end() ? nan : it->second.first);
        samples.s.push_back(it == found.end() ? nan : it->second.second);
      }
  return samples;
}

Errors compare(const Samples& a, const Samples& reference) {
  Real pmin = 1e300, pmax = -1e300, smin = 1e300, smax = -1e300;
  for (std::size_t k = 0; k < reference.p.size(); ++k) {
    if (std::isnan(reference.p[k])) continue;
    pmin = std::min(pmin, reference.p[k]), pmax = std::max(pmax, reference.p[k]);
    smin = std::min(smin, reference.s[k]), smax = std::max(smax, reference.s[k]);
  }
  Errors e;
  for (std::size_t k = 0; k < reference.p.size() && k < a.p.size(); ++k) {
    if (std::isnan(reference.p[k]) || std::isnan(a.p[k])) continue;
    e.p = std::max(e.p, std::fabs(a.p[k] - reference.p[k]) / (pmax - pmin));
    e.s = std::max(e.s, std::fabs(a.s[k] - reference.s[k]) / (smax - smin));
    ++e.compared;
  }
  return e;
}

}  // namespace argine::verification::v4
