#include "dgwarp/plan/plan_file.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>

#include "dgwarp/core/error.hpp"
#include "support/box_in_box.hpp"
#include "support/test_paths.hpp"

using namespace dgwarp;
using dgwarp::test::box_in_box;
using dgwarp::test::BoxInBox;

namespace {

std::vector<char> plan_test_read_bytes(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
}

void write_bytes(const std::filesystem::path& p, const std::vector<char>& bytes) {
    std::ofstream out(p, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

BoundaryMotion rotating_motion(const BoxInBox& m) {
    BoundaryMotion motion(m.boundary.nodes.size());
    for (std::size_t b = 0; b < motion.size(); ++b)
        if (m.boundary.moving[b])
            motion[b] = {{0.01 * (b % 7), -0.02, 0.005}, {0.0, m.dim == 3 ? 0.1 : 0.0, 0.3}, m.inner_center};
    return motion;
}

// A ParseError naming the file and a byte offset; returns its message.
std::string expect_refused(const std::filesystem::path& file, const std::string& what) {
    try {
        load_dg_idw_plan(file);
        ADD_FAILURE() << "accepted: " << what;
    } catch (const ParseError& e) {
        EXPECT_EQ(e.file(), file.string()) << what;
        EXPECT_NE(std::string(e.what()).find("byte offset"), std::string::npos) << what << ": " << e.what();
        return e.what();
    }
    return {};
}

}  // namespace

TEST(PlanFile, SaveThenLoadDeformsBitIdentically) {
    const auto dir = dgwarp::test::scratch_dir();
    for (int dim : {2, 3}) {
        // Shared vertices and an outside node, so every array is non-trivial.
        BoxInBox m = box_in_box(dim, dim == 2 ? 20 : 8);
        const std::size_t first_extra = m.num_points();
        for (int d = 0; d < dim; ++d) m.points.push_back(d == 0 ? 1.5 : 0.5);  // outside the box
        for (int d = 0; d < dim; ++d) m.points.push_back(m.points[m.boundary.nodes.back() * dim + d]);  // duplicate
        m.boundary.nodes.push_back(static_cast<NodeId>(first_extra + 1));
        m.boundary.moving.push_back(1);
        for (DgIdwWeighting weighting : {DgIdwWeighting::paper, DgIdwWeighting::continuous}) {
        SCOPED_TRACE(weighting_name(weighting));
        // Options that are not the defaults, so the test sees them kept.
        const DgIdwOptions options{.a_translation = 5.5, .a_rotation = 2.25, .length_scale = 0, .weighting = weighting};
        const DgIdwPlan plan = prepare_dg_idw(dim, m.points, m.boundary, options);
        ASSERT_EQ(plan.options.weighting, weighting);
        ASSERT_EQ(plan.stats.shared_vertex_count, 1);
        ASSERT_EQ(plan.stats.outside_count, 1);
        const auto file = dir / ("plan" + std::to_string(dim) + ".dgwplan");
        save_dg_idw_plan(file, plan);
        const DgIdwPlan loaded = load_dg_idw_plan(file, m.points, m.boundary);

        EXPECT_EQ(loaded.dim, plan.dim);
        EXPECT_EQ(loaded.options.weighting, weighting);
        EXPECT_EQ(loaded.options.a_translation, 5.5);
        EXPECT_EQ(loaded.options.a_rotation, 2.25);
        EXPECT_EQ(loaded.options.length_scale, 0.0);
        EXPECT_EQ(loaded.auto_length_scale, plan.auto_length_scale);
        EXPECT_EQ(loaded.mesh, plan.mesh);
        EXPECT_EQ(loaded.auto_length_scale, plan.auto_length_scale);
        EXPECT_EQ(loaded.simplex_motion, plan.simplex_motion);
        EXPECT_EQ(loaded.stats.graph_vertex_count, plan.stats.graph_vertex_count);
        EXPECT_EQ(loaded.shared_members, plan.shared_members);
        EXPECT_EQ(loaded.node_simplex, plan.node_simplex);
        EXPECT_EQ(loaded.stats.outside_count, 1);
        EXPECT_EQ(loaded.stats.shared_vertex_count, 1);

        const BoundaryMotion motion = rotating_motion(m);
        std::vector<double> a(m.points.size()), b(m.points.size());
        deform_dg_idw(plan, m.points, motion, a);
        deform_dg_idw(loaded, m.points, motion, b);
        EXPECT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof(double)), 0);
        }
    }
}

