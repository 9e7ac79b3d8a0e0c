// FNV-1a, 64 bits (Fowler, Noll, Vo; the published offset basis and prime): the history's
// payload addresses, the shard rule's key hash, and the fingerprints of views and
// tessellations.
#pragma once

#include <cstdint>
#include <string_view>

namespace tb::mesh {

inline constexpr uint64_t kFnv1aOffsetBasis = 0xcbf29ce484222325ull;
inline constexpr uint64_t kFnv1aPrime = 0x100000001b3ull;

// `hash` with the low `bytes` bytes of `word` mixed in, least significant byte first.
constexpr uint64_t fnv1aWord(uint64_t hash, uint64_t word, int bytes = 8) {
  for (int b = 0; b < bytes; ++b) hash = (hash ^ ((word >> (8 * b)) & 0xff)) * kFnv1aPrime;
  return hash;
}

constexpr uint64_t fnv1a64(std::string_view text, uint64_t hash = kFnv1aOffsetBasis) {
  for (const char c : text) hash = (hash ^ static_cast<unsigned char>(c)) * kFnv1aPrime;
  return hash;
}

}  // namespace tb::mesh
