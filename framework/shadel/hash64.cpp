#include <cstring>

#include <shadelgraph/shadel/hash64.hpp>

namespace sg::shadel {
namespace {

uint64_t finalize(uint64_t x) {  // splitmix64's finalizer
  x ^= x >> 30;
  x *= 0xBF58476D1CE4E5B9ull;
  x ^= x >> 27;
  x *= 0x94D049BB133111EBull;
  x ^= x >> 31;
  return x;
}

}  // namespace

void Hash64::mix(uint64_t word) {
  state_ = (state_ ^ finalize(word + 0x632BE59BD9B4E019ull)) * 0x9FB21C651E98DF25ull;
  state_ ^= state_ >> 29;
}

Hash64& Hash64::bytes(const void* data, size_t size) {
  const auto* p = static_cast<const unsigned char*>(data);
  length_ += size;
  while (size > 0 && pendingBytes_ != 0) {  // top up a partial word first
    pending_ |= uint64_t{*p++} << (8 * pendingBytes_);
    --size;
    if (++pendingBytes_ == 8) {
      mix(pending_);
      pending_ = 0;
      pendingBytes_ = 0;
    }
  }
  for (; size >= 8; size -= 8, p += 8) {
    uint64_t word;
    std::memcpy(&word, p, 8);  // the project targets little-endian machines
    mix(word);
  }
  for (; size > 0; --size) pending_ |= uint64_t{*p++} << (8 * pendingBytes_++);
  return *this;
}

uint64_t Hash64::digest() const {
  Hash64 copy = *this;
  copy.mix(copy.pending_ ^ (uint64_t{copy.pendingBytes_} << 59));
  copy.mix(copy.length_);
  return finalize(copy.state_);
}

}  // namespace sg::shadel
