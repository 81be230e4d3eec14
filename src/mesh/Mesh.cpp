#include "argine/mesh/Mesh.hpp"

namespace argine {

const char* exodusName(ElementType type) {
  return type == ElementType::Tri3 ? "TRI3" : "QUAD4";
}

namespace {
template <class Set>
const Set* findByName(const std::vector<Set>& sets, const std::string& name) {
  for (const auto& set : sets)
    if (set.name == name) return &set;
  return nullptr;
}
template <class Set>
std::vector<std::string> namesOf(const std::vector<Set>& sets) {
  std::vector<std::string> names;
  for (const auto& set : sets) names.push_back(set.name);
  return names;
}
}  // namespace

const ElementBlock* Mesh::findBlock(const std::string& name) const {
  return findByName(blocks, name);
}
const NodeSet* Mesh::findNodeSet(const std::string& name) const {
  return findByName(node_sets, name);
}
const SideSet* Mesh::findSideSet(const std::string& name) const {
  return findByName(side_sets, name);
}
std::vector<std::string> Mesh::blockNames() const {
  return namesOf(blocks);
}
std::vector<std::string> Mesh::nodeSetNames() const {
  return namesOf(node_sets);
}
std::vector<std::string> Mesh::sideSetNames() const {
  return namesOf(side_sets);
}

}  // namespace argine
