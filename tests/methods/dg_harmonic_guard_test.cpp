#include "dgwarp/methods/dg_harmonic_guard.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "dgwarp/cases/child_process.hpp"
#include "dgwarp/cases/paper_cases.hpp"
#include "dgwarp/cases/random_scene.hpp"
#include "dgwarp/core/error.hpp"
#include "dgwarp/core/parallel_for.hpp"
#include "dgwarp/io/mesh_io.hpp"
#include "dgwarp/methods/method.hpp"
#include "dgwarp/motion/resolve_motion.hpp"
#include "dgwarp/quality/mesh_quality.hpp"
#include "support/case_frame.hpp"
#include "support/test_paths.hpp"

using namespace dgwarp;

namespace {

struct Scene {
    Mesh mesh;
    ResolvedBoundary boundary;
    BoundaryMotion motion;
};

Scene case_scene(const std::string& name, const std::string& motion_name) {
    test::CaseFrame c = test::case_frame(name, motion_name);
    return {std::move(c.mesh), std::move(c.boundary), std::move(c.frame.motion)};
}

// Random 2D scene 1 (docs/ROBUSTNESS-2D.md): a circle and a rounded rectangle
// turning 83° and 62° beside a fixed ellipse; DG-harmonic's one pass inverts
// hundreds of cells there, laplacian none. Made by Gmsh in a child process
// with a time limit.
Scene folding_scene() {
    const RandomScene scene = random_scene(2, 1);
    const auto file = test::scratch_dir() / "guard-scene-2-1.msh";
    run_in_child_process([&] { write_mesh(file, make_random_scene_mesh(scene)); }, 300, "random scene");
    Scene s;
    s.mesh = read_mesh(file);
    const MotionSpec spec = random_scene_motion(scene);
    s.boundary = resolve_boundary(s.mesh, spec);
    s.motion = resolve_frame(s.mesh, spec, s.boundary, 0).motion;
    return s;
}

// Brute force: the judged cells' minimum quality and the cells inverted, from
// cell_qualities against the original's majority orientations.
GuardMeasure brute_force(const Mesh& original, std::span<const double> points) {
    const auto orientation = dominant_orientations(original);
    const std::vector<double> before = cell_qualities(original, orientation);
    const std::vector<double> after = cell_qualities(original, points, orientation);
    GuardMeasure m;
    m.min_quality = 1e300;
    for (std::size_t c = 0; c < after.size(); ++c) {
        if (!(before[c] > 0)) continue;
        if (!(after[c] > 0)) ++m.inverted;
        m.min_quality = std::min(m.min_quality, after[c]);
    }
    return m;
}

MethodOptions redo_below(double fraction) {
    MethodOptions o;
    o.dg_harmonic.redo_below = fraction;
    return o;
}

}  // namespace

TEST(DgHarmonicGuard, MeasureIsTheBruteForceMinimumAndInvertedCount) {
    // Tetrahedra (the kernel), triangles and mixed hexahedra/prisms/pyramids
    // (the generic metric), each shaken until some cells invert.
    for (const char* name : {"twisted-bar", "rect-box", "store"}) {
        SCOPED_TRACE(name);
        const Mesh mesh = make_case(name);
        const BoundarySet boundary = resolve_boundary(mesh, MotionSpec{}).boundary;
        const auto guard = make_dg_harmonic_guard(mesh.dim, mesh.points, mesh.cells, boundary);
        const GuardMeasure original = measure_for_guard(*guard, mesh.points);
        EXPECT_EQ(original.inverted, 0);
        EXPECT_EQ(original.min_quality, brute_force(mesh, mesh.points).min_quality);
        EXPECT_EQ(guard->original_min, original.min_quality);
        std::mt19937_64 rng(5);
        for (double shake : {0.02, 5.0}) {
            const BoundingBox box = bounding_box(mesh);
            double size = 0;
            for (int d = 0; d < mesh.dim; ++d) size = std::max(size, box.max[d] - box.min[d]);
            std::uniform_real_distribution<double> u(-shake * size / 100, shake * size / 100);
            std::vector<double> moved = mesh.points;
            for (double& x : moved) x += u(rng);
            const GuardMeasure fast = measure_for_guard(*guard, moved);
            const GuardMeasure slow = brute_force(mesh, moved);
            EXPECT_EQ(fast.inverted, slow.inverted);
            EXPECT_EQ(fast.min_quality, slow.min_quality);
            if (shake > 0.1) {
                EXPECT_GT(fast.inverted, 0);  // the test reaches the inverted branch
            }
        }
    }
}

