// DG-IDW on the paper's squeezed-sphere meshes: prepare time by stage, step
// time (1 and 2 threads) against a plain streaming pass over the same arrays,
// DG-harmonic's prepare and step against DG-IDW's, plan memory, plan file
// round trip, and the effect of the length scale.
//
// Usage: dgwarp_bench_dg_idw [--generate-only | --dg-harmonic] [case ...]
//   cases: 200k 400k 826k (default: all); --generate-only: make the cached meshes and stop;
//   --dg-harmonic: only DG-harmonic against DG-IDW (issue #12's speed targets).
#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

#include "dgwarp/cases/sphere_box.hpp"
#include "dgwarp/core/parallel_for.hpp"
#include "dgwarp/core/stopwatch.hpp"
#include "dgwarp/graph/delaunay_graph.hpp"
#include "dgwarp/plan/plan_file.hpp"
#include "dgwarp/methods/dg_harmonic.hpp"
#include "dgwarp/methods/dg_idw.hpp"
#include "bench_timing.hpp"
#include "sphere_box_mesh.hpp"

using namespace dgwarp;
using bench::median_seconds;
using bench::time_repeats;
using bench::Timing;

namespace {

// The least any one-pass method must do: read the plan's per-node arrays and
// the original coordinates, write every output coordinate.
void streaming_pass(const DgIdwPlan& plan, std::span<const double> x0, std::span<double> out) {
    parallel_for_chunks(plan.num_points(), [&](std::int64_t begin, std::int64_t end) {
        std::int64_t vol = begin - (std::lower_bound(plan.boundary_nodes.begin(), plan.boundary_nodes.end(), begin) -
                                    plan.boundary_nodes.begin());
        for (std::int64_t i = begin; i < end; ++i) {
            const std::int32_t s = plan.node_simplex[i];
            double sum = s * 1e-300;
            if (s >= 0) {
                const double* q = plan.node_coefficients.data() + 4 * vol++;
                sum += (q[0] + q[1]) + (q[2] + q[3]);
            }
            for (int d = 0; d < 3; ++d) out[3 * i + d] = x0[3 * i + d] + sum * 1e-300;
        }
    });
}

// DG-harmonic (the robust method, issue #12) against DG-IDW in the same run:
// prepare by stage and step, one thread; the ratios are issue #12's targets
// (prepare at most 2x, step at most 3x DG-IDW's). Then its step on two threads.
void compare_dg_harmonic(const bench::SphereBoxMesh& m, const BoundarySet& boundary, const BoundaryMotion& motion,
                         int steps) {
    set_num_threads(1);
    DgIdwPlan idw;
    DgHarmonicPlan harm;
    const double idw_prepare = median_seconds(3, [&] { idw = prepare_dg_idw(3, m.points, boundary); });
    const double harm_prepare = median_seconds(3, [&] { harm = prepare_dg_harmonic(3, m.points, boundary); });
    const DgHarmonicPrepareStats& s = harm.stats;
    std::printf("dg-harmonic prepare 1 thread: %.3f s (coarse points %.3f, graph %.3f, locate %.3f, factorise %.3f); "
                "%lld coarse interior points, factor %lld non-zeros; dg-idw prepare %.3f s; ratio %.2f\n",
                harm_prepare, s.select_seconds, s.graph_seconds, s.locate_seconds, s.factor_seconds,
                static_cast<long long>(s.coarse_interior), static_cast<long long>(s.factor_nonzeros), idw_prepare,
                harm_prepare / idw_prepare);
    std::vector<double> out(m.points.size());
    deform_dg_idw(idw, m.points, motion, out);
    const double idw_step = median_seconds(steps, [&] { deform_dg_idw(idw, m.points, motion, out); });
    deform_dg_harmonic(harm, m.points, motion, out);
    const double harm_step = median_seconds(steps, [&] { deform_dg_harmonic(harm, m.points, motion, out); });
    std::printf("dg-harmonic step 1 thread, median of %d: %.2f ms; dg-idw %.2f ms; ratio %.2f\n", steps,
                1e3 * harm_step, 1e3 * idw_step, harm_step / idw_step);
    if (available_cores() >= 2) {
        set_num_threads(2);
        const double harm_step2 = median_seconds(steps, [&] { deform_dg_harmonic(harm, m.points, motion, out); });
        std::printf("dg-harmonic step 2 threads, median of %d: %.2f ms; speed-up %.2f\n", steps, 1e3 * harm_step2,
                    harm_step / harm_step2);
        set_num_threads(1);
    }
}

// Squeeze the sphere into an ellipsoid (per-node translation) and turn it 10
// degrees about z; box nodes are static.
BoundaryMotion squeeze_and_turn(const bench::SphereBoxMesh& m, const BoundarySet& boundary) {
    BoundaryMotion motion(boundary.nodes.size());
    const double scale[3] = {1.3, 0.8, 0.8};
    for (std::size_t b = 0; b < boundary.nodes.size(); ++b) {
        if (!boundary.moving[b]) continue;
        const double* x = m.points.data() + 3 * static_cast<std::size_t>(boundary.nodes[b]);
        for (int d = 0; d < 3; ++d) motion[b].translation[d] = (scale[d] - 1) * x[d];
        motion[b].rotation = {0, 0, 10 * M_PI / 180};
    }
    return motion;
}

BoundarySet sphere_and_box(const bench::SphereBoxMesh& m) {
    BoundarySet boundary;
    std::vector<NodeId> ids = m.sphere_nodes;
    ids.insert(ids.end(), m.box_nodes.begin(), m.box_nodes.end());
    std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
    boundary.nodes = ids;
    for (NodeId n : ids)
        boundary.moving.push_back(std::binary_search(m.sphere_nodes.begin(), m.sphere_nodes.end(), n) &&
                                  !std::binary_search(m.box_nodes.begin(), m.box_nodes.end(), n));
    return boundary;
}

// The paper's whole DG-IDW run (graph, location, weights and one mapping) at
// 202k / 404k / 826k nodes, one core of a 2.7 GHz i7 (issue #13's targets).
double paper_whole_run_seconds(const std::string& case_name) {
    return case_name.starts_with("200k") ? 0.143 : case_name.starts_with("400k") ? 0.237 : 0.451;
}

void run_case(const bench::SphereBoxCase& c, const bench::SphereBoxMesh& m, int steps) {
    const BoundarySet boundary = sphere_and_box(m);
    const std::size_t n = m.num_points(), nb = boundary.nodes.size(), nv = n - nb;
    std::printf("\n== case %s: %zu nodes, %zu boundary (%zu sphere, %zu box), %zu volume; Gmsh %.1f s ==\n",
                c.name.c_str(), n, nb, m.sphere_nodes.size(), m.box_nodes.size(), nv, m.generate_seconds);

    // Prepare, single thread and two threads.
    double prepare_one_thread = 0;
    for (int threads : {1, 2}) {
        set_num_threads(threads);
        double total = 0;
        DgIdwPlan plan;
        total = median_seconds(3, [&] { plan = prepare_dg_idw(3, m.points, boundary); });
        std::printf("prepare %d thread(s): %.3f s  (graph %.3f, locate %.3f, coefficients %.3f)\n",
                    threads, total, plan.stats.graph_seconds, plan.stats.locate_seconds, plan.stats.weights_seconds);
        if (threads == 1) prepare_one_thread = total;
        else std::printf("prepare speed-up on 2 threads: %.2f\n", prepare_one_thread / total);
    }
    // Location in Gmsh's node order instead of Hilbert order.
    set_num_threads(1);
    {
        std::vector<NodeId> volume;
        for (std::size_t i = 0, b = 0; i < n; ++i) {
            if (b < nb && static_cast<std::size_t>(boundary.nodes[b]) == i) ++b;
            else volume.push_back(static_cast<NodeId>(i));
        }
        for (LocateOrder order : {LocateOrder::morton, LocateOrder::given, LocateOrder::automatic}) {
            const LocatedGraph lg = build_located_graph(3, m.points, boundary.nodes, volume, {order});
            std::printf("locate, 1 thread, %-26s %.3f s\n",
                        order == LocateOrder::morton ? "Morton order:"
                        : order == LocateOrder::given ? "mesh (Gmsh) order:"
                                                      : (std::string("automatic (") +
                                                         (lg.timings.spatially_sorted ? "Morton" : "mesh") + "):").c_str(),
                        lg.timings.locate_seconds);
        }
    }

    const DgIdwPlan plan = prepare_dg_idw(3, m.points, boundary);
    std::printf("outside hull %lld, on a vertex %lld, shared vertices %lld; graph: %zu vertices, %zu tetrahedra\n",
                static_cast<long long>(plan.stats.outside_count), static_cast<long long>(plan.stats.snapped_count),
                static_cast<long long>(plan.stats.shared_vertex_count), static_cast<std::size_t>(plan.stats.graph_vertex_count),
                plan.simplex_motion.size() / 4);
    const std::size_t per_node_bytes = plan.node_simplex.size() * 4 + plan.node_coefficients.size() * 8;
    std::printf("plan memory: %.1f bytes per volume node (%.1f MB; per-node arrays alone %.1f B/volume node)\n",
                double(plan_bytes(plan)) / nv, plan_bytes(plan) / 1e6, double(per_node_bytes) / nv);

    const BoundaryMotion motion = squeeze_and_turn(m, boundary);
    std::vector<double> out(m.points.size());
    // The paper's figure: prepare and one step, one thread, from nothing.
    set_num_threads(1);
    const Timing whole = time_repeats(3, [&] {
        const DgIdwPlan p = prepare_dg_idw(3, m.points, boundary);
        deform_dg_idw(p, m.points, motion, out);
    });
    const double paper = paper_whole_run_seconds(c.name);
    std::printf("whole run (prepare + one step), 1 thread, median (min) of 3: %.3f (%.3f) s; the paper's %.3f s; "
                "ratio %.2f\n", whole.median, whole.min, paper, whole.median / paper);
    double step_one_thread = 0;
    for (int threads : {1, 2}) {
        set_num_threads(threads);
        deform_dg_idw(plan, m.points, motion, out);  // warm up
        const Timing step = time_repeats(steps, [&] { deform_dg_idw(plan, m.points, motion, out); });
        streaming_pass(plan, m.points, out);
        const Timing stream = time_repeats(steps, [&] { streaming_pass(plan, m.points, out); });
        BoundaryMotion translate_only = motion;
        for (NodeMotion& nm : translate_only) nm.rotation = {};
        const Timing step_t = time_repeats(steps, [&] { deform_dg_idw(plan, m.points, translate_only, out); });
        std::printf("step %d thread(s), median (min) of %d: %.2f (%.2f) ms; translation only %.2f (%.2f) ms; "
                    "streaming pass %.2f (%.2f) ms; step / streaming %.2f\n",
                    threads, steps, 1e3 * step.median, 1e3 * step.min, 1e3 * step_t.median, 1e3 * step_t.min,
                    1e3 * stream.median, 1e3 * stream.min, step.median / stream.median);
        if (threads == 1) step_one_thread = step.median;
        else std::printf("step speed-up on 2 threads: %.2f\n", step_one_thread / step.median);
    }
    compare_dg_harmonic(m, boundary, motion, steps);
    set_num_threads(1);

    // Plan file round trip.
    std::string stem = c.name;
    for (char& ch : stem)
        if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
    const auto file = std::filesystem::path(DGWARP_BENCH_CACHE_DIR) / ("plan_" + stem + ".dgwplan");
    const double save_s = median_seconds(1, [&] { save_dg_idw_plan(file, plan); });
    DgIdwPlan loaded;
    const double load_s = median_seconds(1, [&] { loaded = load_dg_idw_plan(file, m.points, boundary); });
    std::vector<double> again(out.size());
    deform_dg_idw(plan, m.points, motion, out);
    deform_dg_idw(loaded, m.points, motion, again);
    std::printf("plan file: %.1f MB, save %.3f s, load+check %.3f s, loaded plan output %s\n",
                std::filesystem::file_size(file) / 1e6, save_s, load_s,
                std::memcmp(out.data(), again.data(), out.size() * sizeof(double)) == 0 ? "bit-identical" : "DIFFERENT");
    std::filesystem::remove(file);

    // Length scale: the paper's formula (L = 1) against L = auto (moving bbox diagonal).
    for (double l : {1.0, 0.0}) {
        DgIdwPlan with_l = plan;
        with_l.options.length_scale = l;
        deform_dg_idw(with_l, m.points, motion, out);
        double sum = 0, far = 0;
        std::size_t far_count = 0;
        for (std::size_t i = 0; i < n; ++i) {
            if (plan.node_simplex[i] < 0) continue;
            const double* x = m.points.data() + 3 * i;
            const double dx = out[3 * i] - x[0], dy = out[3 * i + 1] - x[1], dz = out[3 * i + 2] - x[2];
            const double d = std::sqrt(dx * dx + dy * dy + dz * dz);
            sum += d;
            if (std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]) > 3) {
                far += d;
                ++far_count;
            }
        }
        std::printf("L = %-5s: mean volume-node displacement %.4f, beyond radius 3: %.4f\n",
                    l == 0 ? ("auto (" + std::to_string(plan.auto_length_scale).substr(0, 5) + ")").c_str() : "1",
                    sum / nv, far_count ? far / far_count : 0.0);
    }
}

}  // namespace

