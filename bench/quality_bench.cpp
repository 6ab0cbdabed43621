// The quality pass on a mesh file (issue #33 item 2): what `dgwarp deform`
// measures around every frame, phase by phase, one thread then two: the
// original's orientations and quality (measure_original), a frame's cells
// (measure_frame: quality, ratio, inverted cells) and their summaries.
//
// Usage: dgwarp_bench_quality MESH [--repeats N]
//   e.g. dgwarp case squeezed-sphere --size 2 -o s2.msh (865k nodes, 5.3M tetrahedra)
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "bench_timing.hpp"
#include "dgwarp/core/parallel_for.hpp"
#include "dgwarp/graph/morton_order.hpp"
#include "dgwarp/io/mesh_io.hpp"
#include "dgwarp/quality/mesh_quality.hpp"
#include "dgwarp/quality/quality_layout.hpp"
#include "dgwarp/run/deform_frame.hpp"
#include "dgwarp/run/original_cells.hpp"

using namespace dgwarp;
using bench::median_seconds;

int main(int argc, char** argv) {
    std::string file;
    int repeats = 5;
    if (!bench::mesh_and_repeats(argc, argv, file, repeats)) return 1;
    const Mesh mesh = read_mesh(file);
    std::printf("%s: %zu nodes, %zu cells\n", file.c_str(), mesh.num_points(), mesh.cells.size());
    // A frame: every node moved a little (1e-3 of its coordinate), so nothing folds.
    std::vector<double> moved = mesh.points;
    for (std::size_t i = 0; i < moved.size(); ++i) moved[i] *= 1 + 1e-3 * static_cast<double>(i % 7) / 7;
    std::vector<NodeId> fixed;  // no boundary: every inverted cell would be looked at
    // The same cells in the Morton order of their first node: how much of the pass is memory latency.
    {
        std::vector<NodeId> first(mesh.cells.size());
        for (std::size_t c = 0; c < first.size(); ++c) first[c] = mesh.cells.nodes_of(c)[0];
        const std::vector<std::uint32_t> order = morton_order(mesh.dim, mesh.points, first);
        Mesh sorted;
        sorted.dim = mesh.dim;
        sorted.points = mesh.points;
        for (std::uint32_t c : order) sorted.cells.push_back(mesh.cells.types[c], mesh.cells.nodes_of(c));
        const std::vector<std::int8_t> o(sorted.cells.size(), 1);
        for (int threads : {1, 2}) {
            set_num_threads(threads);
            const double t = median_seconds(repeats, [&] { (void)cell_qualities(sorted, moved, o); });
            std::printf("%d thread%s, cells in Morton order: cell_qualities %.1f ms (%.1f ns/cell)\n", threads,
                        threads > 1 ? "s" : "", 1e3 * t, 1e9 * t / static_cast<double>(sorted.cells.size()));
        }
    }
    for (int threads : {1, 2}) {
        set_num_threads(threads);
        OriginalCells original;
        std::vector<std::int8_t> own, orientation;
        std::vector<double> q;
        QualitySummary s;
        FrameCells cells;
        const double t_own = median_seconds(repeats, [&] { own = cell_orientations(mesh); });
        const double t_dominant = median_seconds(repeats, [&] { orientation = dominant_orientations(mesh, own); });
        const double t_quality = median_seconds(repeats, [&] { q = cell_qualities(mesh, moved, orientation); });
        const double t_summary = median_seconds(repeats, [&] { s = summarize_quality(q); });
        const double t_original = median_seconds(repeats, [&] { original = measure_original(mesh); });
        const double t_frame = median_seconds(repeats, [&] { cells = measure_frame(mesh, moved, original, fixed); });
        const double t_ratio_summary = median_seconds(repeats, [&] { (void)summarize_ratios(cells.quality, original.quality); });
        std::printf("%d thread%s: cell_orientations %.1f ms, dominant %.1f ms, cell_qualities %.1f ms (%.1f ns/cell), "
                    "summarize_quality %.1f ms, summarize_ratios %.1f ms\n",
                    threads, threads > 1 ? "s" : "", 1e3 * t_own, 1e3 * t_dominant, 1e3 * t_quality,
                    1e9 * t_quality / static_cast<double>(mesh.cells.size()), 1e3 * t_summary, 1e3 * t_ratio_summary);
        std::printf("   measure_original %.1f ms, measure_frame %.1f ms (min %.6f, mean %.6f)\n", 1e3 * t_original,
                    1e3 * t_frame, s.min, s.mean);
        // Over the layout (quality_layout.hpp), what measure_original builds and measure_frame uses.
        QualityLayout layout;
        const double t_layout = median_seconds(repeats, [&] { layout = make_quality_layout(mesh); });
        const double t_own_layout = median_seconds(repeats, [&] { (void)cell_orientations(layout, mesh); });
        std::vector<double> q_layout;
        const double t_quality_layout =
            median_seconds(repeats, [&] { q_layout = cell_qualities(layout, mesh, moved, orientation); });
        std::printf("   layout: make_quality_layout %.1f ms, cell_orientations %.1f ms, cell_qualities %.1f ms "
                    "(%.1f ns/cell; %s)\n",
                    1e3 * t_layout, 1e3 * t_own_layout, 1e3 * t_quality_layout,
                    1e9 * t_quality_layout / static_cast<double>(mesh.cells.size()),
                    q_layout == q ? "the same values" : "DIFFERENT VALUES");
    }
    return 0;
}
