#pragma once
/// @file CheckpointFile.hpp
/// The container of a checkpoint (doc/checkpoints.md): a fixed 48-byte header and a payload
/// of values in a fixed order, written atomically so a crash never leaves a partial file
/// under the checkpoint's name.
///
///   offset  size  what
///        0     8  magic "ARGINECP"
///        8     4  format version (kCheckpointFormatVersion)
///       12     4  byte-order mark 0x01020304 (values are stored in the writer's byte order)
///       16     8  hash of the deck file the run read (FNV-1a 64 of its bytes)
///       24     8  payload size (bytes)
///       32     8  payload checksum (FNV-1a 64)
///       40     8  header checksum (FNV-1a 64 of bytes 0..39)
///       48     *  payload
///
/// Compatibility rule: a reader accepts exactly its own format version and byte order, and
/// only the deck whose hash the header holds; any change of the payload layout increments
/// the version. What the payload holds is the Simulation's business (SimulationCheckpoint).

#include <cstdint>
#include <cstring>
#include <string>
#include <type_traits>
#include <vector>

#include "argine/core/Types.hpp"

namespace argine {

struct MaterialPoints;

inline constexpr std::uint32_t kCheckpointFormatVersion = 8;
inline constexpr std::size_t kCheckpointHeaderBytes = 48;

/// FNV-1a 64-bit hash of `size` bytes, continuing from `hash`.
std::uint64_t fnv1a64(const void* data, std::size_t size,
                      std::uint64_t hash = 14695981039346656037ULL);
/// fnv1a64 of a file's bytes; InputError naming the file when it cannot be read.
std::uint64_t fileHash(const std::string& path);

/// Builds a payload: values appended in order, raw bytes of trivially copyable types.
class CheckpointWriter {
 public:
  template <class T>
  void put(const T& value) {
    static_assert(std::is_trivially_copyable_v<T>, "raw values only");
    putBytes(&value, sizeof(T));
  }
  template <class T>
  void putVector(const std::vector<T>& values) {
    static_assert(std::is_trivially_copyable_v<T>, "raw values only");
    put<std::uint64_t>(values.size());
    if (!values.empty()) putBytes(values.data(), values.size() * sizeof(T));
  }
  void putString(const std::string& text);
  void putBytes(const void* data, std::size_t size);
  const std::string& payload() const { return payload_; }

 private:
  std::string payload_;
};

/// Reads a payload back in the order it was written; every read past the end or of an
/// implausible length throws InputError naming the file.
class CheckpointReader {
 public:
  CheckpointReader(std::string payload, std::string path)
      : payload_(std::move(payload)), path_(std::move(path)) {}
  template <class T>
  T get() {
    static_assert(std::is_trivially_copyable_v<T>, "raw values only");
    T value;
    getBytes(&value, sizeof(T));
    return value;
  }
  template <class T>
  std::vector<T> getVector() {
    const auto count = get<std::uint64_t>();
    need(count, sizeof(T));
    std::vector<T> values(count);
    if (count > 0) getBytes(values.data(), count * sizeof(T));
    return values;
  }
  std::string getString();
  void getBytes(void* data, std::size_t size);
  /// Throws InputError unless the whole payload was read.
  void expectEnd() const;
  /// InputError(path, "corrupt checkpoint: " + what).
  [[noreturn]] void fail(const std::string& what) const;
  const std::string& path() const { return path_; }

 private:
  void need(std::uint64_t count, std::size_t size) const;
  std::string payload_;
  std::string path_;
  std::size_t offset_ = 0;
};

/// Writes header and payload to `path` atomically: into `path`.part, fsync, rename over
/// `path`, fsync of the directory. Returns the file size. RunError naming the file on failure
/// (the previous checkpoint, if any, is then left untouched).
std::uintmax_t writeCheckpointFile(const std::string& path, std::uint64_t deck_hash,
                                   const std::string& payload);

/// Reads `path` and checks the header (magic, version, byte order, header checksum), the deck
/// hash, the payload size and checksum; returns the payload. InputError naming the file and
/// saying what is wrong (missing, truncated, corrupt, other version, other deck).
std::string readCheckpointFile(const std::string& path, std::uint64_t deck_hash);

/// Every field of the material points, each as a named record (name, element size, rows,
/// columns, values), in their current order. A field added to MaterialPoints must be added
/// to forEachPointField (CheckpointPoints.cpp).
void putPoints(CheckpointWriter& out, const MaterialPoints& points);
/// Reads the points back into `points`, which must hold as many (InputError otherwise); the
/// Views keep their identity, so a solver's reference to them stays valid. InputError when a
/// record does not match this build's fields.
void getPoints(CheckpointReader& in, MaterialPoints& points);

}  // namespace argine
