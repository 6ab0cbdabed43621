// DG-harmonic's guard on a mesh file (issue #26's speed acceptance): the
// default's prepare and step with and without its guard against DG-IDW's, one
// thread then two, on the first frame of a motion file; the guard's measure
// alone, and the one pass's time inside a guarded step; then what the run
// layer (dgwarp deform, Python, the OpenFOAM plugin) runs: prepare_for_frames
// and frames of step_frame + finish_frame, where the guard judges the one pass
// on the frame's own measure.
//
// Usage: dgwarp_bench_guard MESH MOTION.json [--steps N]
//   e.g. dgwarp case squeezed-sphere --size 2 -o s2.msh --motions s2 (865k nodes), then
//        dgwarp_bench_guard s2.msh s2/squeeze.json
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>
#include <vector>

#include "dgwarp/core/parallel_for.hpp"
#include "dgwarp/core/stopwatch.hpp"
#include "dgwarp/graph/morton_order.hpp"
#include "dgwarp/io/mesh_io.hpp"
#include "dgwarp/io/motion_file.hpp"
#include "dgwarp/methods/dg_harmonic_guard.hpp"
#include "dgwarp/methods/method.hpp"
#include "dgwarp/motion/resolve_motion.hpp"
#include "dgwarp/run/deform_frame.hpp"
#include "dgwarp/run/run_deformation.hpp"
#include "bench_timing.hpp"

using namespace dgwarp;
using bench::median_seconds;