TEST(DgHarmonicGuard, MeasureIsTheBruteForceAtExtremeScalesAndAnyThreadCount) {
    // The kernel compares a product with the running minimum instead of
    // dividing: at 2^-168 the denominator's cube is subnormal, at 2^200 it
    // overflows, at 2^-400 and 2^365 the determinant does too; each must
    // fall back to dividing or to the exact value.
    for (const char* name : {"twisted-bar", "rect-box"}) {
        SCOPED_TRACE(name);
        const Mesh mesh = make_case(name);
        const BoundarySet boundary = resolve_boundary(mesh, MotionSpec{}).boundary;
        std::mt19937_64 rng(11);
        std::uniform_real_distribution<double> u(-0.002, 0.002);
        std::vector<double> shaken = mesh.points;
        for (double& x : shaken) x += u(rng);
        for (double scale : {1.0, 0x1p-400, 0x1p-168, 0x1p+200, 0x1p+365}) {
            SCOPED_TRACE(scale);
            Mesh scaled = mesh;
            for (double& x : scaled.points) x *= scale;
            std::vector<double> moved = shaken;
            for (double& x : moved) x *= scale;
            const auto guard = make_dg_harmonic_guard(scaled.dim, scaled.points, scaled.cells, boundary);
            const GuardMeasure slow = brute_force(scaled, moved);
            const int before = num_threads();
            for (int threads : {1, 2}) {
                set_num_threads(threads);
                const GuardMeasure fast = measure_for_guard(*guard, moved);
                EXPECT_EQ(fast.inverted, slow.inverted);
                EXPECT_EQ(fast.min_quality, slow.min_quality);
                EXPECT_GT(fast.min_quality, 0);
            }
            set_num_threads(before);
        }
    }
}

TEST(DgHarmonicGuard, AMildStepKeepsTheOnePassBitForBit) {
    const Scene s = case_scene("naca0012", "rotate-45");
    const Plan plan = prepare(Method::dg_harmonic, 2, s.mesh.points, s.mesh.cells, s.boundary.boundary);
    std::vector<double> guarded(s.mesh.points.size()), one_pass(s.mesh.points.size());
    const StepReport r = deform(plan, s.mesh.points, s.motion, guarded);
    EXPECT_TRUE(r.guard.checked);
    EXPECT_FALSE(r.guard.redone);
    EXPECT_EQ(r.substeps, 1);
    EXPECT_EQ(r.guard.one_pass.min_quality, brute_force(s.mesh, guarded).min_quality);
    EXPECT_GE(r.guard.one_pass.min_quality, r.guard.bar);
    const StepReport unguarded = deform(plan, s.mesh.points, s.motion, one_pass, redo_below(-1));
    EXPECT_FALSE(unguarded.guard.checked);
    EXPECT_EQ(guarded, one_pass);
    // Without the cells there is no guard: the same one pass, unchecked.
    const Plan cloud = prepare(Method::dg_harmonic, 2, s.mesh.points, s.boundary.boundary);
    std::vector<double> from_cloud(s.mesh.points.size());
    EXPECT_FALSE(deform(cloud, s.mesh.points, s.motion, from_cloud).guard.checked);
    EXPECT_EQ(from_cloud, one_pass);
}

