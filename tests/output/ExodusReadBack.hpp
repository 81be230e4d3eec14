#pragma once
// Reads Exodus results back through the exodus API, for the round-trip tests.
#include <exodusII.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace argine::test {

/// An Exodus file opened read-only, with the few queries the tests need.
class ExodusReadBack {
 public:
  explicit ExodusReadBack(const std::string& path) {
    int cpu_word_size = sizeof(double);
    int io_word_size = 0;
    float version = 0.0f;
    id_ = ex_open(path.c_str(), EX_READ, &cpu_word_size, &io_word_size, &version);
    if (id_ < 0) {
      ADD_FAILURE() << "cannot open " << path;
      return;
    }
    // Read names as long as the file stores them (the API default truncates at 32).
    ex_set_max_name_length(id_, static_cast<int>(count(EX_INQ_DB_MAX_USED_NAME_LENGTH)));
  }
  ~ExodusReadBack() {
    if (id_ >= 0) ex_close(id_);
  }
  ExodusReadBack(const ExodusReadBack&) = delete;
  ExodusReadBack& operator=(const ExodusReadBack&) = delete;

  bool ok() const { return id_ >= 0; }
  int64_t count(ex_inquiry what) const { return ex_inquire_int(id_, what); }
  int numNodes() const { return static_cast<int>(count(EX_INQ_NODES)); }
  int numSteps() const { return static_cast<int>(count(EX_INQ_TIME)); }

  std::vector<double> times() const {
    std::vector<double> t(numSteps());
    if (!t.empty()) {
      EXPECT_GE(ex_get_all_times(id_, t.data()), 0);
    }
    return t;
  }
  double time(int step) const {
    double t = -1.0;
    EXPECT_GE(ex_get_time(id_, step, &t), 0);
    return t;
  }
  std::vector<double> coordinate(int d) const {
    std::vector<double> x(numNodes()), y(numNodes());
    EXPECT_GE(ex_get_coord(id_, x.data(), y.data(), nullptr), 0);
    return d == 0 ? x : y;
  }
  std::vector<std::string> nodalVariableNames() const {
    int n = 0;
    EXPECT_GE(ex_get_variable_param(id_, EX_NODAL, &n), 0);
    return names(n, [&](char** p) { return ex_get_variable_names(id_, EX_NODAL, n, p); });
  }
  std::vector<std::string> blockNames() const {
    const int n = static_cast<int>(count(EX_INQ_ELEM_BLK));
    return names(n, [&](char** p) { return ex_get_names(id_, EX_ELEM_BLOCK, p); });
  }
  std::vector<int> blockIds() const {
    std::vector<int> ids(count(EX_INQ_ELEM_BLK));
    EXPECT_GE(ex_get_ids(id_, EX_ELEM_BLOCK, ids.data()), 0);
    return ids;
  }
  /// Element type, number of elements and nodes per element of a block.
  std::string blockType(int block_id, int* num_elements, int* nodes_per_element) const {
    char type[MAX_STR_LENGTH + 1] = {};
    int num_edges = 0, num_faces = 0, num_attributes = 0;
    EXPECT_GE(ex_get_block(id_, EX_ELEM_BLOCK, block_id, type, num_elements, nodes_per_element,
                           &num_edges, &num_faces, &num_attributes),
              0);
    return type;
  }
  std::vector<int> connectivity(int block_id, int size) const {
    std::vector<int> conn(size);
    if (size > 0) {
      EXPECT_GE(ex_get_conn(id_, EX_ELEM_BLOCK, block_id, conn.data(), nullptr, nullptr), 0);
    }
    return conn;
  }
  /// Values of the nodal variable called `name` at `step` (1-based).
  std::vector<double> nodal(const std::string& name, int step) const {
    const auto all = nodalVariableNames();
    int index = 0;
    while (index < static_cast<int>(all.size()) && all[index] != name) ++index;
    std::vector<double> values(numNodes());
    if (index == static_cast<int>(all.size())) {
      ADD_FAILURE() << "no nodal variable " << name;
      return values;
    }
    EXPECT_GE(ex_get_var(id_, step, EX_NODAL, index + 1, 1, numNodes(), values.data()), 0);
    return values;
  }

 private:
  template <class Get>
  static std::vector<std::string> names(int n, Get get) {
    std::vector<std::vector<char>> buffers(n, std::vector<char>(257, '\0'));
    std::vector<char*> pointers;
    for (auto& b : buffers) pointers.push_back(b.data());
    if (n > 0) {
      EXPECT_GE(get(pointers.data()), 0);
    }
    std::vector<std::string> result;
    for (auto& b : buffers) result.emplace_back(b.data());
    return result;
  }
  int id_ = -1;
};

}  // namespace argine::test