TEST(PlanFile, AnUnknownWeightingIsRefused) {
    const auto dir = dgwarp::test::scratch_dir();
    const BoxInBox m = box_in_box(2, 10);
    DgIdwPlan plan = prepare_dg_idw(2, m.points, m.boundary);
    plan.options.weighting = static_cast<DgIdwWeighting>(7);  // saved with a valid checksum
    const auto file = dir / "weighting.dgwplan";
    save_dg_idw_plan(file, plan);
    const std::string message = expect_refused(file, "weighting 7");
    EXPECT_NE(message.find("weighting 0 (paper) or 1 (continuous)"), std::string::npos) << message;
    EXPECT_NE(message.find("byte offset 16"), std::string::npos) << message;
}

TEST(PlanFile, BadOptionsAreRefusedWithTheirOffset) {
    const auto dir = dgwarp::test::scratch_dir();
    const BoxInBox m = box_in_box(2, 10);
    const DgIdwPlan good = prepare_dg_idw(2, m.points, m.boundary);
    struct Case {
        const char* what;
        void (*spoil)(DgIdwPlan&);
        const char* offset;
    };
    const Case cases[] = {
        {"a_translation 0", [](DgIdwPlan& p) { p.options.a_translation = 0; }, "byte offset 84"},
        {"a_rotation NaN", [](DgIdwPlan& p) { p.options.a_rotation = std::nan(""); }, "byte offset 92"},
        {"length_scale -1", [](DgIdwPlan& p) { p.options.length_scale = -1; }, "byte offset 100"},
        {"auto length scale inf", [](DgIdwPlan& p) { p.auto_length_scale = INFINITY; }, "byte offset 44"},
    };
    for (const Case& c : cases) {
        DgIdwPlan plan = good;
        c.spoil(plan);
        const auto file = dir / "options.dgwplan";
        save_dg_idw_plan(file, plan);  // a valid checksum: the value check must catch it
        const std::string message = expect_refused(file, c.what);
        EXPECT_NE(message.find(c.offset), std::string::npos) << c.what << ": " << message;
    }
}

