/// @file GmshFileReader.cpp
/// A reader of gmsh's MSH 4.1 format, ASCII and binary (GmshFile.hpp), of our own: the format
/// is short and documented, and Debian's gmsh library would bring OpenCASCADE and a GUI
/// toolkit (26 packages) into every build for it. Every count is checked against the bytes
/// left before anything is sized by it: a damaged file gets an InputError, never a huge
/// allocation.
#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>

#include "argine/core/Error.hpp"
#include "argine/meshio/GmshFile.hpp"

namespace argine {

namespace {

struct ElementKind {
  int type;
  int nodes;
  const char* name;
};

/// gmsh's element types (reference manual, "MSH file format": elm-type).
constexpr ElementKind kElementKinds[] = {
    {1, 2, "2-node line"},
    {2, 3, "3-node triangle"},
    {3, 4, "4-node quadrangle"},
    {4, 4, "4-node tetrahedron"},
    {5, 8, "8-node hexahedron"},
    {6, 6, "6-node prism"},
    {7, 5, "5-node pyramid"},
    {8, 3, "3-node second-order line"},
    {9, 6, "6-node second-order triangle"},
    {10, 9, "9-node second-order quadrangle"},
    {11, 10, "10-node second-order tetrahedron"},
    {12, 27, "27-node second-order hexahedron"},
    {13, 18, "18-node second-order prism"},
    {14, 14, "14-node second-order pyramid"},
    {15, 1, "1-node point"},
    {16, 8, "8-node second-order quadrangle"},
    {17, 20, "20-node second-order hexahedron"},
    {18, 15, "15-node second-order prism"},
    {19, 13, "13-node second-order pyramid"},
    {20, 9, "9-node third-order incomplete triangle"},
    {21, 10, "10-node third-order triangle"},
    {22, 12, "12-node fourth-order incomplete triangle"},
    {23, 15, "15-node fourth-order triangle"},
    {24, 15, "15-node fifth-order incomplete triangle"},
    {25, 21, "21-node fifth-order triangle"},
    {26, 4, "4-node third-order line"},
    {27, 5, "5-node fourth-order line"},
    {28, 6, "6-node fifth-order line"},
    {29, 20, "20-node third-order tetrahedron"},
    {30, 35, "35-node fourth-order tetrahedron"},
    {31, 56, "56-node fifth-order tetrahedron"},
};

const ElementKind* findKind(int type) {
  for (const auto& kind : kElementKinds)
    if (kind.type == type) return &kind;
  return nullptr;
}

/// Reads the file's bytes: ASCII tokens or binary values, as the file type says, with the
/// bytes left checked before every read.
class Cursor {
 public:
  Cursor(const std::string& path, const std::string& bytes) : path_(path), bytes_(bytes) {}

  [[noreturn]] void fail(const std::string& problem) const { throw InputError(path_, problem); }

  bool binary = false;
  std::string section;  ///< the section being read, for messages

  bool atEnd() {
    skipSpace();
    return pos_ >= bytes_.size();
  }
  std::size_t left() const { return bytes_.size() - pos_; }

  void skipSpace() {
    while (pos_ < bytes_.size() && std::strchr(" \t\r\n", bytes_[pos_]) && bytes_[pos_] != '\0')
      ++pos_;
  }

  /// The rest of the current line (without "\r\n").
  std::string line() {
    const std::size_t end = bytes_.find('\n', pos_);
    std::string text = bytes_.substr(pos_, end == std::string::npos ? end : end - pos_);
    pos_ = end == std::string::npos ? bytes_.size() : end + 1;
    if (!text.empty() && text.back() == '\r') text.pop_back();
    return text;
  }

  /// The next whitespace-separated ASCII token.
  std::string word(const char* what) {
    skipSpace();
    const std::size_t start = pos_;
    while (pos_ < bytes_.size() && !std::strchr(" \t\r\n", bytes_[pos_]) && bytes_[pos_] != '\0')
      ++pos_;
    if (pos_ == start) fail("the file ends inside $" + section + " (expected " + what + ")");
    return bytes_.substr(start, pos_ - start);
  }

