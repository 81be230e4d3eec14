// [Boundary] NodeTable: the per-node table HydraulicConditions::plan fills every step in
// place of std::maps. It must give the map's values to the bit (sums in the order of the
// touches), keep the first value on emplace, list the nodes in increasing order, and
// forget everything on clear() while keeping its storage.
#include <gtest/gtest.h>

#include <array>
#include <map>
#include <vector>

#include "argine/boundary/NodeTable.hpp"

namespace argine {
namespace {

TEST(NodeTable, SumsAsTheMapItReplacesToTheBit) {
  // 0.1 + 0.2 + 0.3 in that order is 0.6000000000000001, in the order 0.3, 0.2, 0.1 it is
  // 0.6: the table must add in the order of the touches, as std::map's operator[] does.
  const std::vector<std::pair<int, double>> touches = {{7, 0.1}, {2, 1e-17}, {7, 0.2}, {2, 1.0},
                                                       {7, 0.3}, {11, -4.5}, {2, -1.0}};
  NodeTable<std::array<double, 2>> table;
  std::map<int, std::array<double, 2>> map;
  for (const auto& [node, value] : touches) {
    table[node][1] += value;
    map[node][1] += value;
  }
  ASSERT_EQ(table.size(), map.size());
  EXPECT_EQ(table.at(7)[1], 0.1 + 0.2 + 0.3);
  EXPECT_NE(table.at(7)[1], 0.6);  // the order matters here: the check above can fail
  EXPECT_EQ(table.at(2)[1], (1e-17 + 1.0) - 1.0);
  EXPECT_EQ(table.at(7)[0], 0.0);  // value-initialised
  for (const auto& [node, value] : map) EXPECT_EQ(table.at(node)[1], value[1]) << node;
}

TEST(NodeTable, KeepsTheFirstValueAndListsTheNodesInOrder) {
  NodeTable<int> table;
  EXPECT_TRUE(table.emplace(9, 3));
  EXPECT_TRUE(table.emplace(4, 1));
  EXPECT_FALSE(table.emplace(9, 5));  // the first claim stands
  EXPECT_TRUE(table.emplace(0, 2));
  EXPECT_EQ(table.at(9), 3);
  EXPECT_TRUE(table.contains(0));
  EXPECT_FALSE(table.contains(5));
  EXPECT_FALSE(table.contains(100));  // beyond the nodes seen: not contained
  EXPECT_FALSE(table.contains(-1));
  EXPECT_EQ(table.nodes(), (std::vector<int>{9, 4, 0}));  // first touches
  EXPECT_EQ(table.sortedNodes(), (std::vector<int>{0, 4, 9}));
}

TEST(NodeTable, ClearForgetsEveryEntry) {
  NodeTable<double> table;
  table[3] += 2.0;
  table[1] += 1.0;
  table.clear();
  EXPECT_EQ(table.size(), 0u);
  EXPECT_FALSE(table.contains(3));
  EXPECT_TRUE(table.sortedNodes().empty());
  table[3] += 0.5;  // starts again from zero, not from the forgotten 2.0
  EXPECT_EQ(table.at(3), 0.5);
  EXPECT_EQ(table.sortedNodes(), (std::vector<int>{3}));
}

}  // namespace
}  // namespace argine