TEST(PlanFile, AnOlderFormatIsRefusedWithAdvice) {
    const auto dir = dgwarp::test::scratch_dir();
    const BoxInBox m = box_in_box(2, 10);
    const auto file = dir / "old.dgwplan";
    save_dg_idw_plan(file, prepare_dg_idw(2, m.points, m.boundary));
    std::vector<std::byte> bytes(std::filesystem::file_size(file));
    std::ifstream(file, std::ios::binary).read(reinterpret_cast<char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
    bytes[8] = std::byte{2};  // format version 2: before the options were kept
    bytes = with_recomputed_plan_checksum(bytes);
    std::ofstream(file, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
    const std::string message = expect_refused(file, "version 2");
    EXPECT_NE(message.find("run dgwarp prepare again"), std::string::npos) << message;
}

TEST(PlanFile, EveryFlippedByteIsRefused) {
    const auto dir = dgwarp::test::scratch_dir();
    const BoxInBox m = box_in_box(2, 10);
    const auto file = dir / "good.dgwplan";
    save_dg_idw_plan(file, prepare_dg_idw(2, m.points, m.boundary));
    const std::vector<char> good = plan_test_read_bytes(file);
    const auto bad = dir / "bad.dgwplan";
    // Every byte of the header and the trailer, and a stride through the arrays.
    for (std::size_t i = 0; i < good.size(); i += (i < 160 || i + 16 > good.size()) ? 1 : 37) {
        std::vector<char> flipped = good;
        flipped[i] ^= 0x10;
        write_bytes(bad, flipped);
        expect_refused(bad, "byte " + std::to_string(i) + " flipped");
    }
}

TEST(PlanFile, TruncatedOrExtendedFilesAreRefused) {
    const auto dir = dgwarp::test::scratch_dir();
    const BoxInBox m = box_in_box(3, 6);
    const auto file = dir / "good.dgwplan";
    save_dg_idw_plan(file, prepare_dg_idw(3, m.points, m.boundary));
    const std::vector<char> good = plan_test_read_bytes(file);
    const auto bad = dir / "bad.dgwplan";
    for (std::size_t size : {std::size_t{0}, std::size_t{7}, std::size_t{100}, good.size() / 2, good.size() - 1}) {
        write_bytes(bad, std::vector<char>(good.begin(), good.begin() + static_cast<std::ptrdiff_t>(size)));
        const std::string message = expect_refused(bad, "truncated to " + std::to_string(size));
        if (size >= 140) {
            EXPECT_NE(message.find("truncated"), std::string::npos) << message;
        }
    }
    std::vector<char> longer = good;
    longer.push_back(0);
    write_bytes(bad, longer);
    expect_refused(bad, "one byte longer");
    // A header claiming a huge array is refused before anything is allocated.
    std::vector<char> huge = good;
    const std::uint64_t count = std::uint64_t{1} << 60;
    // Header: magic 8, version 4, dim 4, weighting 4, eight 8-byte fields, then the 7 array counts.
    std::memcpy(huge.data() + 84 + 6 * 8, &count, 8);  // node_coefficients count
    write_bytes(bad, huge);
    const std::string message = expect_refused(bad, "huge count");
    EXPECT_NE(message.find("array length that fits in the file"), std::string::npos) << message;
    EXPECT_NE(message.find("byte offset 132"), std::string::npos) << message;
}

TEST(PlanFile, APlanForAnotherMeshIsRefused) {
    const auto dir = dgwarp::test::scratch_dir();
    const BoxInBox m = box_in_box(2, 10), other = box_in_box(2, 11);
    const auto file = dir / "plan.dgwplan";
    save_dg_idw_plan(file, prepare_dg_idw(2, m.points, m.boundary));
    try {
        load_dg_idw_plan(file, other.points, other.boundary);
        FAIL();
    } catch (const MeshError& e) {
        EXPECT_NE(std::string(e.what()).find("made for another mesh (" + std::to_string(m.num_points()) +
                                             " points vs " + std::to_string(other.num_points())),
                  std::string::npos)
            << e.what();
    }
    EXPECT_THROW(load_dg_idw_plan(dir / "missing.dgwplan"), IoError);
    write_bytes(dir / "text.dgwplan", std::vector<char>(200, 'x'));
    expect_refused(dir / "text.dgwplan", "not a plan file");
}

TEST(PlanFile, InconsistentContentWithAValidChecksumIsRefused) {
    // Such a plan would make deform read out of bounds, so load checks its indices.
    const auto dir = dgwarp::test::scratch_dir();
    const BoxInBox m = box_in_box(2, 10);
    const DgIdwPlan good = prepare_dg_idw(2, m.points, m.boundary);
    const auto file = dir / "crafted.dgwplan";
    // A row with a static corner before a moving one.
    DgIdwPlan swapped = good;
    std::size_t row = 0;
    while (!(swapped.simplex_motion[3 * row] >= 0 && swapped.simplex_motion[3 * row + 2] < 0)) ++row;
    std::swap(swapped.simplex_motion[3 * row], swapped.simplex_motion[3 * row + 2]);
    save_dg_idw_plan(file, swapped);
    EXPECT_NE(expect_refused(file, "unpartitioned row").find("moving corners first"), std::string::npos);
    // A corner motion index past the boundary nodes.
    DgIdwPlan out_of_range = good;
    out_of_range.simplex_motion[0] = static_cast<std::int32_t>(good.boundary_nodes.size());
    save_dg_idw_plan(file, out_of_range);
    EXPECT_NE(expect_refused(file, "index out of range").find("corner motion index"), std::string::npos);
    // A volume node whose simplex does not exist.
    DgIdwPlan bad_simplex = good;
    bad_simplex.node_simplex[static_cast<std::size_t>(m.volume[0])] = 1 << 30;
    save_dg_idw_plan(file, bad_simplex);
    EXPECT_NE(expect_refused(file, "simplex out of range").find("simplex id"), std::string::npos);
}
