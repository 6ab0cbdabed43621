#include "dgwarp/core/hash.hpp"

#include <gtest/gtest.h>

#include <string>

using namespace dgwarp;

namespace {
std::uint64_t xxh64(const std::string& s, std::uint64_t seed = 0) {
    return hash64(std::as_bytes(std::span<const char>(s.data(), s.size())), seed);
}
}  // namespace

// Suite named for its user, the plan file checksum.
TEST(PlanFileHash, MatchesReferenceXxh64Vectors) {
    EXPECT_EQ(xxh64(""), 0xEF46DB3751D8E999ULL);
    EXPECT_EQ(xxh64("abc"), 0x44BC2CF5AD770999ULL);
    EXPECT_EQ(xxh64(std::string(32, 'a')), 0x856E843298F99AD7ULL);  // exactly one 32-byte stripe
    EXPECT_EQ(xxh64("Nobody inspects the spammish repetition"), 0xFBCEA83C8A378BF1ULL);  // stripe + tail
}

TEST(PlanFileHash, SeedAndEveryByteMatter) {
    const std::string s(100, 'x');
    EXPECT_NE(xxh64(s, 0), xxh64(s, 1));
    for (std::size_t i = 0; i < s.size(); ++i) {
        std::string t = s;
        t[i] ^= 1;
        EXPECT_NE(xxh64(t), xxh64(s)) << i;
    }
}

TEST(PlanFileHash, EmptySpanWithoutData) {
    // An empty std::vector's data() is null; hashing it must not form null + 8
    // (undefined behaviour, found by fuzzing a plan with an empty array).
    const std::span<const std::byte> empty;
    ASSERT_EQ(empty.data(), nullptr);
    EXPECT_EQ(hash64(empty), 0xEF46DB3751D8E999ULL);
    EXPECT_EQ(hash64(empty, 7), xxh64("", 7));
}
