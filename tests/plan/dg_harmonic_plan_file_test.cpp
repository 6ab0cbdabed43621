// DG-harmonic plans on disk (plan_file.hpp, dg_harmonic_plan_file.cpp):
// bit-identical round trips, and corrupt files refused before deform could
// read out of bounds.
#include <gtest/gtest.h>

#include <cstring>
#include <fstream>
#include <vector>

#include "dgwarp/core/error.hpp"
#include "dgwarp/plan/plan_file.hpp"
#include "dgwarp/methods/method.hpp"
#include "support/box_in_box.hpp"
#include "support/test_paths.hpp"

using namespace dgwarp;
using dgwarp::test::box_in_box;
using dgwarp::test::BoxInBox;

namespace {

constexpr DgHarmonicOptions dense_coarse{.wall_spacing = 2.0, .growth = 0.5};

BoxInBox harmonic_plan_box(int dim) { return dgwarp::test::jittered(box_in_box(dim, dim == 2 ? 16 : 8), 0.01, 3); }

std::vector<std::byte> file_bytes(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::vector<char> c((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::vector<std::byte> b(c.size());
    std::memcpy(b.data(), c.data(), c.size());
    return b;
}

// The ParseError message of loading `bytes` (with their checksum recomputed).
std::string harmonic_plan_refusal(const std::vector<std::byte>& bytes) {
    try {
        load_plan_bytes(with_recomputed_plan_checksum(bytes), "bad.plan");
    } catch (const ParseError& e) {
        return e.what();
    }
    ADD_FAILURE() << "the plan was accepted";
    return {};
}

}  // namespace

TEST(DgHarmonicPlanFile, RoundTripIsBitIdenticalAndDeformsIdentically) {
    const auto dir = test::scratch_dir();  // a fresh directory per call
    for (int dim : {2, 3}) {
        const BoxInBox m = harmonic_plan_box(dim);
        const DgHarmonicPlan plan = prepare_dg_harmonic(dim, m.points, m.boundary, dense_coarse);
        ASSERT_GT(plan.num_unknowns(), 0);
        const auto file = dir / ("h" + std::to_string(dim) + ".plan");
        save_plan(file, plan);
        const Plan loaded_any = load_plan(file, m.points, m.boundary);
        ASSERT_TRUE(std::holds_alternative<DgHarmonicPlan>(loaded_any));
        const auto& loaded = std::get<DgHarmonicPlan>(loaded_any);
        EXPECT_EQ(loaded.mesh, plan.mesh);
        EXPECT_EQ(loaded.simplices, plan.simplices);
        EXPECT_EQ(loaded.node_barycentric, plan.node_barycentric);
        EXPECT_EQ(loaded.solve.l_row, plan.solve.l_row);
        EXPECT_EQ(loaded.solve.translation.l_value, plan.solve.translation.l_value);
        EXPECT_EQ(loaded.solve.rotation.d, plan.solve.rotation.d);
        EXPECT_EQ(loaded.solve.shared, plan.solve.shared);
        EXPECT_EQ(loaded.options.wall_spacing, 2.0);
        EXPECT_EQ(loaded.options.rotation_exponent, plan.options.rotation_exponent);
        BoundaryMotion motion(m.boundary.nodes.size());
        for (std::size_t b = 0; b < motion.size(); ++b)
            if (m.boundary.moving[b]) motion[b] = {{0.01, 0.02, 0}, {0, 0, 0.2}, {0.5, 0.5, 0.5}};
        std::vector<double> a(m.points.size()), b(m.points.size());
        deform_dg_harmonic(plan, m.points, motion, a);
        deform_dg_harmonic(loaded, m.points, motion, b);
        EXPECT_EQ(a, b) << dim;
        // Saved again, the file is the same bytes.
        const auto again = dir / ("h" + std::to_string(dim) + "-again.plan");
        save_plan(again, loaded);
        EXPECT_EQ(file_bytes(file), file_bytes(again));
    }
}

TEST(DgHarmonicPlanFile, CorruptFilesAreRefusedNamingTheByteOffset) {
    const BoxInBox m = harmonic_plan_box(2);
    const auto file = test::scratch_dir() / "corrupt.plan";
    save_plan(file, prepare_dg_harmonic(2, m.points, m.boundary, dense_coarse));
    const std::vector<std::byte> good = file_bytes(file);
    ASSERT_NO_THROW(load_plan_bytes(good, "good.plan"));
    // Truncated; one flipped byte (checksum); wrong version.
    EXPECT_THROW(load_plan_bytes(std::span(good).first(good.size() - 9), "short.plan"), ParseError);
    std::vector<std::byte> flipped = good;
    flipped[good.size() / 2] ^= std::byte{1};
    EXPECT_THROW(load_plan_bytes(flipped, "flipped.plan"), ParseError);
    std::vector<std::byte> version = good;
    version[8] = std::byte{9};
    EXPECT_NE(harmonic_plan_refusal(version).find("byte offset 8"), std::string::npos);
    // Indices out of range behind a valid checksum: the last word of the file
    // before the checksums is a rotation coupling weight; change instead a
    // coarse graph vertex id (simplices) and a factor row (l_row), found by
    // their values in a plan we know.
    const DgHarmonicPlan plan = std::get<DgHarmonicPlan>(load_plan_bytes(good, "good.plan"));
    auto with_int_at = [&](std::size_t array_offset, std::size_t index, std::int32_t value) {
        std::vector<std::byte> b = good;
        std::memcpy(b.data() + array_offset + 4 * index, &value, 4);
        return b;
    };
    // Array offsets: header, then the arrays in the file's order.
    std::size_t at = good.size() - 8;
    auto skip_back = [&](std::size_t bytes) { at -= bytes; return at; };
    for (const auto* s : {&plan.solve.rotation, &plan.solve.translation}) {
        skip_back(8 * s->coupling_weight.size());
        skip_back(8 * s->d.size());
        skip_back(8 * s->l_value.size());
    }
    const std::size_t coupling_vertex_at = skip_back(4 * plan.solve.coupling_vertex.size());
    skip_back(8 * plan.solve.coupling_start.size());
    const std::size_t l_row_at = skip_back(4 * plan.solve.l_row.size());
    skip_back(8 * plan.solve.l_start.size());
    const std::size_t perm_at = skip_back(4 * plan.solve.perm.size());
    skip_back(8 * plan.node_barycentric.size());
    skip_back(4 * plan.node_simplex.size());
    const std::size_t simplices_at = skip_back(4 * plan.simplices.size());
    ASSERT_FALSE(plan.solve.l_row.empty());
    ASSERT_FALSE(plan.solve.coupling_vertex.empty());
    EXPECT_NE(harmonic_plan_refusal(with_int_at(simplices_at, 5, static_cast<std::int32_t>(plan.num_vertices())))
                  .find("a coarse graph vertex"),
              std::string::npos);
    EXPECT_NE(harmonic_plan_refusal(with_int_at(l_row_at, 0, -1)).find("a row below the diagonal"), std::string::npos);
    EXPECT_NE(harmonic_plan_refusal(with_int_at(perm_at, 1, plan.solve.perm[0])).find("a permutation"),
              std::string::npos);
    EXPECT_NE(harmonic_plan_refusal(with_int_at(coupling_vertex_at, 0, plan.num_boundary_vertices)).find("a boundary vertex"),
              std::string::npos);
}

TEST(DgHarmonicPlanFile, AnotherMeshIsRefused) {
    const BoxInBox m = harmonic_plan_box(2), other = harmonic_plan_box(3);
    const auto file = test::scratch_dir() / "fits.plan";
    save_plan(file, prepare_dg_harmonic(2, m.points, m.boundary, dense_coarse));
    EXPECT_THROW(load_plan(file, other.points, other.boundary), MeshError);
}
