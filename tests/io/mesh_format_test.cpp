// The format registry (io/mesh_format.hpp): one row per format, chosen by
// extension first, folders second; every row whole, and each format reads
// back what it writes through read_mesh / write_mesh.
#include "dgwarp/io/mesh_format.hpp"

#include <gtest/gtest.h>

#include <set>
#include <string>

#include "dgwarp/cases/rect_box.hpp"
#include "dgwarp/core/error.hpp"
#include "support/test_paths.hpp"

using namespace dgwarp;

TEST(MeshFormats, EveryRowIsWholeAndExtensionsAreUniqueLowerCase) {
    std::set<std::string_view> extensions, names;
    int folders = 0;
    for (const MeshFormat* f : mesh_formats()) {
        EXPECT_TRUE(names.insert(f->name).second) << f->name;
        EXPECT_NE(f->read, nullptr) << f->name;
        EXPECT_NE(f->write, nullptr) << f->name;
        EXPECT_NE(f->check_writable, nullptr) << f->name;
        if (f->extension.empty()) {
            ++folders;
            EXPECT_NE(f->is_input, nullptr) << f->name;
            EXPECT_NE(f->is_output, nullptr) << f->name;
        } else {
            EXPECT_TRUE(extensions.insert(f->extension).second) << f->extension;
            EXPECT_EQ(lower_case_extension(std::string("x") + std::string(f->extension)), f->extension);
        }
    }
    EXPECT_EQ(folders, 1);  // OpenFOAM
    const std::vector<std::string> readable = readable_extensions();
    EXPECT_EQ(std::set<std::string_view>(readable.begin(), readable.end()), extensions);
}

TEST(MeshFormats, ChosenByExtensionWhateverTheCaseThenFolders) {
    EXPECT_EQ(format_to_read("wing.SU2"), &su2_format);
    EXPECT_EQ(format_to_write("a/b/wing.msh"), &gmsh_format);
    EXPECT_EQ(format_to_write("wing.Vtu"), &vtu_format);
    EXPECT_EQ(format_to_read("wing.cgns"), &cgns_format);
    EXPECT_EQ(format_to_read("wing.txt"), nullptr);
    EXPECT_EQ(format_to_write("wing.txt"), nullptr);
    const auto openfoam_case = test::source_dir() / "tests" / "data" / "openfoam" / "mixed";
    EXPECT_EQ(format_to_read(openfoam_case), &openfoam_format);
    EXPECT_EQ(format_to_write(test::scratch_dir() / "out/"), &openfoam_format);
    EXPECT_EQ(format_to_write(test::scratch_dir() / "out"), &openfoam_format);  // no extension: a folder
    // Only SU2 has zones, only VTU keeps fields.
    for (const MeshFormat* f : mesh_formats()) {
        EXPECT_EQ(f->zones, f == &su2_format) << f->name;
        EXPECT_EQ(f->fields, f == &vtu_format) << f->name;
    }
    EXPECT_TRUE(writes_fields("x.vtu"));
    EXPECT_FALSE(writes_fields("x.su2"));
    EXPECT_THROW(read_mesh("x.msh", ReadOptions{.zone = 2}), FormatError);
}

TEST(MeshFormats, EachFormatReadsBackWhatItWrites) {
    const Mesh mesh = make_rect_box();
    const auto dir = test::scratch_dir();
    for (const MeshFormat* f : mesh_formats()) {
        if (f == &openfoam_format) continue;  // 3D only (openfoam_write_test.cpp)
        const auto file = dir / ("box" + std::string(f->extension));
        check_mesh_writable(file, mesh);
        write_mesh(file, mesh);
        const Mesh back = read_mesh(file);
        EXPECT_EQ(back.points, mesh.points) << f->name;
        EXPECT_EQ(back.cells.size(), mesh.cells.size()) << f->name;
        EXPECT_EQ(back.markers.size(), mesh.markers.size()) << f->name;
    }
}
