// A DG-IDW plan cut down to the boundary nodes its step reads: the same bits
// for every node left, on meshes whose boundary nodes are spread among the others.
#include "dgwarp/methods/dg_idw_subset.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "dgwarp/core/error.hpp"
#include "dgwarp/methods/mesh_fingerprint.hpp"
#include "support/box_in_box.hpp"
#include "support/dg_idw_deformed.hpp"

using namespace dgwarp;
using dgwarp::test::box_in_box;
using dgwarp::test::dg_idw_deformed;
using dgwarp::test::BoxInBox;
using dgwarp::test::jittered;
using dgwarp::test::random_motion;

namespace {

bool same_bits_of(const double* a, const double* b, int dim) { return std::memcmp(a, b, sizeof(double) * dim) == 0; }

}  // namespace

TEST(DgIdwSubset, ACutPlanGivesTheNodesLeftTheSameBits) {
    for (int dim : {2, 3}) {
        const BoxInBox m = jittered(box_in_box(dim, dim == 2 ? 14 : 7), 0.01, 3);
        const DgIdwPlan full = prepare_dg_idw(dim, m.points, m.boundary);
        const BoundaryMotion motion = random_motion(m, 11);
        const std::vector<double> expected = dg_idw_deformed(full, m.points, motion);

        const std::size_t nb = m.boundary.nodes.size();
        std::vector<std::uint8_t> keep = dg_idw_motions_read(full);
        const auto read = std::count(keep.begin(), keep.end(), 1);
        ASSERT_GT(read, 0);
        ASSERT_LT(static_cast<std::size_t>(read), nb);  // the static box's nodes are never read
        for (std::size_t b = 0; b < nb; b += 3) keep[b] = 1;  // and some static ones kept anyway
        // The mesh left: every node but the boundary nodes not kept, in order.
        std::vector<std::uint8_t> removed(m.points.size() / dim, 0);
        for (std::size_t b = 0; b < nb; ++b) removed[m.boundary.nodes[b]] = !keep[b];
        std::vector<double> points;
        std::vector<std::size_t> old_id;
        for (std::size_t n = 0; n < removed.size(); ++n)
            if (!removed[n]) {
                old_id.push_back(n);
                points.insert(points.end(), m.points.begin() + n * dim, m.points.begin() + (n + 1) * dim);
            }
        BoundaryMotion kept_motion;
        for (std::size_t b = 0; b < nb; ++b)
            if (keep[b]) kept_motion.push_back(motion[b]);

        DgIdwPlan cut = full;
        const std::vector<std::int32_t> renumber = keep_dg_idw_boundary_nodes(cut, keep, points);
        ASSERT_EQ(renumber.size(), nb);
        ASSERT_EQ(cut.boundary_nodes.size(), kept_motion.size());
        for (std::size_t b = 0; b < nb; ++b)
            if (keep[b]) EXPECT_EQ(old_id[cut.boundary_nodes[renumber[b]]], m.boundary.nodes[b]);
            else EXPECT_EQ(renumber[b], -1);
        EXPECT_EQ(cut.num_volume_nodes(), full.num_volume_nodes());
        EXPECT_EQ(cut.mesh, mesh_fingerprint(dim, points, BoundarySet{cut.boundary_nodes, cut.boundary_moving}));
        const std::vector<double> got = dg_idw_deformed(cut, points, kept_motion);
        for (std::size_t n = 0; n < old_id.size(); ++n)
            EXPECT_TRUE(same_bits_of(&got[n * dim], &expected[old_id[n] * dim], dim)) << dim << "D node " << old_id[n];
    }
}

TEST(DgIdwSubset, ANodeAStepReadsCannotBeCutAndTheFlagsMustFit) {
    const BoxInBox m = box_in_box(2, 12);
    DgIdwPlan plan = prepare_dg_idw(2, m.points, m.boundary);
    EXPECT_TRUE(dg_idw_shared_groups(plan).empty());  // no two boundary nodes at one place
    std::vector<std::uint8_t> keep(m.boundary.nodes.size(), 0);
    const std::vector<double> volume_points(static_cast<std::size_t>(plan.num_volume_nodes()) * 2, 0.0);
    try {
        keep_dg_idw_boundary_nodes(plan, keep, volume_points);  // the points fit: the moving corners are read
        FAIL() << "a boundary node a step reads was cut";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("moves a graph simplex corner but is not kept"), std::string::npos)
            << e.what();
    }
    keep.pop_back();
    EXPECT_THROW(keep_dg_idw_boundary_nodes(plan, keep, {}), Error);
    std::vector<std::uint8_t> all(m.boundary.nodes.size(), 1);
    EXPECT_THROW(keep_dg_idw_boundary_nodes(plan, all, std::span<const double>(m.points).subspan(2)), Error);
    const DgIdwPlan before = plan;
    keep_dg_idw_boundary_nodes(plan, all, m.points);  // keeping everything changes nothing but the shared groups
    EXPECT_EQ(plan.node_simplex, before.node_simplex);
    EXPECT_EQ(plan.simplex_motion, before.simplex_motion);
    EXPECT_EQ(plan.boundary_nodes, before.boundary_nodes);
    EXPECT_EQ(plan.mesh, before.mesh);
}
