#include "dgwarp/io/vtu/base64.hpp"

#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

using namespace dgwarp;

namespace {

std::vector<std::byte> bytes_of(std::string_view s) {
    std::vector<std::byte> b;
    for (char c : s) b.push_back(static_cast<std::byte>(c));
    return b;
}

// Reference encoder written from the definition, one bit at a time.
std::string encode_bit_by_bit(const std::vector<std::byte>& in) {
    const std::string alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::vector<int> bits;
    for (std::byte b : in)
        for (int k = 7; k >= 0; --k) bits.push_back((std::to_integer<int>(b) >> k) & 1);
    while (bits.size() % 6) bits.push_back(0);
    std::string out;
    for (std::size_t i = 0; i < bits.size(); i += 6) {
        int v = 0;
        for (int k = 0; k < 6; ++k) v = 2 * v + bits[i + k];
        out += alphabet[v];
    }
    while (out.size() % 4) out += '=';
    return out;
}

}  // namespace

TEST(Base64, Rfc4648TestVectors) {
    // RFC 4648, section 10.
    EXPECT_EQ(base64_encode(bytes_of("")), "");
    EXPECT_EQ(base64_encode(bytes_of("f")), "Zg==");
    EXPECT_EQ(base64_encode(bytes_of("fo")), "Zm8=");
    EXPECT_EQ(base64_encode(bytes_of("foo")), "Zm9v");
    EXPECT_EQ(base64_encode(bytes_of("foob")), "Zm9vYg==");
    EXPECT_EQ(base64_encode(bytes_of("fooba")), "Zm9vYmE=");
    EXPECT_EQ(base64_encode(bytes_of("foobar")), "Zm9vYmFy");
}

TEST(Base64, LastTwoAlphabetCharactersAndZeroBytes) {
    // 0xFB 0xFF = 111110 111111 1111(00): indices 62 '+', 63 '/', 60 '8'.
    EXPECT_EQ(base64_encode(std::vector<std::byte>{std::byte{0xFB}, std::byte{0xFF}}), "+/8=");
    EXPECT_EQ(base64_encode(std::vector<std::byte>(3, std::byte{0})), "AAAA");
    EXPECT_EQ(base64_encode(std::vector<std::byte>(3, std::byte{0xFF})), "////");
}

TEST(Base64, MatchesBitByBitReferenceForEveryLengthAndByteValue) {
    std::mt19937 rng(12345);
    std::vector<std::byte> all;
    for (int v = 0; v < 256; ++v) all.push_back(static_cast<std::byte>(v));
    EXPECT_EQ(base64_encode(all), encode_bit_by_bit(all));
    for (std::size_t n = 0; n < 50; ++n) {
        std::vector<std::byte> in(n);
        for (auto& b : in) b = static_cast<std::byte>(rng() & 0xFF);
        const std::string text = base64_encode(in);
        EXPECT_EQ(text.size(), base64_encoded_size(n)) << n;
        EXPECT_EQ(text, encode_bit_by_bit(in)) << n;
    }
}

TEST(Base64, PiecesOfMultipleOfThreeBytesConcatenateToTheWhole) {
    std::mt19937 rng(7);
    std::vector<std::byte> in(1000);
    for (auto& b : in) b = static_cast<std::byte>(rng() & 0xFF);
    std::string pieces(base64_encoded_size(in.size()), '\0');
    std::size_t written = 0;
    const std::span<const std::byte> all(in);
    for (std::size_t first = 0; first < in.size(); first += 99)  // 99 = 3 × 33
        written += base64_encode(all.subspan(first, std::min<std::size_t>(99, in.size() - first)),
                                 pieces.data() + written);
    EXPECT_EQ(written, pieces.size());
    EXPECT_EQ(pieces, base64_encode(in));
}
