#pragma once
// Shared by the OpenFOAM tests: the committed cases (tests/data/openfoam) and
// checks of a Mesh against the polyMesh files it was read from, parsed here
// independently of the reader (ascii files as OpenFOAM writes them).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "dgwarp/io/openfoam/openfoam.hpp"
#include "dgwarp/io/openfoam/openfoam_poly_mesh.hpp"
#include "dgwarp/mesh/mesh.hpp"
#include "dgwarp/quality/mesh_quality.hpp"
#include "support/test_paths.hpp"

namespace dgwarp::test {

inline std::filesystem::path openfoam_case(const std::string& name) {
    return source_dir() / "tests" / "data" / "openfoam" / name;
}

inline PolyMeshFiles openfoam_files(const std::string& name) {
    const auto dir = openfoam_case(name) / "constant" / "polyMesh";
    return {slurp(dir / "points"), slurp(dir / "faces"), slurp(dir / "owner"), slurp(dir / "neighbour"),
            slurp(dir / "boundary")};
}

/// The numbers of an ascii FoamFile's body (after the header's closing
/// brace), with every non-digit character (brackets, blanks) a separator.
inline std::vector<double> foam_body_numbers(const std::string& text) {
    std::string body = text.substr(text.find("\n}") + 2);
    body = body.substr(0, body.rfind("// *"));
    std::vector<double> numbers;
    std::size_t i = body.find("// *");  // the separator line after the header
    i = i == std::string::npos ? 0 : body.find('\n', i);
    while (i < body.size()) {
        const char c = body[i];
        if ((c >= '0' && c <= '9') || c == '-' || c == '.') {
            char* end = nullptr;
            numbers.push_back(std::strtod(body.c_str() + i, &end));
            i = static_cast<std::size_t>(end - body.c_str());
        } else {
            ++i;
        }
    }
    return numbers;
}

/// An ascii faceList: N, then k and k labels per face.
inline std::vector<std::vector<NodeId>> foam_ascii_faces(const std::string& text) {
    const std::vector<double> v = foam_body_numbers(text);
    std::vector<std::vector<NodeId>> faces(static_cast<std::size_t>(v.at(0)));
    std::size_t at = 1;
    for (auto& face : faces) {
        const auto k = static_cast<std::size_t>(v.at(at++));
        for (std::size_t i = 0; i < k; ++i) face.push_back(static_cast<NodeId>(v.at(at++)));
    }
    return faces;
}

/// An ascii labelList: N, then N labels.
inline std::vector<std::int64_t> foam_ascii_labels(const std::string& text) {
    const std::vector<double> v = foam_body_numbers(text);
    return {v.begin() + 1, v.begin() + 1 + static_cast<std::ptrdiff_t>(v.at(0))};
}

/// `b` is `a` rotated.
inline bool foam_same_cycle(const std::vector<NodeId>& a, const std::vector<NodeId>& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t r = 0; r < a.size(); ++r) {
        bool same = true;
        for (std::size_t i = 0; i < a.size() && same; ++i) same = a[i] == b[(i + r) % a.size()];
        if (same) return true;
    }
    return false;
}

/// The outward faces of cell c of `mesh` (VTK order, positive orientation).
inline std::vector<std::vector<NodeId>> foam_cell_faces(const Mesh& mesh, std::size_t c) {
    const auto nodes = mesh.cells.nodes_of(c);
    const foam::FaceTable& t = foam::outward_faces(mesh.cells.types[c]);
    std::vector<std::vector<NodeId>> faces;
    for (int k = 0; k < t.count; ++k) {
        std::vector<NodeId> f;
        for (int i = 0; i < t.size[k]; ++i) f.push_back(nodes[static_cast<std::size_t>(t.node[k][i])]);
        faces.push_back(f);
    }
    return faces;
}

/// Every cell of `mesh` is bounded by exactly the faces the ascii polyMesh
/// `files` gives it, each turned out of it (as written for its owner,
/// reversed for its neighbour); every cell is valid (positive Knupp quality);
/// the points are the file's, in order.
inline void expect_mesh_matches_ascii_files(const Mesh& mesh, const PolyMeshFiles& files) {
    const std::vector<double> points = foam_body_numbers(files.points);
    ASSERT_EQ(points.size(), 1 + 3 * mesh.num_points());
    for (std::size_t i = 0; i < mesh.points.size(); ++i) ASSERT_EQ(mesh.points[i], points[i + 1]) << i;
    const auto faces = foam_ascii_faces(files.faces);
    const auto owner = foam_ascii_labels(files.owner);
    const auto neighbour = foam_ascii_labels(files.neighbour);
    std::vector<std::vector<std::vector<NodeId>>> expected(mesh.cells.size());
    for (std::size_t f = 0; f < faces.size(); ++f) {
        expected.at(static_cast<std::size_t>(owner[f])).push_back(faces[f]);
        if (f < neighbour.size()) {
            std::vector<NodeId> reversed(faces[f].rbegin(), faces[f].rend());
            expected.at(static_cast<std::size_t>(neighbour[f])).push_back(reversed);
        }
    }
    for (std::size_t c = 0; c < mesh.cells.size(); ++c) {
        const auto got = foam_cell_faces(mesh, c);
        ASSERT_EQ(got.size(), expected[c].size()) << "cell " << c;
        for (const auto& face : got)
            EXPECT_TRUE(std::any_of(expected[c].begin(), expected[c].end(),
                                    [&](const auto& e) { return foam_same_cycle(face, e); }))
                << "cell " << c;
    }
    const std::vector<std::int8_t> own = cell_orientations(mesh);
    EXPECT_EQ(std::count(own.begin(), own.end(), 1), static_cast<std::ptrdiff_t>(own.size()));
    const std::vector<double> q = cell_qualities(mesh, own);
    EXPECT_GT(*std::min_element(q.begin(), q.end()), 0.0);
}

}  // namespace dgwarp::test
