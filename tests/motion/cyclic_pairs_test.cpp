// Cyclic marker pairs (motion/cyclic_pairs.hpp) and how resolve_boundary
// takes them (CyclicMotion): pairing against hand-placed images, groups
// where pairs meet, coupling by hand-computed vectors, the errors.
#include "dgwarp/motion/cyclic_pairs.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "dgwarp/core/error.hpp"
#include "dgwarp/motion/resolve_motion.hpp"
#include "support/lattice_box.hpp"

namespace dgwarp {
namespace {

using test::lattice_box;

std::size_t marker_index(const Mesh& m, const std::string& name) {
    for (std::size_t i = 0; i < m.markers.size(); ++i)
        if (m.markers[i].name == name) return i;
    return m.markers.size();
}

CyclicPair pair_of(const Mesh& m, const std::string& a, const std::string& b) {
    return {marker_index(m, a), marker_index(m, b)};
}

/// The members of the group holding `node`, or none.
std::vector<NodeId> group_of(const CyclicGroups& g, NodeId node) {
    for (std::size_t k = 0; k < g.size(); ++k) {
        const auto b = g.nodes.begin() + g.offsets[k], e = g.nodes.begin() + g.offsets[k + 1];
        if (std::find(b, e, node) != e) return {b, e};
    }
    return {};
}

constexpr Rotation identity{1, 0, 0, 0, 1, 0, 0, 0, 1};

TEST(CyclicGroups, OppositeSidesOfASquarePairByTranslationAndTheCornersMakeOneGroup) {
    const int n = 5;
    const Mesh m = lattice_box(2, n);  // node i + n j at (i, j) / (n - 1)
    const std::vector<CyclicPair> pairs{pair_of(m, "x_m", "x_p"), pair_of(m, "y_m", "y_p")};
    const CyclicGroups g = cyclic_groups(m, pairs);
    // n - 2 pairs across x and across y, and the four corners as one group.
    ASSERT_EQ(g.size(), static_cast<std::size_t>(2 * (n - 2) + 1));
    EXPECT_EQ(group_of(g, 0), (std::vector<NodeId>{0, n - 1, n * (n - 1), n * n - 1}));
    for (int j = 1; j + 1 < n; ++j) EXPECT_EQ(group_of(g, n * j), (std::vector<NodeId>{n * j, n * j + n - 1}));
    for (int i = 1; i + 1 < n; ++i) EXPECT_EQ(group_of(g, i), (std::vector<NodeId>{i, n * (n - 1) + i}));
    for (const Rotation& r : g.rotations)
        for (std::size_t k = 0; k < 9; ++k) EXPECT_NEAR(r[k], identity[k], 1e-12);
}

TEST(CyclicGroups, ShuffledFacesStillPairByTheTranslationBetweenCentroids) {
    const int n = 6;
    Mesh m = lattice_box(3, n);
    // x_p's faces in another order, and each face's nodes turned: no pairing by order.
    Marker& xp = m.markers[marker_index(m, "x_p")];
    ElementList shuffled;
    for (std::size_t f = xp.elements.size(); f-- > 0;) {
        const auto nodes = xp.elements.nodes_of((f * 7) % xp.elements.size());
        std::vector<NodeId> turned(nodes.begin(), nodes.end());
        std::rotate(turned.begin(), turned.begin() + 1, turned.end());
        shuffled.push_back(CellType::quadrilateral, turned);
    }
    xp.elements = shuffled;
    const std::vector<CyclicPair> pairs{pair_of(m, "x_m", "x_p")};
    const CyclicGroups g = cyclic_groups(m, pairs);
    ASSERT_EQ(g.size(), static_cast<std::size_t>(n * n));
    // Node (0, j, k) with (n - 1, j, k).
    for (int k = 0; k < n; ++k)
        for (int j = 0; j < n; ++j) {
            const NodeId a = n * (j + n * k);
            EXPECT_EQ(group_of(g, a), (std::vector<NodeId>{a, a + n - 1}));
        }
}

TEST(CyclicGroups, ARotatedHalfCouplesThroughItsRotation) {
    // Two 3 x 3 node grids: A in the plane x = 0 (y in [1, 2], z in [0, 1]),
    // B its image turned 90 degrees about the z axis: (x, y, z) -> (-y, x, z).
    Mesh m;
    m.dim = 3;
    const auto add_grid = [&](bool turned) {
        const auto first = static_cast<NodeId>(m.num_points());
        for (int k = 0; k < 3; ++k)
            for (int j = 0; j < 3; ++j) {
                const double y = 1 + 0.5 * j, z = 0.5 * k;
                if (turned) m.points.insert(m.points.end(), {-y, 0.0, z});
                else m.points.insert(m.points.end(), {0.0, y, z});
            }
        Marker marker{turned ? "b" : "a", {}};
        for (int k = 0; k < 2; ++k)
            for (int j = 0; j < 2; ++j) {
                const auto id = [&](int jj, int kk) { return first + static_cast<NodeId>(jj + 3 * kk); };
                const NodeId q[] = {id(j, k), id(j + 1, k), id(j + 1, k + 1), id(j, k + 1)};
                marker.elements.push_back(CellType::quadrilateral, q);
            }
        m.markers.push_back(marker);
    };
    add_grid(false);
    add_grid(true);
    const std::vector<CyclicPair> pairs{{0, 1}};
    const CyclicGroups g = cyclic_groups(m, pairs);
    ASSERT_EQ(g.size(), 9u);
    // Each group: a node of A first (the smaller id), then its image, turned by Rz(90).
    const Rotation rz90{0, -1, 0, 1, 0, 0, 0, 0, 1};
    for (std::size_t k = 0; k < g.size(); ++k) {
        ASSERT_EQ(g.offsets[k + 1] - g.offsets[k], 2);
        const auto first = static_cast<std::size_t>(g.offsets[k]);
        EXPECT_EQ(g.nodes[first + 1], g.nodes[first] + 9);
        for (std::size_t e = 0; e < 9; ++e) {
            EXPECT_NEAR(g.rotations[first][e], identity[e], 1e-12);
            EXPECT_NEAR(g.rotations[first + 1][e], rz90[e], 1e-12);
        }
    }
    // Coupling by hand: A's node free with (1, 0, 0), its image free with 0:
    // the mean in A's frame is (0.5, 0, 0), which the image sees as (0, 0.5, 0).
    CyclicGroups one = g;
    one.offsets = {0, 2};
    one.nodes.resize(2);
    one.rotations.resize(2);
    std::vector<double> v{1, 0, 0, 0, 0, 0};
    const std::vector<char> free(2, 0);
    couple_cyclic_vectors(one, v, free);
    EXPECT_NEAR(v[0], 0.5, 1e-15);
    EXPECT_NEAR(v[1], 0.0, 1e-15);
    EXPECT_NEAR(v[3], 0.0, 1e-15);
    EXPECT_NEAR(v[4], 0.5, 1e-15);
    // The image held at (0, 2, 0): A's node takes Rz(90)^T (0, 2, 0) = (2, 0, 0).
    v = {1, 0, 0, 0, 2, 0};
    const std::vector<char> image_held{0, 1};
    couple_cyclic_vectors(one, v, image_held);
    EXPECT_NEAR(v[0], 2.0, 1e-15);
    EXPECT_NEAR(v[1], 0.0, 1e-15);
    EXPECT_EQ(v[4], 2.0);
    // Both held: they agree when (0, 2, 0) is A's (2, 0, 0) turned, not otherwise.
    const std::vector<char> both{1, 1};
    EXPECT_EQ(cyclic_disagreements(one, std::vector<double>{2, 0, 0, 0, 2, 0}, both, 1e-9), 0);
    NodeId at = -1;
    EXPECT_EQ(cyclic_disagreements(one, std::vector<double>{2, 0, 0, 2, 0, 0}, both, 1e-9, &at), 1);
    EXPECT_EQ(at, one.nodes[1]);
}

TEST(CyclicGroups, HalvesThatAreNotImagesAreAnErrorNamingThem) {
    const int n = 4;
    Mesh m = lattice_box(3, n);
    const std::vector<CyclicPair> pairs{pair_of(m, "x_m", "x_p")};
    {
        // One face fewer on x_p: fewer nodes.
        Mesh fewer = m;
        Marker& xp = fewer.markers[marker_index(fewer, "x_p")];
        ElementList kept;
        for (std::size_t f = 0; f + 1 < xp.elements.size(); ++f) kept.push_back(CellType::quadrilateral, xp.elements.nodes_of(f));
        xp.elements = kept;
        try {
            cyclic_groups(fewer, pairs);
            FAIL() << "halves of different node counts were paired";
        } catch (const MeshError& e) {
            EXPECT_EQ(e.marker(), "x_m");
            EXPECT_NE(std::string(e.what()).find("cyclic markers 'x_m' and 'x_p' are not images of each other: they have 16 and 15 nodes"),
                      std::string::npos)
                << e.what();
        }
    }
    {
        // A node of x_p moved in its plane by a third of a cell: no rigid motion maps x_m onto x_p.
        Mesh moved = m;
        const std::size_t node = static_cast<std::size_t>(n - 1 + n * (1 + n * 1));  // (n - 1, 1, 1)
        moved.points[3 * node + 1] += 1.0 / (3 * (n - 1));
        try {
            cyclic_groups(moved, pairs);
            FAIL() << "a node without an image was paired";
        } catch (const MeshError& e) {
            EXPECT_NE(std::string(e.what()).find("cyclic markers 'x_m' and 'x_p' are not images of each other"),
                      std::string::npos)
                << e.what();
            EXPECT_GE(e.index(), 0) << e.what();
        }
    }
}

MotionSpec shear_with_cyclic_sides(const NodeMotion& top) {
    MotionSpec spec;
    MotionFrame frame;
    frame.markers["y_p"] = RigidMotion{top};
    frame.markers["x_m"] = CyclicMotion{"x_p"};
    frame.markers["x_p"] = CyclicMotion{"x_m"};
    spec.frames.push_back(frame);
    spec.source = "shear";
    return spec;
}

TEST(CyclicGroups, ResolvedCyclicNodesAreFreeSlidingNodesCoupledToTheirImages) {
    const int n = 5;
    const Mesh m = lattice_box(2, n);
    const ResolvedBoundary r = resolve_boundary(m, shear_with_cyclic_sides(NodeMotion{{0.1, 0, 0}, {0, 0, 0}, {0, 0, 0}}));
    EXPECT_EQ(r.cyclic_markers, (std::vector<std::string>{"x_m", "x_p"}));
    EXPECT_EQ(r.moving_markers, std::vector<std::string>{"y_p"});
    EXPECT_EQ(r.static_markers, std::vector<std::string>{"y_m"});
    // The sides' inner nodes are free (planes 0) and moving; the corners are y_m's and y_p's.
    ASSERT_EQ(r.slides.size(), static_cast<std::size_t>(2 * (n - 2)));
    for (std::size_t i = 0; i < r.slides.size(); ++i) {
        EXPECT_EQ(r.slides.planes[i], 0);
        EXPECT_EQ(r.boundary.moving[static_cast<std::size_t>(r.slides.slots[i])], 1);
    }
    const CyclicGroups& g = r.slides.cyclic;
    ASSERT_EQ(g.size(), static_cast<std::size_t>(n));
    for (std::size_t k = 0; k < g.nodes.size(); ++k) {
        EXPECT_EQ(r.boundary.nodes[static_cast<std::size_t>(g.slots[k])], g.nodes[k]);
        const NodeId j = g.nodes[k] / n;
        EXPECT_EQ(g.slide[k] < 0, j == 0 || j == n - 1) << g.nodes[k];
    }
    // The top translated: its corners move alike, no warning.
    for (const Warning& w : r.warnings) EXPECT_NE(w.code, WarningCode::cyclic_mismatch) << w.text;
    // The top turned: its two corners, images of each other, move differently.
    const ResolvedBoundary turned =
        resolve_boundary(m, shear_with_cyclic_sides(NodeMotion{{0, 0, 0}, {0, 0, 0.1}, {0.5, 1, 0}}));
    const auto it = std::find_if(turned.warnings.begin(), turned.warnings.end(),
                                 [](const Warning& w) { return w.code == WarningCode::cyclic_mismatch; });
    ASSERT_NE(it, turned.warnings.end());
    EXPECT_EQ(it->count, 1);
    EXPECT_EQ(it->node, n * (n - 1) + n - 1);
}

TEST(CyclicGroups, APartnerThatDoesNotNameTheMarkerBackIsAnError) {
    const Mesh m = lattice_box(2, 4);
    MotionSpec spec = shear_with_cyclic_sides(NodeMotion{{0.1, 0, 0}, {0, 0, 0}, {0, 0, 0}});
    spec.frames[0].markers["x_p"] = FixedMotion{};
    try {
        resolve_boundary(m, spec);
        FAIL() << "a one-sided cyclic pair was accepted";
    } catch (const MeshError& e) {
        EXPECT_EQ(e.marker(), "x_m");
        EXPECT_NE(std::string(e.what()).find("marker 'x_m' is cyclic with 'x_p', but 'x_p' is not cyclic"),
                  std::string::npos)
            << e.what();
    }
    spec.frames[0].markers["x_m"] = CyclicMotion{"x_m"};
    try {
        resolve_boundary(m, spec);
        FAIL() << "a marker cyclic with itself was accepted";
    } catch (const MeshError& e) {
        EXPECT_NE(std::string(e.what()).find("is cyclic with 'x_m', itself"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace dgwarp