TEST(DgHarmonicGuard, AStepTheOnePassFoldsIsSolvedAgainByLaplacianAndValid) {
    const Scene s = folding_scene();
    const Plan plan = prepare(Method::dg_harmonic, 2, s.mesh.points, s.mesh.cells, s.boundary.boundary);
    std::vector<double> one_pass(s.mesh.points.size()), guarded(s.mesh.points.size()),
        reference(s.mesh.points.size());
    deform(plan, s.mesh.points, s.motion, one_pass, redo_below(-1));
    const GuardMeasure folded = brute_force(s.mesh, one_pass);
    ASSERT_GT(folded.inverted, 0);  // the scene folds the one pass
    const StepReport r = deform(plan, s.mesh.points, s.motion, guarded);
    EXPECT_TRUE(r.guard.redone);
    EXPECT_TRUE(r.guard.kept_redo);
    EXPECT_EQ(r.guard.one_pass.inverted, folded.inverted);
    EXPECT_EQ(r.guard.one_pass.min_quality, folded.min_quality);
    EXPECT_TRUE(r.guard.redo_error.empty());
    // The kept result is laplacian's, bit for bit, with its increments.
    const StepReport lr = deform(prepare(Method::laplacian, 2, s.mesh.points, s.mesh.cells, s.boundary.boundary),
                                 s.mesh.points, s.motion, reference);
    // Points no cell uses (the scene's mesh has some) move with the one pass,
    // which laplacian leaves where they were.
    std::vector<std::uint8_t> used(s.mesh.num_points(), 0);
    for (NodeId n : s.mesh.cells.nodes) used[static_cast<std::size_t>(n)] = 1;
    ASSERT_TRUE(std::count(used.begin(), used.end(), 0) > 0);
    for (std::size_t n = 0; n < used.size(); ++n)
        for (std::size_t d = 0; d < 2; ++d)
            ASSERT_EQ(guarded[2 * n + d], used[n] ? reference[2 * n + d] : one_pass[2 * n + d]) << "node " << n;
    EXPECT_EQ(r.substeps, lr.substeps);
    EXPECT_EQ(r.guard.increments, lr.substeps);
    const GuardMeasure after = brute_force(s.mesh, guarded);
    EXPECT_EQ(after.inverted, 0);
    EXPECT_EQ(r.guard.redo.min_quality, after.min_quality);
    EXPECT_NE(guard_summary(r.guard).find("solved again by laplacian"), std::string::npos);

    // Output aliasing the input, and one thread against two: the same bits.
    std::vector<double> in_place = s.mesh.points;
    deform(plan, in_place, s.motion, in_place);
    EXPECT_EQ(in_place, guarded);
    const int threads = num_threads();
    set_num_threads(1);
    std::vector<double> serial(s.mesh.points.size());
    deform(plan, s.mesh.points, s.motion, serial);
    set_num_threads(threads);
    EXPECT_EQ(serial, guarded);
}

TEST(DgHarmonicGuard, TheBetterResultIsKeptAndZeroRedoesOnlyFolds) {
    // A bar no step of the rect-box's 90° turn reaches: both results measured,
    // the one with the higher minimum kept.
    const Scene s = case_scene("rect-box", "rotate-90");
    const Plan plan = prepare(Method::dg_harmonic, 2, s.mesh.points, s.mesh.cells, s.boundary.boundary);
    std::vector<double> out(s.mesh.points.size());
    const StepReport r = deform(plan, s.mesh.points, s.motion, out, redo_below(0.99));
    ASSERT_TRUE(r.guard.redone);
    EXPECT_EQ(r.guard.kept_redo, r.guard.redo.min_quality > r.guard.one_pass.min_quality);
    EXPECT_EQ(brute_force(s.mesh, out).min_quality,
              std::max(r.guard.redo.min_quality, r.guard.one_pass.min_quality));
    // 0: a valid one pass is kept however low its minimum.
    const StepReport zero = deform(plan, s.mesh.points, s.motion, out, redo_below(0));
    EXPECT_TRUE(zero.guard.checked);
    EXPECT_FALSE(zero.guard.redone);
}

