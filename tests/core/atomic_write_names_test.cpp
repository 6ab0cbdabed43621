// write_file_atomically with long file names: its temporary name beside the
// output must fit wherever the output's own name fits.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "dgwarp/core/atomic_write.hpp"
#include "support/test_paths.hpp"

using namespace dgwarp;

namespace {

std::string read_back(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
}

}  // namespace

TEST(AtomicWriteNames, NamesUpTo255BytesAreWrittenAndNoTemporaryIsLeft) {
    // Issue #27, item 15: names of 240-255 bytes failed, ".NAME.tmp.PID.RANDOM" being too long.
    const auto dir = test::scratch_dir();
    for (std::size_t length : {200u, 240u, 250u, 255u}) {
        const std::string name = std::string(length - 4, 'a') + ".su2";
        write_file_atomically(dir / name, [&](std::ostream& out) { out << length; });
        EXPECT_EQ(read_back(dir / name), std::to_string(length));
    }
    // A name of two-byte UTF-8 characters ("é"), 254 bytes: the temporary name is cut between characters.
    std::string accented;
    while (accented.size() + 2 <= 250) accented += "\xC3\xA9";
    write_file_atomically(dir / (accented + ".su2"), [](std::ostream& out) { out << "x"; });
    EXPECT_EQ(read_back(dir / (accented + ".su2")), "x");
    std::size_t files = 0;
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
        EXPECT_NE(entry.path().filename().string().front(), '.') << entry.path();
        ++files;
    }
    EXPECT_EQ(files, 5u);
}
