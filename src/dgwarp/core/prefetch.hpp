#pragma once
// Asks the memory system for an object ahead of its use: for loops that
// gather through an index array (node -> simplex -> corner data), where the
// addresses are known several iterations before the data are needed.
#include <cstddef>
#include <cstdint>

namespace dgwarp {

/// Prefetches (for reading) every 64-byte cache line that the `bytes` bytes at `p` touch.
inline void prefetch_bytes(const void* p, std::size_t bytes) {
    constexpr std::uintptr_t line = 64;
    const auto first = reinterpret_cast<std::uintptr_t>(p) & ~(line - 1);
    const auto last = reinterpret_cast<std::uintptr_t>(p) + bytes - 1;
    for (std::uintptr_t a = first; a <= last; a += line) __builtin_prefetch(reinterpret_cast<const void*>(a));
}

}  // namespace dgwarp
