// Example 05: every method through the one interface.
//
// prepare(method, ...) and deform(plan, ...) are the same calls for every
// method (METHODS.md): loop over all_methods, time each, measure the result.
// DGM maps nodes through the moved Delaunay graph, which folds over itself
// when the body turns far (the paper's Fig. 10: 90°); deform then throws
// InvalidResultError, whose count() is the number of invalid graph simplices.
// (MethodOptions::dgm.on_invalid = substep makes DGM split the motion instead.)
//
// Run:   build/examples/05_compare_methods [ANGLE_DEG ...]
//        (rect-box, the rectangle turned by each angle in one step; default 30 90)
#include <cstdio>
#include <iostream>
#include <numbers>
#include <string>
#include <vector>

#include "dgwarp/cases/rect_box.hpp"
#include "dgwarp/core/error.hpp"
#include "dgwarp/core/stopwatch.hpp"
#include "dgwarp/methods/method.hpp"
#include "dgwarp/motion/resolve_motion.hpp"
#include "dgwarp/quality/mesh_quality.hpp"

using namespace dgwarp;

/// The rectangle turned by `degrees` about the origin (its centre); the farfield stays.
MotionSpec turn_rectangle(double degrees) {
    NodeMotion turn;
    turn.rotation = {0, 0, degrees * std::numbers::pi / 180};
    MotionSpec spec;
    spec.frames.resize(1);
    spec.frames[0].markers["rectangle"] = RigidMotion{turn};
    return spec;
}

int main(int argc, char** argv) {
    std::vector<double> angles;
    try {
        for (int i = 1; i < argc; ++i) angles.push_back(std::stod(argv[i]));
    } catch (const std::exception&) {
        std::cerr << "usage: " << argv[0] << " [ANGLE_DEG ...]\n";
        return 1;
    }
    if (angles.empty()) angles = {30, 90};
    try {
        const Mesh mesh = make_rect_box();
        // The boundary set (which nodes move) is the same for every angle: one plan per method serves all.
        const BoundarySet boundary = resolve_boundary(mesh, turn_rectangle(angles[0])).boundary;
        const auto orientation = cell_orientations(mesh);
        const QualitySummary original = summarize_quality(cell_qualities(mesh, orientation));
        std::printf("rect-box: %zu points, original quality min %.4f, mean %.4f\n", mesh.num_points(), original.min,
                    original.mean);
        std::printf("%-8s %6s %11s %10s %8s %8s %9s  %s\n", "method", "angle", "prepare ms", "deform ms", "min",
                    "mean", "inverted", "status");

        const MethodOptions options;  // every method's defaults (the paper's parameters for DG-IDW)
        for (Method method : all_methods) {
            const std::string name(method_name(method));
            Clock::time_point start = Clock::now();
            const Plan plan = prepare(method, mesh.dim, mesh.points, mesh.cells, boundary, options);  // cells: laplacian
            const double prepare_ms = 1e3 * seconds_since(start);
            for (double degrees : angles) {
                const MotionSpec spec = turn_rectangle(degrees);
                const BoundaryMotion motion = resolve_frame(mesh, spec, resolve_boundary(mesh, spec), 0).motion;
                Mesh deformed = mesh;
                try {
                    start = Clock::now();
                    deform(plan, mesh.points, motion, deformed.points, options);
                    const double deform_ms = 1e3 * seconds_since(start);
                    const QualitySummary q = summarize_quality(cell_qualities(deformed, orientation));
                    std::printf("%-8s %6g %11.2f %10.2f %8.4f %8.4f %9lld  %s\n", name.c_str(), degrees, prepare_ms,
                                deform_ms, q.min, q.mean, static_cast<long long>(q.inverted),
                                q.inverted > 0 ? "inverted cells" : "ok");
                } catch (const InvalidResultError& e) {  // DGM: the moved graph folded over itself
                    std::printf("%-8s %6g %11.2f %10s %8s %8s %9s  invalid graph (%lld simplices)\n", name.c_str(),
                                degrees, prepare_ms, "-", "-", "-", "-", static_cast<long long>(e.count()));
                }
            }
        }
        return 0;
    } catch (const Error& e) {
        std::cerr << "error: " << e.what() << "\n";
        return 2;
    }
}
