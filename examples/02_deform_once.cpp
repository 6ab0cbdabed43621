// Example 02: one deformation, the whole library path.
//
// mesh -> motion (built in code, or read from a motion file) -> the boundary
// nodes and their motions -> prepare a DG-IDW plan -> deform -> quality before
// and after -> a VTU file with the displacement and the quality per cell, to
// open in ParaView.
//
// Run:   build/examples/02_deform_once          (rect-box, rectangle turned by 30°)
//        build/examples/02_deform_once MESH MOTION.json   (frame 0 of a motion file,
//                                                 docs/MOTION.md, examples/motions/)
// Writes deformed.vtu in the current folder.
#include <cstdio>
#include <iostream>
#include <numbers>

#include "dgwarp/cases/rect_box.hpp"
#include "dgwarp/core/error.hpp"
#include "dgwarp/io/mesh_io.hpp"
#include "dgwarp/io/motion_file.hpp"
#include "dgwarp/methods/method.hpp"
#include "dgwarp/motion/resolve_motion.hpp"
#include "dgwarp/quality/mesh_quality.hpp"

using namespace dgwarp;

/// The motion of example 02 in code: the marker "rectangle" turns by 30°
/// about the origin; markers not named (the farfield) stay fixed. This is the
/// motion file {"markers": {"rectangle": {"rotate": {"angle_deg": 30, "center": [0, 0]}}}}.
MotionSpec rotate_rectangle() {
    NodeMotion turn;                                                   // x -> c + R(w)(x - c) + t
    turn.rotation = rotation_vector(30 * std::numbers::pi / 180, {0, 0, 1});  // w: axis × angle, radians
    turn.center = {0, 0, 0};                                           // c
    MotionFrame frame;
    frame.markers["rectangle"] = RigidMotion{turn};
    MotionSpec spec;
    spec.frames = {frame};  // one frame; spec.default_motion (fixed) covers the other markers
    return spec;
}

int main(int argc, char** argv) {
    if (argc != 1 && argc != 3) {
        std::cerr << "usage: " << argv[0] << " [MESH MOTION.json]\n";
        return 1;
    }
    try {
        const Mesh mesh = argc == 3 ? read_mesh(argv[1]) : make_rect_box();
        const MotionSpec spec = argc == 3 ? read_motion_file(argv[2]) : rotate_rectangle();

        // Which boundary nodes exist and which move (fixed for the life of a
        // plan), then the motion of each boundary node in frame 0.
        const ResolvedBoundary rb = resolve_boundary(mesh, spec);
        const ResolvedFrame frame = resolve_frame(mesh, spec, rb, 0);
        for (const auto& w : rb.warnings) std::cerr << "warning: " << w.text << "\n";
        for (const auto& w : frame.warnings) std::cerr << "warning: " << w.text << "\n";
        std::cout << "boundary " << rb.boundary.nodes.size() << " nodes; moving markers:";
        for (const auto& name : rb.moving_markers) std::cout << " " << name;
        std::cout << "\n";

        // Prepare once (Delaunay graph + weights), then deform into a copy of the points.
        const Plan plan = prepare(Method::dg_idw, mesh.dim, mesh.points, rb.boundary);
        Mesh deformed = mesh;
        deform(plan, mesh.points, frame.motion, deformed.points);

        // Quality: judge both meshes against the original cells' orientation,
        // so a cell turned inside out counts as inverted.
        const auto orientation = cell_orientations(mesh);
        const std::vector<double> before = cell_qualities(mesh, orientation);
        const std::vector<double> after = cell_qualities(deformed, orientation);
        const std::vector<double> ratio = quality_ratios(after, before);
        const QualitySummary qb = summarize_quality(before), qa = summarize_quality(after);
        std::printf("quality      before     after\n");
        std::printf("  min      %8.4f  %8.4f\n", qb.min, qa.min);
        std::printf("  mean     %8.4f  %8.4f\n", qb.mean, qa.mean);
        std::printf("inverted %lld\n", static_cast<long long>(qa.inverted));
        const RatioSummary r = summarize_ratios(ratio);
        std::printf("ratio after/before min %.4f (cell %lld)\n", r.min, static_cast<long long>(r.worst_cell));

        // Point and cell data go with the mesh into formats that hold them (VTU).
        Field displacement{"displacement", 3, std::vector<double>(3 * mesh.num_points(), 0.0)};
        for (std::size_t i = 0; i < mesh.num_points(); ++i)
            for (int d = 0; d < mesh.dim; ++d)
                displacement.values[3 * i + d] = deformed.points[mesh.dim * i + d] - mesh.points[mesh.dim * i + d];
        MeshFields fields;
        fields.point_data = {displacement};
        fields.cell_data = {{"quality", 1, after}, {"quality_ratio", 1, ratio}};
        write_mesh("deformed.vtu", deformed, fields);
        std::cout << "wrote deformed.vtu\n";
        return qa.inverted > 0 ? 3 : 0;
    } catch (const Error& e) {
        std::cerr << "error: " << e.what() << "\n";
        return 2;
    }
}
