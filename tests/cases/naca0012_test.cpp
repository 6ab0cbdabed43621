#include "dgwarp/cases/naca0012.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "dgwarp/core/error.hpp"
#include "dgwarp/quality/mesh_quality.hpp"

using namespace dgwarp;

namespace {
const Mesh& naca() {
    static const Mesh m = make_naca0012();
    return m;
}
}  // namespace

TEST(CasesNaca0012, CountsAreWithinTwoPercentOfThePapers) {
    const Mesh& m = naca();
    EXPECT_EQ(m.dim, 2);
    EXPECT_NEAR(double(m.num_points()), 1647, 0.02 * 1647);
    EXPECT_NEAR(double(m.cells.size()), 3054, 0.02 * 3054);
    EXPECT_EQ(count_by_type(m.cells)[static_cast<int>(CellType::triangle)], static_cast<std::int64_t>(m.cells.size()));
    EXPECT_NO_THROW(validate(m));
}

TEST(CasesNaca0012, AirfoilAndFarfieldMarkersLieOnTheirCurves) {
    const Mesh& m = naca();
    const auto airfoil = marker_nodes(find_marker(m, "airfoil"));
    const auto far = marker_nodes(find_marker(m, "farfield"));
    EXPECT_EQ(airfoil.size(), 200u);
    EXPECT_EQ(far.size(), 40u);
    for (NodeId n : airfoil) {
        const double x = m.points[2 * n], y = m.points[2 * n + 1];
        ASSERT_GE(x, -1e-12);
        ASSERT_LE(x, 1 + 1e-12);
        EXPECT_NEAR(std::abs(y), naca0012_half_thickness(x), 1e-12) << "node " << n;
    }
    for (NodeId n : far) EXPECT_NEAR(std::hypot(m.points[2 * n] - 0.5, m.points[2 * n + 1]), 10.0, 1e-9);
}

TEST(CasesNaca0012, AllCellsPositiveAndTheWorstIsTheSliverBehindTheTrailingEdge) {
    const Mesh& m = naca();
    // Judged against counter-clockwise (+1) for every cell: the generator orients them.
    const std::vector<std::int8_t> ccw(m.cells.size(), 1);
    const QualitySummary q = summarize_quality(cell_qualities(m, ccw));
    EXPECT_EQ(q.inverted, 0);
    EXPECT_GT(q.min, 0.0);
    EXPECT_LT(q.min, 0.25);  // the paper's sliver: 0.177
    EXPECT_GT(q.mean, 0.9);
    double cx = 0, cy = 0;
    for (NodeId n : m.cells.nodes_of(q.worst_cell)) {
        cx += m.points[2 * n] / 3;
        cy += m.points[2 * n + 1] / 3;
    }
    EXPECT_GT(cx, 1.0);  // behind the trailing edge (1, 0)
    EXPECT_LT(cx, 1.05);
    EXPECT_LT(std::abs(cy), 0.01);
    // Without the sliver nodes no cell is that bad.
    Naca0012Options plain;
    plain.sliver_half_width = 0;
    const Mesh p = make_naca0012(plain);
    EXPECT_GT(summarize_quality(cell_qualities(p, cell_orientations(p))).min, q.min);
}

TEST(CasesNaca0012, IsDeterministic) { EXPECT_TRUE(make_naca0012() == naca()); }

TEST(CasesNaca0012, BadOptionsThrowMeshError) {
    Naca0012Options o;
    o.sliver_half_width = 1;
    EXPECT_THROW(make_naca0012(o), MeshError);
    o = {};
    o.farfield_radius = 1;
    EXPECT_THROW(make_naca0012(o), MeshError);
}
