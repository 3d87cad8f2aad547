#pragma once
// A streaming 64-bit hash for cache keys and file checksums: 8 bytes a step
// with a multiply-xorshift mix (fast enough to checksum a 4K² ID map in a few
// milliseconds). Not cryptographic; it guards against stale and damaged
// cache files, not against an adversary.
#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>
#include <type_traits>

namespace sg::shadel {

class Hash64 {
 public:
  Hash64& bytes(const void* data, size_t size);
  template <class T>
    requires std::is_trivially_copyable_v<T>
  Hash64& values(std::span<const T> items) {
    value(uint64_t{items.size()});
    return bytes(items.data(), items.size_bytes());
  }
  template <class T>
    requires std::is_trivially_copyable_v<T>
  Hash64& value(const T& item) {
    return bytes(&item, sizeof item);
  }
  Hash64& text(std::string_view s) {
    value(uint64_t{s.size()});
    return bytes(s.data(), s.size());
  }
  uint64_t digest() const;

 private:
  void mix(uint64_t word);
  uint64_t state_ = 0x9E3779B97F4A7C15ull;
  uint64_t length_ = 0;
  uint64_t pending_ = 0;  // bytes not yet mixed, little-endian
  uint32_t pendingBytes_ = 0;
};

}  // namespace sg::shadel
