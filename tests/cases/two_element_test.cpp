#include "dgwarp/cases/two_element.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>

#include "dgwarp/cases/paper_cases.hpp"
#include "dgwarp/methods/method.hpp"
#include "dgwarp/motion/resolve_motion.hpp"
#include "dgwarp/quality/mesh_quality.hpp"

using namespace dgwarp;

namespace {

const Mesh& two_element() {
    static const Mesh m = make_two_element();
    return m;
}

// The shortest distance between the nodes of two markers, brute force, with
// the second marker's nodes moved by `motion` (every marker node the same).
double marker_gap(const Mesh& m, const std::string& fixed, const std::string& moved, const NodeMotion& motion) {
    double gap = 1e300;
    for (NodeId b : marker_nodes(find_marker(m, moved))) {
        double y[2];
        apply_motion(motion, std::span<const double>(m.points).subspan(2 * b, 2), std::span<double>(y, 2));
        for (NodeId a : marker_nodes(find_marker(m, fixed)))
            gap = std::min(gap, std::hypot(m.points[2 * a] - y[0], m.points[2 * a + 1] - y[1]));
    }
    return gap;
}

}  // namespace

TEST(CasesTwoElement, MarkersCountsAndAValidOriginalMesh) {
    const Mesh& m = two_element();
    EXPECT_EQ(m.dim, 2);
    EXPECT_NO_THROW(validate(m));
    EXPECT_EQ(marker_nodes(find_marker(m, "main")).size(), 200u);
    EXPECT_EQ(marker_nodes(find_marker(m, "flap")).size(), 100u);
    EXPECT_EQ(marker_nodes(find_marker(m, "farfield")).size(), 48u);
    EXPECT_GT(m.num_points(), 2000u);
    EXPECT_LT(m.num_points(), 20000u);
    const QualitySummary q = summarize_quality(cell_qualities(m, cell_orientations(m)));
    EXPECT_EQ(q.inverted, 0);
    EXPECT_GT(q.min, 0.3);
}

TEST(CasesTwoElement, TheSlotIsAboutTwoPercentChordAndOpensAsTheFlapDeflects) {
    const Mesh& m = two_element();
    const double flap_spacing = 0.3 / 50;  // the flap's wall spacing, the cells' size in the slot
    const double gap0 = marker_gap(m, "main", "flap", {});
    EXPECT_GT(gap0, 0.015);
    EXPECT_LT(gap0, 0.03);
    EXPECT_GE(gap0, 2 * flap_spacing);  // at least two cells across
    double previous = gap0;
    for (const CaseMotion& c : case_motions("two-element", m)) {
        const auto& marker = c.spec.frames.at(0).markers.at("flap");
        const NodeMotion motion = std::get<RigidMotion>(marker).motion;
        const double gap = marker_gap(m, "main", "flap", motion);
        EXPECT_GE(gap, previous - 1e-12) << c.name;  // never closer than before
        previous = gap;
    }
}

TEST(CasesTwoElement, DgHarmonicKeepsEveryCellValidWhereDgIdwFolds) {
    // Measured: dg-harmonic min 0.609 / 0.542 / 0.416 / 0.286 at 10-40°; the
    // paper's DG-IDW inverts 132 / 208 / 250 / 285 cells.
    const std::map<std::string, std::pair<double, std::int64_t>> measured = {
        {"flap-10", {0.609, 132}}, {"flap-20", {0.542, 208}}, {"flap-30", {0.416, 250}}, {"flap-40", {0.286, 285}}};
    const Mesh& m = two_element();
    const auto orientation = cell_orientations(m);
    for (const CaseMotion& c : case_motions("two-element", m)) {
        const ResolvedBoundary rb = resolve_boundary(m, c.spec);
        const ResolvedFrame frame = resolve_frame(m, c.spec, rb, 0);
        for (Method method : {Method::dg_harmonic, Method::dg_idw}) {
            std::vector<double> out(m.points.size());
            deform(prepare(method, 2, m.points, rb.boundary), m.points, frame.motion, out);
            Mesh moved = m;
            moved.points = out;
            const QualitySummary q = summarize_quality(cell_qualities(moved, orientation));
            if (method == Method::dg_harmonic) {
                EXPECT_EQ(q.inverted, 0) << c.name;
                EXPECT_GT(q.min, 0.98 * measured.at(c.name).first) << c.name;
            } else {
                EXPECT_NEAR(double(q.inverted), double(measured.at(c.name).second), 0.05 * double(measured.at(c.name).second))
                    << c.name;
            }
        }
    }
}

TEST(CasesTwoElement, APitchingFlapComesBackToItsOriginalMeshAfterOnePeriod) {
    // Issue #12: 20 steps of a pitching flap (±20° about its hinge); every
    // step is computed from the original mesh, so after one period every node
    // is back within 1e-12 of the mesh size.
    const Mesh& m = two_element();
    const auto hinge = two_element_hinge();
    MotionSpec spec;
    spec.frames.push_back({{{"flap", RigidMotion{}}}});
    const ResolvedBoundary rb = resolve_boundary(m, spec);
    const Plan plan = prepare(Method::dg_harmonic, 2, m.points, rb.boundary);
    std::vector<double> out(m.points.size());
    double size = 0;
    for (double v : m.points) size = std::max(size, std::abs(v));
    for (int step = 1; step <= 20; ++step) {
        const double angle = -20 * std::numbers::pi / 180 * std::sin(2 * std::numbers::pi * step / 20);
        BoundaryMotion motion(rb.boundary.nodes.size());
        for (std::size_t b = 0; b < motion.size(); ++b)
            if (rb.boundary.moving[b]) motion[b] = {{0, 0, 0}, {0, 0, angle}, {hinge[0], hinge[1], 0}};
        deform(plan, m.points, motion, out);
    }
    for (std::size_t i = 0; i < out.size(); ++i) ASSERT_NEAR(out[i], m.points[i], 1e-12 * size) << i;
}
