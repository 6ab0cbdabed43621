#pragma once
// Base64 (RFC 4648, section 4: alphabet A-Z a-z 0-9 + /, '=' padding), as VTK
// XML files use for their binary data arrays: encoding without line breaks,
// and decoding of what VTK, meshio and dgwarp write.
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>

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

/// Decodes base64 text in pieces, as VTK XML files hold it: whitespace may
/// stand anywhere, and several padded streams may follow one another (VTK
/// encodes a compressed array's header and its data separately, and an
/// appended section holds one stream per array). A final group without its
/// padding is accepted.
class Base64Decoder {
public:
    explicit Base64Decoder(std::string_view text) : text_(text) {}

    /// Decodes the next `n` bytes into `out`; returns how many it decoded:
    /// fewer than `n` when the text ends or holds a character that does not
    /// belong there (see bad_position).
    std::size_t read(std::byte* out, std::size_t n);

    /// Offset in the text of the first character that is neither base64,
    /// whitespace nor well-placed padding; npos while none was met.
    std::size_t bad_position() const { return bad_; }

    /// Offset in the text after the last character consumed.
    std::size_t position() const { return pos_; }

private:
    bool decode_group();  // refills pending_ from the next group of 4 characters

    std::string_view text_;
    std::size_t pos_ = 0;
    std::size_t bad_ = std::string_view::npos;
    std::uint8_t pending_[3] = {};
    int pending_begin_ = 0, pending_end_ = 0;
};

}  // namespace dgwarp
