// compare_results DIR_A DIR_B TOLERANCE: the Exodus (*.e, *.e-s*) and CSV files of two runs
// of the same deck agree to TOLERANCE, relative to the largest magnitude of each quantity
// (a nodal variable at one time step, a CSV column). Same files, steps, times, node ids and
// rows; NaN at the same places. Prints the largest difference per file; exit 0 when all
// agree, 1 otherwise. Used by two_ranks_case.sh (1 vs 2 MPI ranks, doc/parallel.md).
#include <exodusII.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

int failures = 0;

void fail(const std::string& what) {
  std::printf("FAIL: %s\n", what.c_str());
  ++failures;
}

// Largest |a - b| / max |a| (0 when both are all zero); -1 when NaNs differ in place.
double relativeDifference(const std::vector<double>& a, const std::vector<double>& b) {
  double scale = 0, difference = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (std::isnan(a[i]) != std::isnan(b[i])) return -1;
    if (std::isnan(a[i])) continue;
    scale = std::max(scale, std::fabs(a[i]));
    difference = std::max(difference, std::fabs(a[i] - b[i]));
  }
  return difference == 0 ? 0 : difference / scale;
}

struct Exodus {
  int id = -1;
  explicit Exodus(const fs::path& path) {
    int cpu = sizeof(double), io = 0;
    float version = 0;
    id = ex_open(path.c_str(), EX_READ, &cpu, &io, &version);
    if (id >= 0) ex_set_max_name_length(id, ex_inquire_int(id, EX_INQ_DB_MAX_USED_NAME_LENGTH));
  }
  ~Exodus() {
    if (id >= 0) ex_close(id);
  }
  int count(ex_inquiry what) const { return static_cast<int>(ex_inquire_int(id, what)); }
  std::vector<std::string> variables() const {
    int n = 0;
    ex_get_variable_param(id, EX_NODAL, &n);
    std::vector<std::vector<char>> buffers(n, std::vector<char>(257, '\0'));
    std::vector<char*> pointers;
    for (auto& b : buffers) pointers.push_back(b.data());
    if (n > 0) ex_get_variable_names(id, EX_NODAL, n, pointers.data());
    std::vector<std::string> names;
    for (auto& b : buffers) names.emplace_back(b.data());
    return names;
  }
  std::vector<double> nodal(int step, int variable) const {
    std::vector<double> values(count(EX_INQ_NODES));
    ex_get_var(id, step, EX_NODAL, variable, 1, static_cast<int>(values.size()), values.data());
    return values;
  }
  std::vector<double> idMap() const {
    std::vector<int> map(count(EX_INQ_NODES));
    if (!map.empty()) ex_get_id_map(id, EX_NODE_MAP, map.data());
    return std::vector<double>(map.begin(), map.end());
  }
  std::vector<double> coordinates() const {
    const int n = count(EX_INQ_NODES);
    std::vector<double> x(n), y(n);
    if (n > 0) ex_get_coord(id, x.data(), y.data(), nullptr);
    x.insert(x.end(), y.begin(), y.end());
    return x;
  }
  std::vector<double> times() const {
    std::vector<double> t(count(EX_INQ_TIME));
    if (!t.empty()) ex_get_all_times(id, t.data());
    return t;
  }
};

void compareExodus(const fs::path& a_path, const fs::path& b_path, double tolerance) {
  const Exodus a(a_path), b(b_path);
  const std::string name = a_path.filename().string();
  if (a.id < 0 || b.id < 0) return fail(name + ": cannot open");
  if (a.count(EX_INQ_NODES) != b.count(EX_INQ_NODES)) return fail(name + ": node counts");
  if (a.idMap() != b.idMap()) return fail(name + ": node ids differ");
  if (a.variables() != b.variables()) return fail(name + ": variable names");
  double worst = std::max(relativeDifference(a.coordinates(), b.coordinates()),
                          relativeDifference(a.times(), b.times()));
  std::string where = "coordinates/times";
  if (a.times().size() != b.times().size()) return fail(name + ": time step counts");
  const auto names = a.variables();
  for (int step = 1; step <= static_cast<int>(a.times().size()); ++step)
    for (int v = 0; v < static_cast<int>(names.size()); ++v) {
      const double d = relativeDifference(a.nodal(step, v + 1), b.nodal(step, v + 1));
      if (d < 0) return fail(name + ": NaN in different places: " + names[v]);
      if (d > worst) worst = d, where = names[v] + " at step " + std::to_string(step);
    }
  std::printf("%-40s %3zu steps %6d nodes: largest relative difference %.3g (%s)\n", name.c_str(),
              a.times().size(), a.count(EX_INQ_NODES), worst, where.c_str());
  if (!(worst <= tolerance)) fail(name + ": beyond the tolerance");
}

std::vector<std::vector<double>> readCsv(const fs::path& path, std::string& header) {
  std::ifstream in(path);
  std::getline(in, header);
  std::vector<std::vector<double>> columns;
  std::string line;
  while (std::getline(in, line)) {
    std::stringstream cells(line);
    std::string cell;
    for (std::size_t c = 0; std::getline(cells, cell, ','); ++c) {
      if (columns.size() <= c) columns.resize(c + 1);
      columns[c].push_back(std::strtod(cell.c_str(), nullptr));  // "nan" -> NaN
    }
  }
  return columns;
}

void compareCsv(const fs::path& a_path, const fs::path& b_path, double tolerance) {
  std::string a_header, b_header;
  const auto a = readCsv(a_path, a_header), b = readCsv(b_path, b_header);
  const std::string name = a_path.filename().string();
  if (a_header != b_header) return fail(name + ": headers differ");
  if (a.size() != b.size()) return fail(name + ": column counts");
  double worst = 0;
  std::size_t worst_column = 0;
  for (std::size_t c = 0; c < a.size(); ++c) {
    if (a[c].size() != b[c].size()) return fail(name + ": row counts");
    const double d = relativeDifference(a[c], b[c]);
    if (d < 0) return fail(name + ": NaN in different places, column " + std::to_string(c));
    if (d > worst) worst = d, worst_column = c;
  }
  std::printf("%-40s %3zu rows: largest relative difference %.3g (column %zu)\n", name.c_str(),
              a.empty() ? 0 : a[0].size(), worst, worst_column);
  if (!(worst <= tolerance)) fail(name + ": beyond the tolerance");
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 4) {
    std::fprintf(stderr, "usage: compare_results DIR_A DIR_B TOLERANCE\n");
    return 2;
  }
  const fs::path a_dir = argv[1], b_dir = argv[2];
  const double tolerance = std::strtod(argv[3], nullptr);
  std::vector<std::string> a_files, b_files;
  for (const auto& entry : fs::directory_iterator(a_dir))
    a_files.push_back(entry.path().filename());
  for (const auto& entry : fs::directory_iterator(b_dir))
    b_files.push_back(entry.path().filename());
  std::sort(a_files.begin(), a_files.end());
  std::sort(b_files.begin(), b_files.end());
  if (a_files != b_files) fail("the two directories hold different files");
  if (a_files.empty()) fail("no files");
  for (const auto& file : a_files) {
    if (!fs::exists(b_dir / file)) continue;
    if (file.size() > 4 && file.compare(file.size() - 4, 4, ".csv") == 0)
      compareCsv(a_dir / file, b_dir / file, tolerance);
    else if (file.find(".e") != std::string::npos)
      compareExodus(a_dir / file, b_dir / file, tolerance);
  }
  std::printf("%s (tolerance %.3g)\n", failures ? "DIFFERENT" : "same to round-off", tolerance);
  return failures ? 1 : 0;
}
