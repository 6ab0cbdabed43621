#include "dgwarp/io/vtu/vtu.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "dgwarp/core/error.hpp"
#include "dgwarp/io/vtu/base64.hpp"
#include "support/test_paths.hpp"

using namespace dgwarp;
using dgwarp::test::slurp;
using nlohmann::json;

namespace {

// 2D: a quadrilateral and three triangles on 7 nodes.
Mesh mixed_2d_mesh() {
    Mesh m;
    m.dim = 2;
    m.points = {0, 0, 1, 0, 2.5, 0, 0, 1, 1, 1.25, 2, 1, 1, 2};
    const NodeId q[] = {0, 1, 4, 3}, t0[] = {1, 2, 5}, t1[] = {1, 5, 4}, t2[] = {3, 4, 6};
    m.cells.push_back(CellType::quadrilateral, q);
    m.cells.push_back(CellType::triangle, t0);
    m.cells.push_back(CellType::triangle, t1);
    m.cells.push_back(CellType::triangle, t2);
    Marker wall{"wall", {}};
    const NodeId e[] = {0, 1};
    wall.elements.push_back(CellType::line, e);
    m.markers.push_back(wall);
    return m;
}

// 3D: a unit-cube hexahedron, a pyramid on its top face, a prism beside it
// and a tetrahedron beside the prism (12 nodes, one cell of each solid type).
Mesh solids_3d_mesh() {
    Mesh m;
    m.dim = 3;
    m.points = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0,     // 0-3: cube bottom
                0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1,     // 4-7: cube top
                0.5, 0.5, 1.75,                         // 8: pyramid apex
                2, 0, 0, 2, 0, 1,                       // 9, 10
                3, 0.5, 0.25};                          // 11
    const NodeId hex[] = {0, 1, 2, 3, 4, 5, 6, 7}, pyr[] = {4, 5, 6, 7, 8},
                 prism[] = {1, 9, 2, 5, 10, 6}, tet[] = {9, 11, 2, 10};
    m.cells.push_back(CellType::hexahedron, hex);
    m.cells.push_back(CellType::pyramid, pyr);
    m.cells.push_back(CellType::prism, prism);
    m.cells.push_back(CellType::tetrahedron, tet);
    return m;
}

// A 3-component point field "displacement" and a cell field "quality" with
// distinct, exactly representable values.
MeshFields displacement_and_quality(const Mesh& mesh) {
    MeshFields f;
    Field d{"displacement", 3, {}};
    for (std::size_t i = 0; i < mesh.num_points(); ++i) {
        const double s = static_cast<double>(i);
        d.values.insert(d.values.end(), {0.125 * s, -0.5 * s + 1, mesh.dim == 3 ? s * s / 64 : 0.0});
    }
    Field q{"quality", 1, {}};
    for (std::size_t c = 0; c < mesh.cells.size(); ++c) q.values.push_back(1.0 / static_cast<double>(1u << c));
    f.point_data.push_back(d);
    f.cell_data.push_back(q);
    return f;
}

std::filesystem::path read_vtu_script() { return test::source_dir() / "tests" / "tools" / "read_vtu.py"; }

test::CommandResult run_read_vtu(const std::filesystem::path& file) {
    return test::run_command(std::string(DGWARP_PYTHON) + " '" + read_vtu_script().string() + "' '" +
                             file.string() + "'");
}

// The JSON summary read_vtu.py prints for a file it accepts.
json checked_summary(const std::filesystem::path& file) {
    const auto r = run_read_vtu(file);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return json::parse(r.out);
}

const json& array_named(const json& summary, const std::string& section, const std::string& name) {
    for (const json& a : summary["arrays"])
        if (a["section"] == section && a["name"] == name) return a;
    ADD_FAILURE() << "no array " << section << "/" << name;
    static const json none;
    return none;
}


void overwrite(const std::filesystem::path& file, const std::string& text) {
    std::ofstream(file, std::ios::binary | std::ios::trunc) << text;
}

