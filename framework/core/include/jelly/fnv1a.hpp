// 64-bit FNV-1a: the one hash of bytes the project uses (state hashes in determinism tests, the
// grader's case hashes and file digests). Header-only, so that tools that do not link the core
// (jelly-grade) use the same code.
#pragma once

#include <cstddef>
#include <cstdint>

namespace jelly {

/// FNV-1a's standard 64-bit offset basis and prime.
inline constexpr std::uint64_t kFnv1aOffsetBasis = 14695981039346656037ull;
inline constexpr std::uint64_t kFnv1aPrime = 1099511628211ull;

/// FNV-1a of `size` bytes at `data`, continuing from `hash` (start with an offset basis).
inline std::uint64_t fnv1a(const void* data, std::size_t size,
                           std::uint64_t hash = kFnv1aOffsetBasis) {
  const auto* bytes = static_cast<const unsigned char*>(data);
  for (std::size_t k = 0; k < size; ++k) {
    hash ^= bytes[k];
    hash *= kFnv1aPrime;
  }
  return hash;
}

}  // namespace jelly
