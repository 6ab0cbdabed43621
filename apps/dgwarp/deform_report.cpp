// deform_report.hpp: the frames' and methods' reports of `dgwarp deform`.
#include "deform_report.hpp"

#include <iomanip>
#include <iostream>

#include "report.hpp"

namespace dgwarp::cli {

void print_single_frame(const Inputs& in, const JobFrame& f) {
    std::cout << "quality (Knupp shape)   before      after\n" << std::fixed << std::setprecision(6);
    std::cout << "  min               " << std::setw(10) << in.original.summary.min << "  " << std::setw(10)
              << f.quality.min << "  (cell " << f.quality.worst_cell << ")\n";
    std::cout << "  mean              " << std::setw(10) << in.original.summary.mean << "  " << std::setw(10)
              << f.quality.mean << "\n";
    std::cout << "  inverted          " << std::setw(10) << in.original.summary.inverted << "  " << std::setw(10)
              << f.quality.inverted << "\n";
    if (in.original.summary.inverted > 0)
        std::cout << "  inverted by the motion " << f.inverted_by_motion << " (the other "
                  << f.quality.inverted - f.inverted_by_motion << " were already inverted or degenerate in the input)\n";
    if (f.inverted_on_boundary > 0)
        std::cout << "  inverted with every node on the boundary " << f.inverted_on_boundary << " (cells "
                  << cell_list(f.worst_on_boundary) << (f.inverted_on_boundary > 10 ? ", ..." : "")
                  << "): the boundary motion itself folds them\n";
    std::cout << "ratio after/before, per cell: min " << f.ratio.min << " (cell " << f.ratio.worst_cell
              << "), mean " << f.ratio.mean << "\n";
    std::cout.unsetf(std::ios::floatfield);
    std::cout << "time      deform " << milliseconds(f.step_seconds) << ", quality " << milliseconds(f.quality_seconds)
              << (f.output.empty() ? std::string() : ", write " + milliseconds(f.write_seconds)) << "\n";
    if (!f.process_seconds.empty()) {
        std::cout << "processes " << f.process_seconds.size() << ", step on each:";
        for (double s : f.process_seconds) std::cout << " " << milliseconds(s);
        std::cout << (f.own_parts ? " (each process its own processor folder)\n"
                                  : " (deform: with the scatter and gather by rank 0)\n");
    }
    if (const auto& u = f.untangled)
        std::cout << "untangle  " << (f.last_resort ? "(dg-harmonic's last resort) " : "") << "inverted cells "
                  << u->inverted_before << " -> " << u->inverted_after
                  << ", cells at or below the target " << u->below_target_before << " -> " << u->below_target_after
                  << ", " << u->nodes_moved << " volume nodes moved (at most " << u->max_move << "), "
                  << milliseconds(f.repair_seconds) << "\n";
    if (f.step.guard.checked) std::cout << "guard     " << guard_summary(f.step.guard) << "\n";
    if (f.step.substeps > 1 && f.step.invalid_graph_simplices > 0)
        std::cout << "DGM       " << f.step.substeps << " sub-steps (the moved graph had "
                  << f.step.invalid_graph_simplices << " invalid simplices)\n";
    else if (f.step.substeps > 1 && !f.step.guard.checked)
        std::cout << "increments " << f.step.substeps << " (each solved on the mesh the earlier ones moved)\n";
}

void print_frame_line(const JobFrame& f, bool timed) {
    char time[32] = "";
    if (timed) std::snprintf(time, sizeof time, "t=%-10g ", f.time);  // a frames list has no times
    char line[200];
    std::snprintf(line, sizeof line, "frame %4zu  %smin %.6f  mean %.6f  inverted %lld  ratio min %.4f  deform %s",
                  f.frame, time, f.quality.min, f.quality.mean, static_cast<long long>(f.quality.inverted),
                  f.ratio.min, milliseconds(f.step_seconds).c_str());
    std::cout << line << (f.step.guard.kept_redo ? "  (laplacian, " + std::to_string(f.step.substeps) + " increments)" : "")
              << (f.output.empty() ? "" : "  -> " + f.output) << "\n";
}

void print_frame(const Inputs& in, const JobFrame& f, std::size_t frames, WarningPrinter& warnings) {
    for (const Warning& w : f.warnings)  // the motion's name the frame; the step's do not
        warnings.print(w.text, w.code == WarningCode::conflicting_shared_motions ? "frame " + std::to_string(f.frame) + ": "
                                                                                 : std::string());
    if (frames == 1) {
        print_single_frame(in, f);
        if (!f.output.empty()) std::cout << "wrote " << f.output << "\n";
    } else {
        print_frame_line(f, in.spec.time.has_value());
    }
}

}  // namespace dgwarp::cli