namespace {

void run(const Mesh& mesh, const BoundarySet& boundary, const BoundaryMotion& motion, int threads, int steps) {
    set_num_threads(threads);
    Plan idw, one_pass, guarded;
    const double idw_prepare = median_seconds(3, [&] { idw = prepare(Method::dg_idw, mesh.dim, mesh.points, boundary); });
    const double harm_prepare =
        median_seconds(3, [&] { one_pass = prepare(Method::dg_harmonic, mesh.dim, mesh.points, boundary); });
    const double guard_prepare = median_seconds(
        3, [&] { guarded = prepare(Method::dg_harmonic, mesh.dim, mesh.points, mesh.cells, boundary); });
    std::vector<double> out(mesh.points.size());
    const auto step = [&](const Plan& p) { return median_seconds(steps, [&] { deform(p, mesh.points, motion, out); }); };
    const double idw_step = step(idw), harm_step = step(one_pass), guard_step = step(guarded);
    const DgHarmonicPlan& h = std::get<DgHarmonicPlan>(guarded);
    deform(one_pass, mesh.points, motion, out);
    const double measure = median_seconds(steps, [&] { (void)measure_for_guard(*h.guard, out); });
    const StepReport r = deform(guarded, mesh.points, motion, out);
    double sink = 0;
    const double gather = median_seconds(steps, [&] {
        double acc = 0;
        for (std::size_t c = 0; c < mesh.cells.size(); ++c)
            for (NodeId v : mesh.cells.nodes_of(c)) acc += out[3 * static_cast<std::size_t>(v)];
        sink += acc;
    });
    const double stream = median_seconds(steps, [&] {
        double acc = 0;
        for (std::size_t c = 0; c < mesh.cells.size(); ++c)
            for (NodeId v : mesh.cells.nodes_of(c)) acc += v;
        sink += acc;
    });
    std::printf("  gather of the cells' points alone (one thread): %.2f ms; the cells' node ids alone %.2f ms (%g)\n",
                1e3 * gather, 1e3 * stream, sink);
    std::printf("%d thread%s: dg-idw prepare %.3f s, step %.2f ms\n", threads, threads > 1 ? "s" : "", idw_prepare,
                1e3 * idw_step);
    std::printf("  dg-harmonic without guard: prepare %.3f s (%.2f x), step %.2f ms (%.2f x)\n", harm_prepare,
                harm_prepare / idw_prepare, 1e3 * harm_step, harm_step / idw_step);
    std::printf("  dg-harmonic with guard:    prepare %.3f s (%.2f x), step %.2f ms (%.2f x); measure alone %.2f ms; "
                "redone %s, one pass min %.4f, inverted %lld\n",
                guard_prepare, guard_prepare / idw_prepare, 1e3 * guard_step, guard_step / idw_step, 1e3 * measure,
                r.guard.redone ? "yes" : "no", r.guard.one_pass.min_quality,
                static_cast<long long>(r.guard.one_pass.inverted));

    // What `dgwarp deform`, Python and the OpenFOAM plugin run (the run
    // layer): prepare_for_frames (DG-harmonic's guard without its own
    // measure), then per frame step_frame and finish_frame's measure, which
    // every method's frame has; DG-harmonic's guard judges its one pass on it.
    const OriginalCells original = measure_original(mesh);
    Plan idw_run, harm_run;
    const double idw_run_prepare =
        median_seconds(5, [&] { idw_run = prepare_for_frames(Method::dg_idw, mesh, boundary); });
    const double harm_run_prepare =
        median_seconds(5, [&] { harm_run = prepare_for_frames(Method::dg_harmonic, mesh, boundary); });
    const auto frame = [&](const Plan& p, double& step_seconds) {
        std::vector<double> steps_seen;
        const double whole = median_seconds(steps, [&] {
            FrameReport report;
            std::optional<FrameCells> cells =
                step_frame(p, mesh, original, boundary.nodes, nullptr, motion, {}, out, report);
            finish_frame(plan_method(p), mesh, original, boundary.nodes, {}, out, report, {}, std::move(cells));
            steps_seen.push_back(report.step_seconds);
        });
        std::sort(steps_seen.begin(), steps_seen.end());
        step_seconds = steps_seen[steps_seen.size() / 2];
        return whole;
    };
    double idw_run_step = 0, harm_run_step = 0;
    const double idw_frame = frame(idw_run, idw_run_step), harm_frame = frame(harm_run, harm_run_step);
    std::printf("  run layer (dgwarp deform): dg-idw prepare %.3f s, step %.2f ms, frame %.2f ms (step, repair, measure)\n",
                idw_run_prepare, 1e3 * idw_run_step, 1e3 * idw_frame);
    std::printf("  run layer (dgwarp deform): dg-harmonic prepare %.3f s (%.2f x), step %.2f ms (%.2f x; the guard "
                "judges on the frame's measure), frame %.2f ms (%.2f x)\n",
                harm_run_prepare, harm_run_prepare / idw_run_prepare, 1e3 * harm_run_step, harm_run_step / idw_run_step,
                1e3 * harm_frame, harm_frame / idw_frame);
}

/// The mesh with its nodes renumbered along a Morton curve and its cells in
/// the Morton order of their first node (as solvers renumber for locality).
struct Scene {
    Mesh mesh;
    BoundarySet boundary;
    BoundaryMotion motion;
};
Scene renumbered(const Mesh& m, const BoundarySet& boundary, const BoundaryMotion& motion) {
    std::vector<NodeId> all(m.num_points());
    for (std::size_t i = 0; i < all.size(); ++i) all[i] = static_cast<NodeId>(i);
    const std::vector<std::uint32_t> order = morton_order(m.dim, m.points, all);
    std::vector<NodeId> new_id(all.size());
    Scene scene;
    Mesh& r = scene.mesh;
    r.dim = m.dim;
    r.points.resize(m.points.size());
    const auto d = static_cast<std::size_t>(m.dim);
    for (std::size_t k = 0; k < order.size(); ++k) {
        new_id[order[k]] = static_cast<NodeId>(k);
        for (std::size_t j = 0; j < d; ++j) r.points[k * d + j] = m.points[order[k] * d + j];
    }
    const auto remap = [&](const ElementList& in, bool sort) {
        std::vector<std::size_t> cells(in.size());
        for (std::size_t c = 0; c < cells.size(); ++c) cells[c] = c;
        if (sort)
            std::stable_sort(cells.begin(), cells.end(), [&](std::size_t a, std::size_t b) {
                return new_id[in.nodes_of(a)[0]] < new_id[in.nodes_of(b)[0]];
            });
        ElementList out;
        std::vector<NodeId> nodes;
        for (std::size_t c : cells) {
            nodes.clear();
            for (NodeId v : in.nodes_of(c)) nodes.push_back(new_id[v]);
            out.push_back(in.types[c], nodes);
        }
        return out;
    };
    r.cells = remap(m.cells, true);
    for (const Marker& mk : m.markers) {
        Marker k = mk;
        k.elements = remap(mk.elements, false);
        r.markers.push_back(std::move(k));
    }
    std::vector<std::size_t> b(boundary.nodes.size());
    for (std::size_t i = 0; i < b.size(); ++i) b[i] = i;
    std::sort(b.begin(), b.end(), [&](std::size_t x, std::size_t y) {
        return new_id[boundary.nodes[x]] < new_id[boundary.nodes[y]];
    });
    for (std::size_t i : b) {
        scene.boundary.nodes.push_back(new_id[boundary.nodes[i]]);
        scene.boundary.moving.push_back(boundary.moving[i]);
        scene.motion.push_back(motion[i]);
    }
    return scene;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 3) {
        std::fprintf(stderr, "usage: %s MESH MOTION.json [--steps N]\n", argv[0]);
        return 2;
    }
    int steps = 11;
    if (argc >= 5 && std::string(argv[3]) == "--steps") steps = std::max(1, std::atoi(argv[4]));
    try {
        Stopwatch sw;
        const bool renumber = std::string(argv[argc - 1]) == "--renumber";
        const Mesh mesh = read_mesh(argv[1]);
        const MotionSpec spec = read_motion_file(argv[2]);
        const ResolvedBoundary resolved = resolve_boundary(mesh, spec);
        const ResolvedFrame frame = resolve_frame(mesh, spec, resolved, 0);
        std::printf("DG-harmonic's guard: %s, %zu nodes, %zu cells, %zu boundary nodes (read %.2f s)\n", argv[1],
                    mesh.num_points(), mesh.cells.size(), resolved.boundary.nodes.size(), sw.lap());
        Scene scene{mesh, resolved.boundary, frame.motion};
        if (renumber) {
            scene = renumbered(mesh, resolved.boundary, frame.motion);
            std::printf("nodes renumbered along a Morton curve, cells in the order of their first node\n");
        }
        run(scene.mesh, scene.boundary, scene.motion, 1, steps);
        if (available_cores() >= 2) run(scene.mesh, scene.boundary, scene.motion, 2, steps);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "error: %s\n", e.what());
        return 1;
    }
    return 0;
}