  /// A count or tag of type size_t in the file (ASCII: digits only).
  std::uint64_t size(const char* what) {
    if (binary) return raw<std::uint64_t>(what);
    const std::string text = word(what);
    if (text.find_first_not_of("0123456789") != std::string::npos || text.size() > 19)
      fail("$" + section + ": expected " + what + " (a non-negative integer), found '" +
           shortened(text) + "'");
    return std::strtoull(text.c_str(), nullptr, 10);
  }

  /// A value of type int in the file.
  int integer(const char* what) {
    if (binary) return raw<std::int32_t>(what);
    const std::string text = word(what);
    errno = 0;
    char* end = nullptr;
    const long long value = std::strtoll(text.c_str(), &end, 10);
    if (*end != '\0' || errno != 0 || value < std::numeric_limits<int>::min() ||
        value > std::numeric_limits<int>::max())
      fail("$" + section + ": expected " + what + " (an integer), found '" + shortened(text) + "'");
    return static_cast<int>(value);
  }

  /// A value of type double in the file.
  Real real(const char* what) {
    if (binary) return raw<double>(what);
    const std::string text = word(what);
    char* end = nullptr;
    const double value = std::strtod(text.c_str(), &end);
    if (*end != '\0')
      fail("$" + section + ": expected " + what + " (a number), found '" + shortened(text) + "'");
    return value;
  }

  /// Throws unless `count` items of `numbers_each` values, `bytes_each` bytes in binary and
  /// at least 2 characters each in ASCII (a digit and a separator), fit in what is left.
  void checkCount(std::uint64_t count, std::size_t numbers_each, std::size_t bytes_each,
                  const char* what) {
    const std::size_t least = std::max<std::size_t>(1, binary ? bytes_each : 2 * numbers_each);
    if (count > left() / least)
      fail("$" + section + " says " + std::to_string(count) + " " + what +
           ", more than the rest of the file can hold (truncated or damaged file)");
  }

  /// Skips to after `$End<name>` (a section argine does not read, or the end of one it did).
  void skipTo(const std::string& name) {
    const std::string marker = "$End" + name;
    const std::size_t at = bytes_.find(marker, pos_);
    if (at == std::string::npos) fail("section $" + name + " has no " + marker);
    pos_ = at + marker.size();
  }

  /// Expects `$End<name>` next (after white space).
  void expectEnd(const std::string& name) {
    skipSpace();
    const std::string marker = "$End" + name;
    if (bytes_.compare(pos_, marker.size(), marker) != 0)
      fail("section $" + name + " does not end with " + marker +
           " where its counts say it ends (inconsistent counts or damaged file)");
    pos_ += marker.size();
  }

  /// A double-quoted name (the $PhysicalNames section, ASCII in every file).
  std::string quoted(const char* what) {
    skipSpace();
    if (pos_ >= bytes_.size() || bytes_[pos_] != '"')
      fail("$" + section + ": expected " + what + " in double quotes");
    const std::size_t end = bytes_.find('"', pos_ + 1);
    if (end == std::string::npos || bytes_.find('\n', pos_) < end)
      fail("$" + section + ": " + what + " has no closing quote on its line");
    std::string text = bytes_.substr(pos_ + 1, end - pos_ - 1);
    pos_ = end + 1;
    return text;
  }

 private:
  template <class T>
  T raw(const char* what) {
    if (left() < sizeof(T)) fail("the file ends inside $" + section + " (expected " + what + ")");
    T value;
    std::memcpy(&value, bytes_.data() + pos_, sizeof(T));
    pos_ += sizeof(T);
    return value;
  }

  static std::string shortened(const std::string& text) {
    return text.size() > 40 ? text.substr(0, 40) + "..." : text;
  }

