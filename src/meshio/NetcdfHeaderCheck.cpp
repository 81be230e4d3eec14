#include "argine/meshio/NetcdfHeaderCheck.hpp"

#include <cstdint>
#include <fstream>
#include <iterator>
#include <vector>

#include "argine/core/Error.hpp"

namespace argine {

namespace {

/// Walks the header (netCDF classic format specification): magic, numrecs, dim_list,
/// gatt_list, var_list. Big-endian; names and values padded to 4 bytes.
class HeaderWalk {
 public:
  HeaderWalk(const std::string& path, std::vector<unsigned char> bytes, int version)
      : path_(path), bytes_(std::move(bytes)), version_(version) {}

  void walk() {
    at_ = 4;
    size(version_ == 5 ? 8 : 4);  // numrecs
    list(0x0A, [&] {              // dimensions: name, length
      name();
      size(version_ == 5 ? 8 : 4);
    });
    attributes();
    list(0x0B, [&] {  // variables: name, dimension ids, attributes, type, vsize, begin
      name();
      const uint64_t dims = count("variable dimensions");
      skip(dims * (version_ == 5 ? 8 : 4), "variable dimension ids");
      attributes();
      type();
      size(version_ == 5 ? 8 : 4);  // vsize
      size(version_ == 1 ? 4 : 8);  // begin
    });
  }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    throw InputError(path_, "damaged netCDF header at byte " + std::to_string(at_) + ": " + what +
                                " (the file has " + std::to_string(bytes_.size()) + " bytes)");
  }
  uint64_t size(int width) {
    if (at_ + width > bytes_.size()) fail("the header ends early");
    uint64_t value = 0;
    for (int k = 0; k < width; ++k) value = value << 8 | bytes_[at_ + k];
    at_ += width;
    return value;
  }
  /// A count of items that each take at least 4 bytes: it cannot exceed what is left.
  uint64_t count(const char* what) {
    const uint64_t n = size(version_ == 5 ? 8 : 4);
    if (n > (bytes_.size() - at_) / 4)
      fail(std::string("a count of ") + what + " (" + std::to_string(n) + ") larger than the file");
    return n;
  }
  void skip(uint64_t n, const char* what) {
    if (n > bytes_.size() - at_) fail(std::string(what) + " longer than the file");
    at_ += n;
  }
  void name() { skip((count("name bytes") + 3) / 4 * 4, "a name"); }
  int type() {
    const uint64_t t = size(4);
    static const int widths[] = {0, 1, 1, 2, 4, 4, 8, 1, 2, 4, 8, 8};
    if (t < 1 || t > 11 || (version_ != 5 && t > 6)) fail("unknown type " + std::to_string(t));
    return widths[t];
  }
  void attributes() {
    list(0x0C, [&] {  // name, type, nelems, values
      name();
      const int width = type();
      const uint64_t n = size(version_ == 5 ? 8 : 4);
      if (n > (bytes_.size() - at_) / static_cast<uint64_t>(width))
        fail("attribute values longer than the file");
      skip((n * width + 3) / 4 * 4, "attribute values");
    });
  }
  /// ABSENT (two zero words) or tag + count + items.
  template <class Item>
  void list(uint64_t tag, Item item) {
    const uint64_t found = size(4);
    if (found == 0) {
      if (count("absent list") != 0) fail("an empty list with a non-zero count");
      return;
    }
    if (found != tag)
      fail("list tag " + std::to_string(found) + ", expected " + std::to_string(tag));
    const uint64_t n = count("list items");
    for (uint64_t k = 0; k < n; ++k) item();
  }

  std::string path_;
  std::vector<unsigned char> bytes_;
  int version_;
  std::size_t at_ = 0;
};

}  // namespace

void checkNetcdfClassicHeader(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(file)),
                                   std::istreambuf_iterator<char>());
  if (bytes.size() < 4 || bytes[0] != 'C' || bytes[1] != 'D' || bytes[2] != 'F') return;
  const int version = bytes[3];
  if (version != 1 && version != 2 && version != 5)
    throw InputError(path, "netCDF classic file of unknown version " + std::to_string(version));
  HeaderWalk(path, std::move(bytes), version).walk();
}

}  // namespace argine
