#pragma once
// Base64 encoding (RFC 4648, section 4: alphabet A-Z a-z 0-9 + /, '=' padding,
// no line breaks), as VTK XML files use for their binary data arrays.
#include <cstddef>
#include <span>
#include <string>

namespace dgwarp {

/// Number of characters base64_encode writes for `num_bytes` input bytes:
/// 4 × ceil(num_bytes / 3).
constexpr std::size_t base64_encoded_size(std::size_t num_bytes) { return (num_bytes + 2) / 3 * 4; }

/// Encodes `bytes` into `out`, which must have room for
/// base64_encoded_size(bytes.size()) characters; pads the last group with '='.
/// Returns the number of characters written. To encode a long stream in
/// pieces, pass pieces whose sizes are multiples of 3 (all but the last), so
/// that no padding appears in the middle.
std::size_t base64_encode(std::span<const std::byte> bytes, char* out);

/// Encodes `bytes` and returns the text.
std::string base64_encode(std::span<const std::byte> bytes);

}  // namespace dgwarp
