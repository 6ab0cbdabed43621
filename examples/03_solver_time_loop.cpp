// Example 03: what a flow solver does every time step, without files.
//
// The solver owns plain arrays: the original node coordinates (num_points ×
// dim, row-major), the ids of its wall and farfield nodes. It prepares a plan
// once, then every time step computes the motion of each boundary node (here
// a pitching and plunging body), and dgwarp writes the new coordinates of
// every node into the solver's own array.
//
// Run:   build/examples/03_solver_time_loop [STEPS [EVERY]]
//   STEPS  time steps over one period of the motion (default 40)
//   EVERY  when > 0, write every EVERY-th frame as pitch_plunge_NNNN.vtu (default 0)
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <iostream>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "dgwarp/cases/rect_box.hpp"
#include "dgwarp/core/error.hpp"
#include "dgwarp/core/stopwatch.hpp"
#include "dgwarp/io/mesh_io.hpp"
#include "dgwarp/methods/method.hpp"
#include "dgwarp/quality/mesh_quality.hpp"

using namespace dgwarp;

/// The boundary set of a solver's node lists: every wall and farfield node id,
/// sorted (BoundarySet order is ascending node id), the wall ones moving.
BoundarySet boundary_set(const std::vector<NodeId>& wall, const std::vector<NodeId>& farfield) {
    std::vector<std::pair<NodeId, std::uint8_t>> all;
    for (NodeId n : wall) all.push_back({n, 1});
    for (NodeId n : farfield) all.push_back({n, 0});
    std::sort(all.begin(), all.end());
    BoundarySet b;
    for (const auto& [node, moving] : all) {
        b.nodes.push_back(node);
        b.moving.push_back(moving);
    }
    return b;
}

int main(int argc, char** argv) {
    int steps = 40, every = 0;
    try {
        if (argc > 1) steps = std::stoi(argv[1]);
        if (argc > 2) every = std::stoi(argv[2]);
    } catch (const std::exception&) {
        steps = 0;
    }
    if (argc > 3 || steps < 1 || every < 0) {
        std::cerr << "usage: " << argv[0] << " [STEPS >= 1 [EVERY >= 0]]\n";
        return 1;
    }
    try {
        // Stand-in for the solver's grid: the rect-box's arrays. From here on
        // only `x0`, `wall` and `farfield` are used (the Mesh only to check
        // quality and to write frames).
        const Mesh grid = make_rect_box();
        const int dim = grid.dim;
        const std::vector<double> x0 = grid.points;  // original coordinates, never changed
        const BoundarySet boundary = boundary_set(marker_nodes(find_marker(grid, "rectangle")),
                                                  marker_nodes(find_marker(grid, "farfield")));

        Clock::time_point start = Clock::now();
        const Plan plan = prepare(Method::dg_idw, dim, x0, boundary);
        std::printf("prepare %.2f ms (%zu boundary nodes, %zu points)\n", 1e3 * seconds_since(start),
                    boundary.nodes.size(), x0.size() / dim);

        // The body pitches ±10° about its centre and plunges ±1 in y a quarter
        // period ahead (cos); one period of 1 s in `steps` steps.
        const double pitch = 10 * std::numbers::pi / 180, plunge = 1.0, frequency = 1.0, dt = 1.0 / steps;
        std::vector<double> x(x0.size());     // the solver's coordinates, updated every step
        BoundaryMotion motion(boundary.nodes.size());  // one NodeMotion per boundary node, zero = static
        const auto orientation = cell_orientations(grid);
        Mesh frame = grid;  // for the quality check and the written frames only
        double total = 0, slowest = 0, worst_quality = 1;
        std::int64_t inverted = 0;
        for (int n = 0; n < steps; ++n) {
            const double t = n * dt, phase = 2 * std::numbers::pi * frequency * t;
            // Static nodes keep the zero motion. Every node may get its own (a flexible
            // wall); this body is rigid: t = plunge, w = pitch angle about z (2D), c = pitch axis.
            for (std::size_t b = 0; b < boundary.nodes.size(); ++b)
                if (boundary.moving[b])
                    motion[b] = {{0, plunge * std::cos(phase), 0}, {0, 0, pitch * std::sin(phase)}, {0, 0, 0}};
            start = Clock::now();
            deform(plan, x0, motion, x);  // every node of x, measured from x0
            const double seconds = seconds_since(start);
            total += seconds;
            slowest = std::max(slowest, seconds);

            frame.points = x;
            const QualitySummary q = summarize_quality(cell_qualities(frame, orientation));
            worst_quality = std::min(worst_quality, q.min);
            inverted = std::max(inverted, q.inverted);
            std::printf("step %3d  t=%.3f  deform %6.3f ms  min quality %.4f\n", n, t, 1e3 * seconds, q.min);
            if (every > 0 && n % every == 0) {
                char name[64];
                std::snprintf(name, sizeof name, "pitch_plunge_%04d.vtu", n);
                write_mesh(name, frame);
            }
        }
        std::printf("steps %d, deform mean %.3f ms, slowest %.3f ms\n", steps, 1e3 * total / steps,
                    1e3 * slowest);
        std::printf("worst min quality %.4f\n", worst_quality);
        std::printf("inverted %lld\n", static_cast<long long>(inverted));
        return inverted > 0 ? 3 : 0;
    } catch (const Error& e) {
        std::cerr << "error: " << e.what() << "\n";
        return 2;
    }
}
