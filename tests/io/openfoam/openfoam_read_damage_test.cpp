// Damaged OpenFOAM polyMesh files: every kind of damage gives an error naming
// the file and the line (ParseError; FormatError for what dgwarp does not
// read), never a crash, a hang or a wrong mesh.
#include <gtest/gtest.h>

#include <string>

#include "dgwarp/core/error.hpp"
#include "dgwarp/io/openfoam/openfoam.hpp"
#include "io/openfoam/openfoam_test_support.hpp"

using namespace dgwarp;
using namespace dgwarp::test;

namespace {

const std::filesystem::path damaged_dir = "damaged/constant/polyMesh";

/// `files` with the file `name` replaced by `text`.
PolyMeshFiles foam_with(PolyMeshFiles files, const std::string& name, std::string text) {
    std::string* parts[] = {&files.points, &files.faces, &files.owner, &files.neighbour, &files.boundary};
    for (int k = 0; k < 5; ++k)
        if (name == poly_mesh_file_names[k]) *parts[k] = std::move(text);
    return files;
}

const std::string& foam_file(const PolyMeshFiles& files, const std::string& name) {
    const std::string* parts[] = {&files.points, &files.faces, &files.owner, &files.neighbour, &files.boundary};
    for (int k = 0; k < 5; ++k)
        if (name == poly_mesh_file_names[k]) return *parts[k];
    throw std::logic_error(name);
}

/// The cavity's file `name` with its line `line` (1-based) replaced by `text`.
PolyMeshFiles cavity_with_line(const std::string& name, std::size_t line, const std::string& text) {
    const PolyMeshFiles files = openfoam_files("cavity");
    std::string s = foam_file(files, name);
    std::size_t begin = 0;
    for (std::size_t l = 1; l < line; ++l) begin = s.find('\n', begin) + 1;
    const std::size_t end = s.find('\n', begin);
    s.replace(begin, end - begin, text);
    return foam_with(files, name, s);
}

/// Reading `files` throws a ParseError in file `name` at `line` whose
/// expected-text contains `expected` (and whose found-text is `found` when given).
void expect_foam_parse_error(const PolyMeshFiles& files, const std::string& name, std::size_t line,
                             const std::string& expected, const char* found = nullptr) {
    try {
        read_openfoam_files(damaged_dir, files);
        ADD_FAILURE() << "no error";
    } catch (const ParseError& e) {
        EXPECT_EQ(e.file(), (damaged_dir / name).string()) << e.what();
        EXPECT_EQ(e.line(), line) << e.what();
        EXPECT_NE(e.expected().find(expected), std::string::npos) << e.what();
        if (found) {
            EXPECT_EQ(e.found(), found) << e.what();
        }
    } catch (const std::exception& e) {
        ADD_FAILURE() << "not a ParseError: " << e.what();
    }
}

}  // namespace

// Every prefix of every file, ascii and binary: an error naming that file, or
// (when only the closing comment was cut) the whole mesh.
TEST(OpenFoamReadDamage, EveryPrefixOfEveryFileFailsCleanlyInThatFile) {
    for (const std::string name : {"cavity", "cavity-binary"}) {
        const PolyMeshFiles files = openfoam_files(name);
        const Mesh whole = read_openfoam_files(damaged_dir, files);
        for (const char* file : poly_mesh_file_names) {
            const std::string& text = foam_file(files, file);
            std::size_t errors = 0;
            for (std::size_t n = 0; n < text.size(); ++n) {
                try {
                    const Mesh mesh = read_openfoam_files(damaged_dir, foam_with(files, file, text.substr(0, n)));
                    ASSERT_TRUE(mesh == whole) << name << "/" << file << " cut at " << n;
                    ASSERT_GT(n, text.rfind(')')) << name << "/" << file << " cut at " << n;
                } catch (const ParseError& e) {
                    ++errors;
                    ASSERT_EQ(e.file(), (damaged_dir / file).string()) << e.what();
                    ASSERT_GE(e.line(), 1u) << e.what();
                } catch (const std::exception& e) {
                    FAIL() << name << "/" << file << " cut at " << n << ": not a ParseError: " << e.what();
                }
            }
            EXPECT_GT(errors, text.size() / 2) << name << "/" << file;
        }
    }
}

