#include "argine/checkpoint/CheckpointFile.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>

#include "argine/core/Error.hpp"

namespace argine {

namespace {

constexpr char kMagic[8] = {'A', 'R', 'G', 'I', 'N', 'E', 'C', 'P'};
constexpr std::uint32_t kByteOrderMark = 0x01020304;

struct Header {
  char magic[8];
  std::uint32_t version;
  std::uint32_t byte_order;
  std::uint64_t deck_hash;
  std::uint64_t payload_size;
  std::uint64_t payload_checksum;
  std::uint64_t header_checksum;
};
static_assert(sizeof(Header) == kCheckpointHeaderBytes, "the header layout is fixed");

std::uint64_t headerChecksum(const Header& header) {
  return fnv1a64(&header, offsetof(Header, header_checksum));
}

std::string hex(std::uint64_t value) {
  char text[24];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(value));
  return text;
}

// Writes all of `size` bytes to `fd`; false on error.
bool writeAll(int fd, const char* data, std::size_t size) {
  while (size > 0) {
    const ssize_t n = ::write(fd, data, size);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    data += n;
    size -= static_cast<std::size_t>(n);
  }
  return true;
}

}  // namespace

std::uint64_t fnv1a64(const void* data, std::size_t size, std::uint64_t hash) {
  const auto* bytes = static_cast<const unsigned char*>(data);
  for (std::size_t i = 0; i < size; ++i) {
    hash ^= bytes[i];
    hash *= 1099511628211ULL;
  }
  return hash;
}

std::uint64_t fileHash(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "cannot read the file to hash it");
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  return fnv1a64(bytes.data(), bytes.size());
}

// ---------------------------------------------------------------- payload

void CheckpointWriter::putString(const std::string& text) {
  put<std::uint64_t>(text.size());
  putBytes(text.data(), text.size());
}

void CheckpointWriter::putBytes(const void* data, std::size_t size) {
  payload_.append(static_cast<const char*>(data), size);
}

void CheckpointReader::fail(const std::string& what) const {
  throw InputError(path_, "corrupt checkpoint: " + what);
}

void CheckpointReader::need(std::uint64_t count, std::size_t size) const {
  const std::size_t left = payload_.size() - offset_;
  if (size > 0 && count > left / size)
    fail("a record of " + std::to_string(count) + " values of " + std::to_string(size) +
         " bytes at payload offset " + std::to_string(offset_) + " runs past the end");
}

void CheckpointReader::getBytes(void* data, std::size_t size) {
  need(size, 1);
  std::memcpy(data, payload_.data() + offset_, size);
  offset_ += size;
}

std::string CheckpointReader::getString() {
  const auto size = get<std::uint64_t>();
  need(size, 1);
  std::string text(payload_.data() + offset_, size);
  offset_ += size;
  return text;
}

void CheckpointReader::expectEnd() const {
  if (offset_ != payload_.size())
    fail(std::to_string(payload_.size() - offset_) + " payload bytes left unread");
}

// ---------------------------------------------------------------- file

std::uintmax_t writeCheckpointFile(const std::string& path, std::uint64_t deck_hash,
                                   const std::string& payload) {
  Header header{};
  std::memcpy(header.magic, kMagic, sizeof kMagic);
  header.version = kCheckpointFormatVersion;
  header.byte_order = kByteOrderMark;
  header.deck_hash = deck_hash;
  header.payload_size = payload.size();
  header.payload_checksum = fnv1a64(payload.data(), payload.size());
  header.header_checksum = headerChecksum(header);

  const std::string temporary = path + ".part";
  auto fail = [&](const std::string& what) {
    const std::string reason = std::strerror(errno);
    ::unlink(temporary.c_str());
    throw RunError(path + ": cannot write the checkpoint: " + what + " (" + reason + ")");
  };
  const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) fail("open " + temporary);
  const bool written = writeAll(fd, reinterpret_cast<const char*>(&header), sizeof header) &&
                       writeAll(fd, payload.data(), payload.size());
  // The data must be on disk before the rename makes it the checkpoint.
  const bool synced = written && ::fsync(fd) == 0;
  if (::close(fd) != 0 || !synced) fail(written ? "fsync" : "write");
  if (std::rename(temporary.c_str(), path.c_str()) != 0) fail("rename " + temporary);
  // And the rename itself: fsync the directory entry.
  std::string directory = std::filesystem::path(path).parent_path().string();
  if (directory.empty()) directory = ".";
  const int dir = ::open(directory.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dir >= 0) {
    ::fsync(dir);
    ::close(dir);
  }
  return sizeof header + payload.size();
}

std::string readCheckpointFile(const std::string& path, std::uint64_t deck_hash) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "cannot open the checkpoint file");
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (bytes.size() < sizeof(Header))
    throw InputError(path, "truncated checkpoint: " + std::to_string(bytes.size()) +
                               " bytes, shorter than its " +
                               std::to_string(kCheckpointHeaderBytes) + "-byte header");
  Header header;
  std::memcpy(&header, bytes.data(), sizeof header);
  if (std::memcmp(header.magic, kMagic, sizeof kMagic) != 0)
    throw InputError(path, "not an argine checkpoint (no ARGINECP magic)");
  if (header.byte_order != kByteOrderMark)
    throw InputError(path, "checkpoint written on a machine of another byte order");
  if (headerChecksum(header) != header.header_checksum)
    throw InputError(path, "corrupt checkpoint: header checksum mismatch");
  if (header.version != kCheckpointFormatVersion)
    throw InputError(path, "checkpoint format version " + std::to_string(header.version) +
                               "; this argine reads version " +
                               std::to_string(kCheckpointFormatVersion) + " only");
  if (header.deck_hash != deck_hash)
    throw InputError(path, "checkpoint of another deck (deck hash " + hex(header.deck_hash) +
                               ", this deck " + hex(deck_hash) +
                               "): restart with the unchanged deck the checkpoint was made with");
  const std::uint64_t stored = bytes.size() - sizeof header;
  if (stored != header.payload_size)
    throw InputError(path, std::string(stored < header.payload_size ? "truncated" : "corrupt") +
                               " checkpoint: " + std::to_string(stored) +
                               " payload bytes, the "
                               "header says " +
                               std::to_string(header.payload_size));
  bytes.erase(0, sizeof header);
  if (fnv1a64(bytes.data(), bytes.size()) != header.payload_checksum)
    throw InputError(path, "corrupt checkpoint: payload checksum mismatch");
  return bytes;
}

}  // namespace argine
