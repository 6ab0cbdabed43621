// Damaged CGNS files: every prefix of a valid file (HDF5 and ADF) is refused
// with a dgwarp::Error naming the file, never a crash, a hang or a wrong mesh;
// so are files with bytes overwritten.
#include <gtest/gtest.h>

#include <fstream>
#include <random>

#include "dgwarp/core/error.hpp"
#include "dgwarp/io/cgns.hpp"
#include "support/cgns_test_writer.hpp"

using namespace dgwarp;
using namespace dgwarp::test;

namespace {

void cgns_write_bytes(const std::filesystem::path& file, const std::string& bytes) {
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    ASSERT_TRUE(out.good()) << file;
}

}  // namespace

TEST(CgnsReadDamage, EveryPrefixOfAValidFileFailsCleanly) {
    const auto dir = scratch_dir();
    for (const std::string name : {"tet.cgns", "tet-adf.cgns"}) {
        const std::string bytes = slurp(cgns_data(name));
        const Mesh whole = read_cgns(cgns_data(name));
        const auto file = dir / ("cut-" + name);
        // The file grows by one byte a step (truncating a file is slow on some file systems).
        std::ofstream grow(file, std::ios::binary | std::ios::trunc);
        for (std::size_t n = 0; n < bytes.size(); grow.put(bytes[n]), grow.flush(), ++n) {
            ASSERT_TRUE(grow.good());
            try {
                const Mesh mesh = read_cgns(file);
                ASSERT_TRUE(mesh == whole) << name << " cut at " << n << " read as another mesh";
                // HDF5 reads a file whose unused tail was cut; the mesh is then whole.
            } catch (const Error& e) {
                ASSERT_NE(std::string(e.what()).find(file.string()), std::string::npos) << e.what();
            } catch (const std::exception& e) {
                FAIL() << name << " cut at " << n << ": not a dgwarp::Error: " << e.what();
            }
        }
    }
}

// Bytes overwritten at random places: an error or a mesh that passes
// validate() (read_cgns checks it), never a crash.
TEST(CgnsReadDamage, OverwrittenBytesFailCleanly) {
    const auto dir = scratch_dir();
    std::mt19937 random(15);
    for (const std::string name : {"tet.cgns", "tet-adf.cgns"}) {
        const std::string bytes = slurp(cgns_data(name));
        std::uniform_int_distribution<std::size_t> at(0, bytes.size() - 1);
        std::uniform_int_distribution<int> value(0, 255);
        for (int trial = 0; trial < 300; ++trial) {
            std::string damaged = bytes;
            for (int k = 0; k < 4; ++k) damaged[at(random)] = static_cast<char>(value(random));
            const auto file = dir / ("damaged-" + name);
            cgns_write_bytes(file, damaged);
            try {
                read_cgns(file);
            } catch (const Error&) {
            } catch (const std::exception& e) {
                FAIL() << name << " trial " << trial << ": not a dgwarp::Error: " << e.what();
            }
        }
    }
}
