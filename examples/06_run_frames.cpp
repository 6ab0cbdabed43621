// Example 06: a whole deformation run through the library's run layer, as
// `dgwarp deform` runs it: every frame stepped from the original mesh, the
// method's repair, each frame's quality and warnings (codes and data), and
// the frames handed to the caller, who writes them.
//
// Run:   build/examples/06_run_frames                  (rect-box, the rectangle pitching ±20° in 8 frames)
//        build/examples/06_run_frames MESH MOTION.json [METHOD]
// Writes frame_NNNN.vtu in the current folder; exit code 3 when a frame has inverted cells.
#include <cstdio>
#include <iostream>
#include <numbers>
#include <string>

#include "dgwarp/cases/rect_box.hpp"
#include "dgwarp/core/error.hpp"
#include "dgwarp/io/mesh_io.hpp"
#include "dgwarp/io/motion_file.hpp"
#include "dgwarp/run/run_deformation.hpp"

using namespace dgwarp;

/// The rectangle pitching ±20° about the origin, 8 frames of one period.
MotionSpec pitching_rectangle() {
    PeriodicMotion pitch;
    pitch.pitch = Pitch{};
    pitch.pitch->amplitude = 20 * std::numbers::pi / 180;
    pitch.pitch->frequency = 1;
    MotionSpec spec;
    spec.frames.resize(1);
    spec.frames[0].markers["rectangle"] = pitch;
    spec.time = TimeSteps{0.125, 8};  // time step, steps
    return spec;
}

int main(int argc, char** argv) {
    if (argc != 1 && argc != 3 && argc != 4) {
        std::cerr << "usage: " << argv[0] << " [MESH MOTION.json [METHOD]]\n";
        return 1;
    }
    try {
        const Mesh mesh = argc >= 3 ? read_mesh(argv[1]) : make_rect_box();
        const MotionSpec spec = argc >= 3 ? read_motion_file(argv[2]) : pitching_rectangle();
        const auto method = method_from_name(argc == 4 ? argv[3] : "dg-harmonic");
        if (!method) throw Error(std::string("no method called ") + argv[3]);

        // Once: the boundary (which nodes move), the original cells every frame is judged against, the plan.
        const Deformation d = prepare_deformation(mesh, spec, *method);
        for (const Warning& w : d.boundary.warnings) std::cerr << "warning: " << w.text << "\n";
        std::printf("prepare %.2f ms (%s)\n", 1e3 * d.prepare_seconds, std::string(method_name(*method)).c_str());

        // Every frame: the run layer steps, repairs and measures; we print and write.
        RunCallbacks on;
        on.frame_done = [&](const FrameView& f) {
            const FrameReport& r = f.report;
            std::printf("frame %2zu  t=%.3f  step %6.3f ms  min quality %.4f  inverted %lld%s\n", f.frame, f.time,
                        1e3 * r.step_seconds, r.quality.min, static_cast<long long>(r.inverted_by_motion),
                        r.last_resort ? "  (repaired by the last resort)" : "");
            for (const Warning& w : r.warnings)
                std::printf("  warning %s: %s\n", std::string(warning_code_name(w.code)).c_str(), w.text.c_str());
            if (!r.valid()) return false;  // nothing written for an invalid frame
            Mesh moved = mesh;
            moved.points.assign(f.points.begin(), f.points.end());
            char name[64];
            std::snprintf(name, sizeof name, "frame_%04zu.vtu", f.frame);
            write_mesh(name, moved,
                       MeshFields{{},
                                  {{"quality", 1, f.cells.quality},
                                   {"quality_ratio", 1, quality_ratios(f.cells.quality, d.original.quality)}}});
            return true;
        };
        const RunReport run = run_frames(RunContext::of(mesh, spec, d), {}, on);
        std::printf("frames %zu, valid: %s\n", run.frames.size(), run.valid() ? "yes" : "no");
        return run.valid() ? 0 : 3;
    } catch (const Error& e) {
        std::cerr << "error: " << e.what() << "\n";
        return 2;
    }
}