  const std::string& path_;
  const std::string& bytes_;
  std::size_t pos_ = 0;
};

void readFormat(Cursor& in, GmshFile& file) {
  const std::string version = in.word("the version");
  if (version.rfind("2.", 0) == 0 || version.rfind("3.", 0) == 0)
    in.fail("MSH version " + version +
            "; argine reads MSH 4.1 (save it with gmsh -format msh41, or Mesh.MshFileVersion = "
            "4.1)");
  if (version != "4.1") in.fail("MSH version " + version + "; argine reads MSH 4.1");
  const int type = in.integer("the file type");
  const int data_size = in.integer("the data size");
  if (type != 0 && type != 1) in.fail("file type " + std::to_string(type) + "; expected 0 or 1");
  if (data_size != 8)
    in.fail("data size " + std::to_string(data_size) + "; argine reads files of 8-byte size_t");
  file.binary = type == 1;
  if (file.binary) {
    in.line();  // the end of the format line
    in.binary = true;
    if (in.integer("the byte-order mark") != 1)
      in.fail("a binary file of the other byte order; save it as ASCII (gmsh without -bin)");
    in.binary = false;
  }
}

void readPhysicalNames(Cursor& in, GmshFile& file) {
  const bool binary = in.binary;
  in.binary = false;  // this section is ASCII in binary files too
  const std::uint64_t count = in.size("the number of physical names");
  in.checkCount(count, 3, 3 * 2, "physical names");
  for (std::uint64_t i = 0; i < count; ++i) {
    const int dim = in.integer("a physical group's dimension");
    const int tag = in.integer("a physical tag");
    std::string name = in.quoted("a physical name");
    if (!file.physical_names.emplace(std::make_pair(dim, tag), std::move(name)).second)
      in.fail("$PhysicalNames names the physical group of dimension " + std::to_string(dim) +
              " and tag " + std::to_string(tag) + " twice");
  }
  in.binary = binary;
}

void readEntities(Cursor& in, GmshFile& file) {
  std::uint64_t counts[4];
  for (auto& count : counts) count = in.size("the number of entities");
  for (int dim = 0; dim < 4; ++dim) {
    // a point: tag, x, y, z, number of physicals (4 + 24 + 8 bytes); the others more
    in.checkCount(counts[dim], 5, 36, "entities");
    for (std::uint64_t i = 0; i < counts[dim]; ++i) {
      const int tag = in.integer("an entity tag");
      for (int k = 0; k < (dim == 0 ? 3 : 6); ++k) in.real("an entity's bounding box");
      const std::uint64_t physicals = in.size("the number of physical tags");
      in.checkCount(physicals, 1, 4, "physical tags");
      std::vector<int> tags(physicals);
      for (auto& physical : tags) physical = in.integer("a physical tag");
      if (!file.entity_physicals.emplace(std::make_pair(dim, tag), std::move(tags)).second)
        in.fail("$Entities lists the entity of dimension " + std::to_string(dim) + " and tag " +
                std::to_string(tag) + " twice");
      if (dim == 0) continue;
      const std::uint64_t bounding = in.size("the number of bounding entities");
      in.checkCount(bounding, 1, 4, "bounding entities");
      for (std::uint64_t k = 0; k < bounding; ++k) in.integer("a bounding entity's tag");
    }
  }
}

void readNodes(Cursor& in, GmshFile& file) {
  const std::uint64_t blocks = in.size("the number of node blocks");
  const std::uint64_t total = in.size("the number of nodes");
  in.size("the smallest node tag");
  in.size("the largest node tag");
  in.checkCount(blocks, 4, 20, "node blocks");
  in.checkCount(total, 4, 32, "nodes");
  std::uint64_t read = 0;
  for (std::uint64_t b = 0; b < blocks; ++b) {
    const int dim = in.integer("a node block's entity dimension");
    in.integer("a node block's entity tag");
    const int parametric = in.integer("a node block's parametric flag");
    const std::uint64_t count = in.size("the number of nodes in a block");
    in.checkCount(count, 4, 32, "nodes");
    if (count > total - read)
      in.fail("$Nodes: the blocks hold more nodes than the " + std::to_string(total) +
              " the section's header says");
    read += count;
    std::vector<std::uint64_t> tags(count);
    for (auto& tag : tags) tag = in.size("a node tag");
    const int extra = parametric != 0 ? std::max(0, std::min(dim, 3)) : 0;
    for (const std::uint64_t tag : tags) {
      std::array<Real, 3> x;
      for (auto& value : x) value = in.real("a node coordinate");
      for (int k = 0; k < extra; ++k) in.real("a node's parametric coordinate");
      if (!file.nodes.emplace(tag, x).second)
        in.fail("$Nodes has node " + std::to_string(tag) + " twice");
    }
  }
  if (read != total)
    in.fail("$Nodes: the blocks hold " + std::to_string(read) + " nodes but the header says " +
            std::to_string(total));
}

void readElements(Cursor& in, GmshFile& file) {
  const std::uint64_t blocks = in.size("the number of element blocks");
  const std::uint64_t total = in.size("the number of elements");
  in.size("the smallest element tag");
  in.size("the largest element tag");
  in.checkCount(blocks, 4, 20, "element blocks");
  in.checkCount(total, 2, 16, "elements");
  std::uint64_t read = 0;
  for (std::uint64_t b = 0; b < blocks; ++b) {
    GmshElementBlock block;
    block.entity_dim = in.integer("an element block's entity dimension");
    block.entity_tag = in.integer("an element block's entity tag");
    block.element_type = in.integer("an element type");
    const ElementKind* kind = findKind(block.element_type);
    if (!kind)
      in.fail("$Elements has elements of type " + std::to_string(block.element_type) +
              ", which is not a gmsh element type this reader knows");
    block.nodes_per_element = kind->nodes;
    const std::uint64_t count = in.size("the number of elements in a block");
    in.checkCount(count, 1 + kind->nodes, 8 * (1 + kind->nodes), "elements");
    if (count > total - read)
      in.fail("$Elements: the blocks hold more elements than the " + std::to_string(total) +
              " the section's header says");
    read += count;
    block.node_tags.resize(count * kind->nodes);
    for (std::uint64_t e = 0; e < count; ++e) {
      in.size("an element tag");
      for (int k = 0; k < kind->nodes; ++k)
        block.node_tags[e * kind->nodes + k] = in.size("an element's node tag");
    }
    file.element_blocks.push_back(std::move(block));
  }
  if (read != total)
    in.fail("$Elements: the blocks hold " + std::to_string(read) +
            " elements but the header says " + std::to_string(total));
}

}  // namespace

int gmshNodesPerElement(int type) {
  const ElementKind* kind = findKind(type);
  return kind ? kind->nodes : 0;
}

std::string gmshElementName(int type) {
  const ElementKind* kind = findKind(type);
  return kind ? kind->name : "";
}

GmshFile parseGmshFile(const std::string& path, const std::string& bytes) {
  Cursor in(path, bytes);
  GmshFile file;
  bool format = false, entities = false, nodes = false, elements = false;
  while (!in.atEnd()) {
    const std::string header = in.line();
    if (header.empty() || header[0] != '$')
      in.fail(format ? "expected a section ($Name) after $End" + in.section + ", found '" +
                           header.substr(0, 40) + "'"
                     : "not a gmsh MSH file (it does not start with $MeshFormat)");
    const std::string name = header.substr(1);
    if (!format && name != "MeshFormat")
      in.fail("not a gmsh MSH file (it does not start with $MeshFormat)");
    in.section = name;
    bool* seen = nullptr;
    if (name == "MeshFormat") {
      if (format) in.fail("$MeshFormat appears twice");
      readFormat(in, file);
      format = true;
    } else if (name == "PhysicalNames") {
      readPhysicalNames(in, file);
    } else if (name == "Entities") {
      readEntities(in, file);
      seen = &entities;
    } else if (name == "Nodes") {
      readNodes(in, file);
      seen = &nodes;
    } else if (name == "Elements") {
      readElements(in, file);
      seen = &elements;
    } else if (name == "PartitionedEntities" || name == "GhostElements") {
      in.fail("a partitioned mesh ($" + name +
              "); argine partitions the mesh itself: save it unpartitioned");
    } else {
      in.skipTo(name);  // $Periodic, $NodeData, $Comments, ...: nothing argine uses
      continue;
    }
    if (seen) {
      if (*seen) in.fail("$" + name + " appears twice");
      *seen = true;
    }
    in.expectEnd(name);
    // From here on a binary file's section data is binary ($PhysicalNames excepted, above).
    in.binary = file.binary;
  }
  if (!format) in.fail("the file is empty (expected $MeshFormat)");
  if (!entities) in.fail("the file has no $Entities section");
  if (!nodes) in.fail("the file has no $Nodes section");
  if (!elements) in.fail("the file has no $Elements section");
  return file;
}

GmshFile readGmshFile(const std::string& path) {
  std::ifstream stream(path, std::ios::binary);
  if (!stream) throw InputError(path, "cannot open the mesh file (missing or unreadable)");
  const std::string bytes((std::istreambuf_iterator<char>(stream)),
                          std::istreambuf_iterator<char>());
  return parseGmshFile(path, bytes);
}

}  // namespace argine