// Everything read_vtu.py reports, checked against values computed here from the mesh.
void expect_summary_matches(const json& s, const Mesh& mesh, const MeshFields& fields) {
    const std::size_t n = mesh.num_points(), dim = static_cast<std::size_t>(mesh.dim);
    EXPECT_EQ(s["points"], n);
    EXPECT_EQ(s["cells"], mesh.cells.size());

    std::map<std::string, int> type_counts;
    for (CellType t : mesh.cells.types) ++type_counts[std::to_string(vtk_cell_id(t))];
    EXPECT_EQ(s["cell_types"], json(type_counts));

    for (std::size_t c = 0; c < 3; ++c) {
        double sum = 0;
        for (std::size_t i = 0; c < dim && i < n; ++i) sum += mesh.points[i * dim + c];
        EXPECT_DOUBLE_EQ(s["coordinate_sums"][c].get<double>(), sum) << "component " << c;
    }

    const json& conn = array_named(s, "Cells", "connectivity");
    EXPECT_EQ(conn["type"], "Int64");
    EXPECT_EQ(conn["tuples"], mesh.cells.nodes.size());
    EXPECT_EQ(conn["max"], *std::max_element(mesh.cells.nodes.begin(), mesh.cells.nodes.end()));
    EXPECT_EQ(array_named(s, "Cells", "offsets")["max"], mesh.cells.nodes.size());
    EXPECT_EQ(array_named(s, "Cells", "types")["type"], "UInt8");
    EXPECT_EQ(array_named(s, "Points", "Points")["type"], "Float64");

    auto expect_field = [&](const std::string& section, const Field& f, std::size_t count) {
        const json& a = array_named(s, section, f.name);
        EXPECT_EQ(a["type"], "Float64");
        EXPECT_EQ(a["components"], f.components);
        EXPECT_EQ(a["tuples"], count);
        const auto k = static_cast<std::size_t>(f.components);
        for (std::size_t c = 0; c < k; ++c) {
            double lo = f.values[c], hi = f.values[c];
            for (std::size_t i = 0; i < count; ++i) {
                lo = std::min(lo, f.values[i * k + c]);
                hi = std::max(hi, f.values[i * k + c]);
            }
            EXPECT_EQ(a["component_min"][c].get<double>(), lo) << f.name << " component " << c;
            EXPECT_EQ(a["component_max"][c].get<double>(), hi) << f.name << " component " << c;
        }
    };
    for (const Field& f : fields.point_data) expect_field("PointData", f, n);
    for (const Field& f : fields.cell_data) expect_field("CellData", f, mesh.cells.size());
    EXPECT_EQ(s["arrays"].size(), 4 + fields.point_data.size() + fields.cell_data.size());
}

// Replaces the base64 text of the DataArray called `name` by `text`.
std::string with_array_text(std::string xml, const std::string& name, const std::string& text) {
    const auto tag = xml.find("Name=\"" + name + "\"");
    const auto begin = xml.find('>', tag) + 1;
    const auto end = xml.find("</DataArray>", begin);
    EXPECT_NE(tag, std::string::npos);
    return xml.replace(begin, end - begin, text);
}

// base64 of [UInt64 byte count][int64 values], as a DataArray holds them.
std::string encoded_int64s(const std::vector<std::int64_t>& values) {
    std::vector<std::byte> raw(8 + 8 * values.size());
    const std::uint64_t n = 8 * values.size();
    std::memcpy(raw.data(), &n, 8);
    std::memcpy(raw.data() + 8, values.data(), n);
    return base64_encode(raw);
}

}  // namespace

TEST(VtuWrite, Mixed2dMeshReadsBackWithEveryCountAndValue) {
    const Mesh mesh = mixed_2d_mesh();
    const MeshFields fields = displacement_and_quality(mesh);
    const auto file = test::scratch_dir() / "mixed.vtu";
    write_vtu(file, mesh, fields);
    const json s = checked_summary(file);
    expect_summary_matches(s, mesh, fields);
    EXPECT_EQ(s["cell_types"], (json{{"5", 3}, {"9", 1}}));
    EXPECT_EQ(s["coordinate_sums"], (json{7.5, 5.25, 0.0}));  // by hand; z = 0 in 2D
    EXPECT_EQ(array_named(s, "Points", "Points")["component_max"][2], 0.0);
}

