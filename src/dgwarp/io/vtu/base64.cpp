#include "dgwarp/io/vtu/base64.hpp"

#include <cstdint>

namespace dgwarp {

namespace {

constexpr char alphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";

// Character classes for decoding: 0-63 the value of a base64 digit.
constexpr std::uint8_t pad = 64, blank = 65, invalid = 66;

struct DecodeTable {
    std::uint8_t value[256];
    constexpr DecodeTable() : value() {
        for (auto& v : value) v = invalid;
        for (int i = 0; i < 64; ++i) value[static_cast<std::uint8_t>(alphabet[i])] = static_cast<std::uint8_t>(i);
        value[static_cast<std::uint8_t>('=')] = pad;
        for (char c : {' ', '\t', '\n', '\r'}) value[static_cast<std::uint8_t>(c)] = blank;
    }
};
constexpr DecodeTable table;

std::uint8_t class_of(char c) { return table.value[static_cast<std::uint8_t>(c)]; }

}  // namespace

std::size_t base64_encode(std::span<const std::byte> bytes, char* out) {
    const auto* in = reinterpret_cast<const std::uint8_t*>(bytes.data());
    const std::size_t n = bytes.size();
    const std::size_t whole = n - n % 3;
    char* o = out;
    for (std::size_t i = 0; i < whole; i += 3) {
        const std::uint32_t v = (std::uint32_t{in[i]} << 16) | (std::uint32_t{in[i + 1]} << 8) | in[i + 2];
        o[0] = alphabet[v >> 18];
        o[1] = alphabet[(v >> 12) & 63];
        o[2] = alphabet[(v >> 6) & 63];
        o[3] = alphabet[v & 63];
        o += 4;
    }
    if (n - whole == 1) {
        const std::uint32_t v = std::uint32_t{in[whole]} << 16;
        o[0] = alphabet[v >> 18];
        o[1] = alphabet[(v >> 12) & 63];
        o[2] = '=';
        o[3] = '=';
        o += 4;
    } else if (n - whole == 2) {
        const std::uint32_t v = (std::uint32_t{in[whole]} << 16) | (std::uint32_t{in[whole + 1]} << 8);
        o[0] = alphabet[v >> 18];
        o[1] = alphabet[(v >> 12) & 63];
        o[2] = alphabet[(v >> 6) & 63];
        o[3] = '=';
        o += 4;
    }
    return static_cast<std::size_t>(o - out);
}

std::string base64_encode(std::span<const std::byte> bytes) {
    std::string text(base64_encoded_size(bytes.size()), '\0');
    base64_encode(bytes, text.data());
    return text;
}

bool Base64Decoder::decode_group() {
    // The next 4 significant characters: digits, then padding only in the last two.
    std::uint8_t v[4];
    std::size_t where[4];
    int k = 0;
    while (k < 4 && pos_ < text_.size()) {
        const std::uint8_t c = class_of(text_[pos_]);
        if (c == blank) {
            ++pos_;
            continue;
        }
        // Padding never in the first two places, and nothing but padding after it ("xx=y").
        if (c == invalid || (c == pad && k < 2) || (k == 3 && v[2] == pad && c != pad)) {
            bad_ = pos_;
            return false;
        }
        where[k] = pos_;
        v[k++] = c;
        ++pos_;
    }
    if (k == 0) return false;  // the end of the text
    if (k == 1) {              // one digit cannot hold a byte
        bad_ = where[0];
        return false;
    }
    int bytes = 3;
    if (k == 2 || v[2] == pad) bytes = 1;       // "xx==", or "xx" / "xx=" at the end
    else if (k == 3 || v[3] == pad) bytes = 2;  // "xxx=", or "xxx" at the end
    const std::uint32_t digits = (std::uint32_t{v[0]} << 18) | (std::uint32_t{v[1]} << 12) |
                                 (std::uint32_t{bytes >= 2 ? v[2] : 0u} << 6) | (bytes == 3 ? v[3] : 0u);
    pending_[0] = static_cast<std::uint8_t>(digits >> 16);
    pending_[1] = static_cast<std::uint8_t>(digits >> 8);
    pending_[2] = static_cast<std::uint8_t>(digits);
    pending_begin_ = 0;
    pending_end_ = bytes;
    return true;
}

std::size_t Base64Decoder::read(std::byte* out, std::size_t n) {
    std::size_t done = 0;
    while (done < n) {
        if (pending_begin_ < pending_end_) {
            out[done++] = static_cast<std::byte>(pending_[pending_begin_++]);
            continue;
        }
        // Fast path: whole groups of 4 digits straight into `out`.
        while (n - done >= 3 && text_.size() - pos_ >= 4) {
            const std::uint8_t a = class_of(text_[pos_]), b = class_of(text_[pos_ + 1]),
                               c = class_of(text_[pos_ + 2]), d = class_of(text_[pos_ + 3]);
            if ((a | b | c | d) >= 64) break;
            const std::uint32_t digits = (std::uint32_t{a} << 18) | (std::uint32_t{b} << 12) | (std::uint32_t{c} << 6) | d;
            out[done] = static_cast<std::byte>(digits >> 16);
            out[done + 1] = static_cast<std::byte>(digits >> 8);
            out[done + 2] = static_cast<std::byte>(digits);
            done += 3;
            pos_ += 4;
        }
        if (done == n) break;
        if (bad_ != std::string_view::npos || !decode_group()) break;
    }
    return done;
}

}  // namespace dgwarp
