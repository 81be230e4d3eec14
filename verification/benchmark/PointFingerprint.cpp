#include "PointFingerprint.hpp"

#include <algorithm>
#include <string>
#include <type_traits>
#include <vector>

#include "argine/points/PointFields.hpp"

namespace argine::benchmark {

namespace {

constexpr unsigned long long kOffset = 1469598103934665603ULL;  // FNV-1a 64-bit
constexpr unsigned long long kPrime = 1099511628211ULL;

/// Whether a field was added in P9 and is zero where its feature is unused (APIC's affine
/// velocity matrices in FLIP runs, the separation of points that never opened): hashed only
/// when some value is not +0, so that such a run's fingerprint is the one of the builds
/// before the field existed (the bits of the other fields are what the fingerprint checks).
bool skippedWhenZero(const std::string& name) {
  return name == "affine_velocity_solid" || name == "affine_velocity_liquid" ||
         name == "separation";
}

/// Calls visit(p, bytes, size) with the bit pattern of point p's value of every point field,
/// field by field, points in `order`.
template <class Visit>
void forEachPointValue(const MaterialPoints& points, const std::vector<int>& order, Visit&& visit) {
  forEachPointField(points, [&](const char* name, const auto& view) {
    auto host = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), view);
    const std::size_t width = host.span() / std::max<std::size_t>(host.extent(0), 1);
    using Value = typename std::decay_t<decltype(host)>::value_type;
    if (skippedWhenZero(name)) {
      const auto* bytes = reinterpret_cast<const unsigned char*>(host.data());
      if (std::all_of(bytes, bytes + host.span() * sizeof(Value),
                      [](unsigned char b) { return b == 0; }))
        return;
    }
    for (const int p : order)
      visit(p, reinterpret_cast<const unsigned char*>(host.data() + p * width),
            width * sizeof(Value));
  });
}

unsigned long long hashBytes(unsigned long long hash, const unsigned char* bytes,
                             std::size_t size) {
  for (std::size_t b = 0; b < size; ++b) hash = (hash ^ bytes[b]) * kPrime;
  return hash;
}

}  // namespace

unsigned long long fingerprint(const MaterialPoints& points) {
  const auto id = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), points.id);
  std::vector<int> index_of_id(points.count);
  for (int p = 0; p < points.count; ++p) index_of_id.at(id(p)) = p;
  unsigned long long hash = kOffset;
  forEachPointValue(points, index_of_id, [&](int, const unsigned char* bytes, std::size_t size) {
    hash = hashBytes(hash, bytes, size);
  });
  return hash;
}

unsigned long long additiveFingerprint(const MaterialPoints& points) {
  std::vector<int> order(points.count);
  for (int p = 0; p < points.count; ++p) order[p] = p;
  std::vector<unsigned long long> hash(points.count, kOffset);
  forEachPointValue(points, order, [&](int p, const unsigned char* bytes, std::size_t size) {
    hash[p] = hashBytes(hash[p], bytes, size);
  });
  unsigned long long sum = 0;
  for (const unsigned long long h : hash) sum += h;
  return sum;
}

}  // namespace argine::benchmark