TEST(DgHarmonicGuard, AValidOnePassBelowTheBarGetsOneSolveOfLaplaciansIncrements) {
    // The twisted bar's twist: the one pass is valid at 0.55 of the original
    // minimum (below the default bar, 0.8), and laplacian folds the bar's
    // corners at any number of increments (docs/laplacian.md): one solve of
    // its 4 increments, not 4 + 8 + ... + 64, and the one pass is kept.
    const Scene s = case_scene("twisted-bar", "twist");
    const Plan plan = prepare(Method::dg_harmonic, 2, s.mesh.points, s.mesh.cells, s.boundary.boundary);
    std::vector<double> guarded(s.mesh.points.size()), one_pass(s.mesh.points.size());
    const StepReport r = deform(plan, s.mesh.points, s.motion, guarded);
    deform(plan, s.mesh.points, s.motion, one_pass, redo_below(-1));
    ASSERT_TRUE(r.guard.checked);
    EXPECT_EQ(r.guard.one_pass.inverted, 0);
    EXPECT_LT(r.guard.one_pass.min_quality, r.guard.bar);
    EXPECT_TRUE(r.guard.redone);
    EXPECT_EQ(r.guard.increments, LaplacianOptions{}.increments);
    EXPECT_GT(r.guard.redo.inverted, 0);
    EXPECT_FALSE(r.guard.kept_redo);
    EXPECT_EQ(guarded, one_pass);
}

TEST(DgHarmonicGuard, RefusesABarThatIsNotAFractionBelowOne) {
    const Scene s = case_scene("rect-box", "rotate-30");
    for (double bad : {std::nan(""), 1.0, 2.0}) {
        EXPECT_THROW(prepare(Method::dg_harmonic, 2, s.mesh.points, s.mesh.cells, s.boundary.boundary, redo_below(bad)),
                     Error);
        const Plan plan = prepare(Method::dg_harmonic, 2, s.mesh.points, s.mesh.cells, s.boundary.boundary);
        std::vector<double> out(s.mesh.points.size());
        EXPECT_THROW(deform(plan, s.mesh.points, s.motion, out, redo_below(bad)), Error);
    }
    // Cells the guard cannot measure are refused at prepare, naming the cell.
    ElementList bad_cells = s.mesh.cells;
    bad_cells.nodes[0] = static_cast<NodeId>(s.mesh.num_points());
    try {
        prepare(Method::dg_harmonic, 2, s.mesh.points, bad_cells, s.boundary.boundary);
        FAIL() << "no error";
    } catch (const MeshError& e) {
        EXPECT_NE(std::string(e.what()).find("cell 0"), std::string::npos) << e.what();
    }
}

TEST(DgHarmonicGuard, A3dMeshAboveTheNodeLimitIsNotSolvedAgainAndTheReportSaysWhy) {
    // The store dropped and pitched 30°: with a bar of 0.9 × the original minimum
    // the one pass is below it; a node limit under the mesh's nodes keeps the
    // one pass (no laplacian solve), says why, and redo_max_nodes_3d must not
    // be negative.
    const Scene s = case_scene("store", "drop-pitch-30");
    ASSERT_FALSE(s.motion.empty());
    MethodOptions small = redo_below(0.9);
    small.dg_harmonic.redo_max_nodes_3d = static_cast<std::int64_t>(s.mesh.num_points()) - 1;
    const Plan plan = prepare(Method::dg_harmonic, 3, s.mesh.points, s.mesh.cells, s.boundary.boundary, small);
    std::vector<double> guarded(s.mesh.points.size()), one_pass(s.mesh.points.size());
    const StepReport r = deform(plan, s.mesh.points, s.motion, guarded, redo_below(0.9));
    ASSERT_TRUE(r.guard.checked);
    EXPECT_LT(r.guard.one_pass.min_quality, r.guard.bar);
    EXPECT_FALSE(r.guard.redone);
    EXPECT_FALSE(r.guard.kept_redo);
    EXPECT_NE(r.guard.redo_error.find(std::to_string(s.mesh.num_points()) + " nodes"), std::string::npos)
        << r.guard.redo_error;
    EXPECT_NE(guard_summary(r.guard).find("not solved again"), std::string::npos) << guard_summary(r.guard);
    deform(plan, s.mesh.points, s.motion, one_pass, redo_below(-1));
    EXPECT_EQ(guarded, one_pass);
    MethodOptions negative;
    negative.dg_harmonic.redo_max_nodes_3d = -1;
    EXPECT_THROW(prepare(Method::dg_harmonic, 3, s.mesh.points, s.mesh.cells, s.boundary.boundary, negative), Error);
}
