// Example 04: prepare once, save the plan, reuse it in a later run.
//
// A DG-IDW plan is plain arrays; save_dg_idw_plan writes them to a binary file
// with a checksum and a fingerprint of the mesh and boundary set. Loading it
// with the mesh's points and boundary checks it was made for them, so a plan
// is never applied to another mesh. The loaded plan deforms bit for bit as the
// freshly built one.
//
// Run:   build/examples/04_save_and_reuse_plan     (writes rect_box.plan in the current folder)
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "dgwarp/cases/rect_box.hpp"
#include "dgwarp/core/error.hpp"
#include "dgwarp/core/stopwatch.hpp"
#include "dgwarp/plan/plan_file.hpp"
#include "dgwarp/methods/dg_idw.hpp"
#include "dgwarp/motion/resolve_motion.hpp"

using namespace dgwarp;

int main() {
    try {
        const Mesh mesh = make_rect_box();
        // The rectangle moves up by 1 and turns by 0.3 rad about the origin; the farfield stays.
        const NodeMotion lift_and_turn{{0, 1, 0}, {0, 0, 0.3}, {0, 0, 0}};  // t, w (radians), c
        MotionSpec spec;
        spec.frames.resize(1);
        spec.frames[0].markers["rectangle"] = RigidMotion{lift_and_turn};
        const ResolvedBoundary resolved = resolve_boundary(mesh, spec);
        const BoundarySet& boundary = resolved.boundary;
        const BoundaryMotion motion = resolve_frame(mesh, spec, resolved, 0).motion;

        // First run: build and save.
        Clock::time_point start = Clock::now();
        const DgIdwPlan built = prepare_dg_idw(mesh.dim, mesh.points, boundary);
        const double prepare_seconds = seconds_since(start);
        save_dg_idw_plan("rect_box.plan", built);
        std::printf("prepared in %.2f ms, saved rect_box.plan (%ju bytes)\n", 1e3 * prepare_seconds,
                    static_cast<std::uintmax_t>(std::filesystem::file_size("rect_box.plan")));

        // Later run: load, checked against this mesh's points and boundary set.
        start = Clock::now();
        const DgIdwPlan loaded = load_dg_idw_plan("rect_box.plan", mesh.points, boundary);
        std::printf("loaded in %.2f ms\n", 1e3 * seconds_since(start));

        // The same step with both plans.
        std::vector<double> a(mesh.points.size()), b(mesh.points.size());
        deform_dg_idw(built, mesh.points, motion, a);
        deform_dg_idw(loaded, mesh.points, motion, b);
        std::printf("bit-identical: %s\n", a == b ? "yes" : "no");

        // A plan loaded for other points (here: the mesh shifted by 1e-9) is refused.
        std::vector<double> other = mesh.points;
        other[0] += 1e-9;
        try {
            load_dg_idw_plan("rect_box.plan", other, boundary);
            std::printf("other mesh: accepted (wrong!)\n");
            return 1;
        } catch (const MeshError& e) {
            std::printf("other mesh: refused (%s)\n", e.what());
        }
        return a == b ? 0 : 1;
    } catch (const Error& e) {  // IoError, ParseError (a damaged file), MeshError
        std::cerr << "error: " << e.what() << "\n";
        return 2;
    }
}