int main(int argc, char** argv) {
    // The library's squeezed-sphere sizes (cases/sphere_box.hpp), chosen to
    // approach the paper's node counts (201,920 / 403,840 / 826,080 nodes;
    // 10,096 / 10,096 / 41,304 boundary).
    std::vector<bench::SphereBoxCase> cases;
    for (int size = 0; size < 3; ++size)
        cases.push_back({std::array{"200k", "400k", "826k"}[size], sphere_box_paper_size(size)});
    std::vector<std::string> wanted(argv + 1, argv + argc);
    const bool generate_only = std::erase(wanted, "--generate-only") > 0;
    const bool harmonic_only = std::erase(wanted, "--dg-harmonic") > 0;
    if (wanted.empty())
        for (const auto& c : cases) wanted.push_back(c.name);
    // Generate (or load) every mesh first: Gmsh runs in forked children,
    // which must happen before this process starts OpenMP threads.
    std::vector<std::pair<bench::SphereBoxCase, bench::SphereBoxMesh>> meshes;
    for (const auto& c : cases)
        if (std::find(wanted.begin(), wanted.end(), c.name) != wanted.end())
            meshes.emplace_back(c, bench::sphere_box_mesh(c, DGWARP_BENCH_CACHE_DIR, 900));
    if (generate_only) return 0;
    std::printf("DG-IDW benchmark: squeezed sphere in a box (paper section 3), %d hardware threads\n",
                static_cast<int>(std::thread::hardware_concurrency()));
    for (const auto& [c, m] : meshes) {
        if (harmonic_only) {
            const BoundarySet boundary = sphere_and_box(m);
            std::printf("\n== case %s: %zu nodes, %zu boundary ==\n", c.name.c_str(), m.num_points(), boundary.nodes.size());
            compare_dg_harmonic(m, boundary, squeeze_and_turn(m, boundary), 21);
            continue;
        }
        run_case(c, m, 21);
        // The same mesh renumbered for locality: the step's cost depends on
        // how far apart consecutive nodes' graph simplices are.
        bench::SphereBoxCase renumbered = c;
        renumbered.name += ", nodes renumbered along a Hilbert curve";
        run_case(renumbered, bench::renumbered_along_hilbert_curve(m), 21);
    }
    return 0;
}