TEST(OpenFoamReadDamage, CountsThatDoNotMatchNameTheirLine) {
    // 54 owners for 55 faces: the list is whole, its size wrong.
    PolyMeshFiles files = openfoam_files("cavity");
    std::string owner = files.owner;
    owner.replace(owner.find("\n55\n"), 4, "\n54\n");
    owner.erase(owner.rfind("\n)") - 2, 2);  // the last owner, "\n1"
    expect_foam_parse_error(foam_with(files, "owner", owner), "owner", 20, "one owner per face: 55", "54");
    // The owner list says 56 and has 55.
    expect_foam_parse_error(cavity_with_line("owner", 20, "56"), "owner", 77, "label 55 (0-based) of the 56");
    // Patches that leave boundary faces out, or do not follow each other.
    expect_foam_parse_error(cavity_with_line("boundary", 24, "        nFaces          3;"), "boundary", 27,
                            "startFace 20 in patch 'fixedWalls' (the end of patch 'movingWall')", "21");
    expect_foam_parse_error(cavity_with_line("boundary", 25, "        startFace       16;"), "boundary", 20,
                            "startFace 17 in patch 'movingWall' (the number of internal faces", "16");
}

TEST(OpenFoamReadDamage, BadLabelsNameTheirLine) {
    expect_foam_parse_error(cavity_with_line("faces", 22, "4(5 25 26 40)"), "faces", 22,
                            "point labels of face 1 (0-based) of the 55 of the list on line 19 from 0 to 39", "40");
    expect_foam_parse_error(cavity_with_line("faces", 22, "4(5 25 -1 6)"), "faces", 22, "point labels of face 1", "-1");
    expect_foam_parse_error(cavity_with_line("faces", 23, "2(2 7)"), "faces", 23, "with at least 3 points", "2");
    expect_foam_parse_error(cavity_with_line("faces", 23, "4(2 7 27 x)"), "faces", 23, "point 3 of face 2", "x");
    expect_foam_parse_error(cavity_with_line("owner", 23, "-3"), "owner", 23, "the owner of face 1", "-3");
    // Face 0's neighbour is 1 (line 22 of neighbour); its owner is 0.
    expect_foam_parse_error(cavity_with_line("neighbour", 22, "0"), "neighbour", 22,
                            "a neighbour of face 0 other than its owner", "0");
    expect_foam_parse_error(cavity_with_line("points", 22, "(0.025 nan 0)"), "points", 22,
                            "coordinate 2 of 3 of point 1", "nan");
    expect_foam_parse_error(cavity_with_line("points", 22, "(0.025 0)"), "points", 22, "coordinate 3 of 3 of point 1",
                            ")");
}

TEST(OpenFoamReadDamage, FacesThatDoNotCloseACellNameTheCellAndALine) {
    // Face 0 (line 21) with two points swapped: its cells 0 and 1 are no longer closed.
    expect_foam_parse_error(cavity_with_line("faces", 21, "4(1 26 6 21)"), "faces", 21,
                            "the faces of cell 0 (faces 0, 1, 21, 27, 31, 43, oriented by owner and neighbour) to "
                            "close a hexahedron");
}

TEST(OpenFoamReadDamage, HeadersNameWhatIsWrong) {
    expect_foam_parse_error(cavity_with_line("faces", 11, "    format      text;"), "faces", 11, "format ascii or binary",
                            "text");
    expect_foam_parse_error(cavity_with_line("faces", 12, "    class       labelList;"), "faces", 12,
                            "class faceList or faceCompactList", "labelList");
    expect_foam_parse_error(cavity_with_line("owner", 8, "FoamFil"), "owner", 8, "the FoamFile header", "FoamFil");
    expect_foam_parse_error(cavity_with_line("points", 8, "/* a comment that never ends"), "points", 8,
                            "the end of the comment", "end of file");
    // A processor's patches: a decomposed case.
    try {
        read_openfoam_files(damaged_dir, cavity_with_line("boundary", 22, "        type            processor;"));
        FAIL();
    } catch (const FormatError& e) {
        EXPECT_EQ(std::string(e.what()).rfind((damaged_dir / "boundary").string() + ":22: ", 0), 0u) << e.what();
        EXPECT_NE(std::string(e.what()).find("reconstructPar"), std::string::npos) << e.what();
    }
}

TEST(OpenFoamReadDamage, BinaryFilesOfOtherLabelOrScalarSizesAreRefused) {
    const PolyMeshFiles files = openfoam_files("cavity-binary");
    for (const std::string arch : {"LSB;label=64;scalar=64", "LSB;label=32;scalar=32", "MSB;label=32;scalar=64"}) {
        std::string faces = files.faces;
        faces.replace(faces.find("LSB;label=32;scalar=64"), 22, arch);
        try {
            read_openfoam_files(damaged_dir, foam_with(files, "faces", faces));
            FAIL() << arch;
        } catch (const FormatError& e) {
            const std::string what = e.what();
            EXPECT_EQ(what.rfind((damaged_dir / "faces").string() + ":13: binary data with arch \"" + arch + "\"", 0), 0u)
                << what;
            EXPECT_NE(what.find("foamFormatConvert"), std::string::npos) << what;
        }
    }
}
