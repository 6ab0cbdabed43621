#pragma once
// A fast 64-bit hash of a byte range: XXH64 (Yann Collet's xxHash, 64-bit
// variant), reimplemented here. Used for mesh fingerprints and file checksums,
// where it reads tens of megabytes at memory speed; it is not cryptographic.
#include <cstddef>
#include <cstdint>
#include <span>

namespace dgwarp {

/// XXH64 of `bytes` with `seed`; equals the reference xxHash XXH64(bytes, seed).
std::uint64_t hash64(std::span<const std::byte> bytes, std::uint64_t seed = 0);

/// hash64 of the object representation of the elements of `values`.
template <class T>
std::uint64_t hash64_of(std::span<const T> values, std::uint64_t seed = 0) {
    return hash64(std::as_bytes(values), seed);
}

}  // namespace dgwarp