TEST(VtuWrite, AllFourSolidTypesReadBackWithEveryCountAndValue) {
    const Mesh mesh = solids_3d_mesh();
    const MeshFields fields = displacement_and_quality(mesh);
    const auto file = test::scratch_dir() / "solids.vtu";
    write_vtu(file, mesh, fields);
    const json s = checked_summary(file);
    expect_summary_matches(s, mesh, fields);
    EXPECT_EQ(s["cell_types"], (json{{"10", 1}, {"12", 1}, {"13", 1}, {"14", 1}}));
    EXPECT_EQ(s["coordinate_sums"], (json{11.5, 5.0, 7.0}));  // by hand
    EXPECT_EQ(array_named(s, "CellData", "quality")["min"], 0.125);
    EXPECT_EQ(array_named(s, "PointData", "displacement")["max"], 121.0 / 64);  // 11² / 64
}

TEST(VtuWrite, HeaderDeclaresTheAgreedFormat) {
    const auto file = test::scratch_dir() / "header.vtu";
    write_vtu(file, solids_3d_mesh());
    const std::string text = slurp(file);
    EXPECT_NE(text.find("<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" "
                        "header_type=\"UInt64\">"),
              std::string::npos);
    EXPECT_NE(text.find("<Piece NumberOfPoints=\"12\" NumberOfCells=\"4\">"), std::string::npos);
    EXPECT_EQ(text.find("format=\"ascii\""), std::string::npos);
    EXPECT_EQ(text.find("wall"), std::string::npos);  // markers are not written
    expect_summary_matches(checked_summary(file), solids_3d_mesh(), {});
}

TEST(VtuWrite, StreamAndFileOverloadsWriteTheSameBytes) {
    const Mesh mesh = mixed_2d_mesh();
    const MeshFields fields = displacement_and_quality(mesh);
    const auto file = test::scratch_dir() / "same.vtu";
    write_vtu(file, mesh, fields);
    std::ostringstream out;
    write_vtu(out, mesh, fields);
    EXPECT_EQ(out.str(), slurp(file));
}

TEST(VtuWrite, FieldNamesAreXmlEscaped) {
    const Mesh mesh = mixed_2d_mesh();
    MeshFields fields;
    const std::string name = "a<b> & \"c\" 'd'\tend";
    fields.point_data.push_back({name, 1, std::vector<double>(mesh.num_points(), 2.0)});
    const auto file = test::scratch_dir() / "escaped.vtu";
    write_vtu(file, mesh, fields);
    const json s = checked_summary(file);
    EXPECT_EQ(array_named(s, "PointData", name)["max"], 2.0);
}

TEST(VtuWrite, FieldOfTheWrongSizeThrowsMeshErrorNamingIt) {
    const Mesh mesh = mixed_2d_mesh();
    auto expect_rejected = [&](const MeshFields& fields, const std::string& name) {
        std::ostringstream out;
        try {
            write_vtu(out, mesh, fields);
            ADD_FAILURE() << "no error for " << name;
        } catch (const MeshError& e) {
            EXPECT_NE(std::string(e.what()).find("'" + name + "'"), std::string::npos) << e.what();
        }
        EXPECT_TRUE(out.str().empty()) << "wrote before checking";
    };
    MeshFields short_point = displacement_and_quality(mesh);
    short_point.point_data[0].values.pop_back();
    expect_rejected(short_point, "displacement");

    MeshFields long_cell = displacement_and_quality(mesh);
    long_cell.cell_data[0].values.push_back(1.0);
    expect_rejected(long_cell, "quality");

    MeshFields no_components = displacement_and_quality(mesh);
    no_components.cell_data.push_back({"empty", 0, {}});
    expect_rejected(no_components, "empty");

    MeshFields control_char = displacement_and_quality(mesh);
    control_char.cell_data.push_back({std::string("bell\a"), 1, std::vector<double>(mesh.cells.size())});
    expect_rejected(control_char, "bell\a");
}

TEST(VtuWrite, InconsistentMeshThrowsMeshError) {
    Mesh mesh = solids_3d_mesh();
    mesh.cells.nodes.back() = 12;  // one past the last node
    std::ostringstream out;
    EXPECT_THROW(write_vtu(out, mesh), MeshError);
}

TEST(VtuWrite, FailedWriteLeavesExistingFileIntact) {
    const Mesh mesh = mixed_2d_mesh();
    MeshFields bad = displacement_and_quality(mesh);
    bad.point_data[0].values.resize(3);
    const auto dir = test::scratch_dir();
    const auto file = dir / "keep.vtu";
    write_vtu(file, mesh, displacement_and_quality(mesh));
    const std::string before = slurp(file);
    EXPECT_THROW(write_vtu(file, mesh, bad), MeshError);
    EXPECT_EQ(slurp(file), before);
    EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir), std::filesystem::directory_iterator()), 1)
        << "a temporary file was left behind";
}

