#include "dgwarp/io/mesh_io.hpp"

#include <gtest/gtest.h>

#include <cerrno>
#include <filesystem>
#include <fstream>
#include <string>

#include "dgwarp/core/error.hpp"
#include "support/test_paths.hpp"

using namespace dgwarp;

TEST(ReadMesh, APathWithoutExtensionThatIsNotThereIsAMissingFile) {
    const auto dir = test::scratch_dir();
    // Without an extension it would be an OpenFOAM case; it is not there at all.
    for (const std::string name : {"nosuchcase", "nosuch/"}) {
        const auto path = dir / name;
        try {
            read_mesh(path);
            FAIL() << name << ": no error";
        } catch (const IoError& e) {
            EXPECT_EQ(e.error_number(), ENOENT) << e.what();
            EXPECT_EQ(std::string(e.what()),
                      path.string() + ": cannot open file for reading: No such file or directory (dgwarp reads .su2, "
                                      ".msh, .vtu, .cgns files and OpenFOAM case folders)");
        }
    }
}

TEST(ReadMesh, AFileOfAnUnknownTypeSaysWhichTypesAreReadThereOrNot) {
    const auto dir = test::scratch_dir();
    const auto path = dir / "mesh.xyz", missing = dir / "missing.xyz";
    std::ofstream(path) << "1 2 3\n";
    for (const auto& p : {path, missing}) {
        try {
            read_mesh(p);
            FAIL() << p << ": no error";
        } catch (const FormatError& e) {
            EXPECT_EQ(std::string(e.what()), p.string() + ": cannot read files of type '.xyz'; dgwarp reads .su2, "
                                                          ".msh, .vtu, .cgns and OpenFOAM case folders");
        }
    }
}