TEST(VtuReadTool, RejectsTruncatedFile) {
    const auto file = test::scratch_dir() / "truncated.vtu";
    write_vtu(file, solids_3d_mesh(), displacement_and_quality(solids_3d_mesh()));
    const std::string text = slurp(file);
    overwrite(file, text.substr(0, text.size() / 2));
    const auto r = run_read_vtu(file);
    EXPECT_NE(r.exit_code, 0);
    EXPECT_NE(r.err.find("XML"), std::string::npos) << r.err;
}

TEST(VtuReadTool, RejectsWrongByteCount) {
    const auto file = test::scratch_dir() / "byte_count.vtu";
    write_vtu(file, solids_3d_mesh());
    std::string text = slurp(file);
    // The first base64 character of an array holds the top 6 bits of the low
    // byte of its UInt64 byte count; changing it changes the count.
    const auto pos = text.find_first_not_of(" \n", text.find('>', text.find("Name=\"offsets\"")) + 1);
    text[pos] = text[pos] == 'Q' ? 'R' : 'Q';
    overwrite(file, text);
    const auto r = run_read_vtu(file);
    EXPECT_NE(r.exit_code, 0);
    EXPECT_NE(r.err.find("'offsets': header declares"), std::string::npos) << r.err;
}

TEST(VtuReadTool, RejectsWrongNumberOfPoints) {
    const auto file = test::scratch_dir() / "num_points.vtu";
    write_vtu(file, solids_3d_mesh());
    std::string text = slurp(file);
    const std::string from = "NumberOfPoints=\"12\"";
    text.replace(text.find(from), from.size(), "NumberOfPoints=\"13\"");
    overwrite(file, text);
    const auto r = run_read_vtu(file);
    EXPECT_NE(r.exit_code, 0);
    EXPECT_NE(r.err.find("NumberOfPoints is 13"), std::string::npos) << r.err;
}

TEST(VtuReadTool, RejectsNodeIdOutOfRangeAndBadOffsets) {
    const Mesh mesh = solids_3d_mesh();
    const auto file = test::scratch_dir() / "ids.vtu";
    write_vtu(file, mesh);
    const std::string good = slurp(file);

    std::vector<std::int64_t> conn(mesh.cells.nodes.begin(), mesh.cells.nodes.end());
    conn[3] = 12;  // = NumberOfPoints
    overwrite(file, with_array_text(good, "connectivity", encoded_int64s(conn)));
    auto r = run_read_vtu(file);
    EXPECT_NE(r.exit_code, 0);
    EXPECT_NE(r.err.find("connectivity[3] = 12"), std::string::npos) << r.err;

    // The re-encoded original is accepted, so the failure above is the bad id.
    conn[3] = mesh.cells.nodes[3];
    overwrite(file, with_array_text(good, "connectivity", encoded_int64s(conn)));
    EXPECT_EQ(run_read_vtu(file).exit_code, 0);

    std::vector<std::int64_t> offsets(mesh.cells.offsets.begin() + 1, mesh.cells.offsets.end());
    offsets.back() -= 1;  // the tetrahedron would have 3 nodes
    overwrite(file, with_array_text(good, "offsets", encoded_int64s(offsets)));
    r = run_read_vtu(file);
    EXPECT_NE(r.exit_code, 0);
    EXPECT_NE(r.err.find("cell 3"), std::string::npos) << r.err;
}

TEST(VtuWrite, NonFiniteFieldValuesAreWrittenAsTheyAre) {
    const Mesh mesh = mixed_2d_mesh();
    MeshFields fields;
    std::vector<double> q = {0.5, std::numeric_limits<double>::quiet_NaN(), -0.25,
                             std::numeric_limits<double>::infinity()};
    fields.cell_data.push_back({"quality", 1, q});
    const auto file = test::scratch_dir() / "nan.vtu";
    write_vtu(file, mesh, fields);
    const json s = checked_summary(file);
    const json& a = array_named(s, "CellData", "quality");
    EXPECT_EQ(a["non_finite"], 2);
    EXPECT_EQ(a["min"], -0.25);
    EXPECT_EQ(a["max"], 0.5);
}
