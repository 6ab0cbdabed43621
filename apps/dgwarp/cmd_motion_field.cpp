// dgwarp motion-field MESH -m MOTION -o OUT: the displacement a motion gives
// the boundary nodes, for another solver to apply the same motion (CSV, or
// OpenFOAM's pointDisplacement in a case's time folder; docs/OPENFOAM.md).
#include <algorithm>
#include <iostream>
#include <memory>

#include "commands.hpp"
#include "deform_setup.hpp"
#include "dgwarp/core/atomic_write.hpp"
#include "dgwarp/core/error.hpp"
#include "dgwarp/io/number_text.hpp"
#include "dgwarp/io/openfoam/openfoam.hpp"
#include "dgwarp/job/boundary_displacement.hpp"
#include "output_files.hpp"

namespace dgwarp::cli {

namespace {

struct MotionFieldArgs {
    SetupArgs setup;
    std::string output;
    std::string foam_time = "0";
    int frame = 0;
    bool quiet = false;
};

bool writes_csv(const std::string& output) { return lower_case_extension(output) == ".csv"; }

std::filesystem::path foam_field_file(const MotionFieldArgs& a) {
    return std::filesystem::path(a.output) / a.foam_time / "pointDisplacement";
}

void write_csv(const std::filesystem::path& file, const Mesh& mesh, const BoundarySet& boundary,
               const std::vector<double>& displacement) {
    const auto dim = static_cast<std::size_t>(mesh.dim);
    write_file_atomically(file, [&](std::ostream& out) {
        out << (dim == 3 ? "node,dx,dy,dz\n" : "node,dx,dy\n");
        for (NodeId node : boundary.nodes) {
            out << node;
            for (std::size_t d = 0; d < dim; ++d) {
                out.put(',');
                write_number(out, displacement[static_cast<std::size_t>(node) * dim + d]);
            }
            out.put('\n');
        }
    });
}

void run_motion_field(const MotionFieldArgs& a) {
    const bool csv = writes_csv(a.output);
    if (!csv && !is_openfoam_output(a.output))
        throw CLI::ValidationError("--output", a.output + ": give a .csv file or an OpenFOAM case folder");
    if (!csv && a.foam_time == "constant")
        throw CLI::ValidationError("--foam-time", "a field goes to a time folder (e.g. 0), not constant");
    const std::filesystem::path file = csv ? std::filesystem::path(a.output) : foam_field_file(a);
    ProgressLine progress(!a.quiet);
    const Inputs in = read_motion_inputs(a.setup, progress, [&](const MotionSpec& spec) {
        std::vector<std::filesystem::path> inputs = mesh_input_files(a.setup.mesh);
        inputs.push_back(a.setup.motion);
        for (const auto& f : motion_named_files(spec)) inputs.push_back(f);
        check_nearest_folder_writable(file.parent_path());
        check_output(file, inputs);
        if (static_cast<std::size_t>(a.frame) >= frame_count(spec))
            throw CLI::ValidationError("--frame", "the motion has " + std::to_string(frame_count(spec)) + " frame" +
                                                      (frame_count(spec) == 1 ? "" : "s") +
                                                      ", frames count from 0; got " + std::to_string(a.frame));
    });
    if (!csv && (!in.extras.openfoam || !in.extras.openfoam->processors.empty()))
        throw FormatError(a.setup.mesh + ": a pointDisplacement field lists values in the patches' point order, " +
                          "so MESH must be the OpenFOAM case it is for (convert the mesh first: dgwarp convert " +
                          a.setup.mesh + " CASE/; a decomposed case: reconstructPar first)");
    const BoundaryDisplacement d = boundary_displacement(in, static_cast<std::size_t>(a.frame));
    WarningPrinter warnings(!a.quiet);
    for (const auto& w : in.boundary.warnings) warnings.print(w.text);
    for (const auto& w : d.warnings) warnings.print(w.text);
    const BoundarySet& boundary = d.boundary;
    const std::vector<double>& displacement = d.displacement;
    const Mesh& mesh = output_mesh(in);
    if (csv) {
        write_csv(file, mesh, boundary, displacement);
    } else {
        std::filesystem::create_directories(file.parent_path());
        const std::string text =
            openfoam_point_displacement_text(mesh, displacement, in.extras.openfoam->patches, a.foam_time);
        write_file_atomically(file, [&](std::ostream& out) { out << text; });
    }
    if (a.quiet) return;
    std::cout << "wrote " << file.string() << ": displacement of " << boundary.nodes.size()
              << " boundary nodes (" << moving_count(boundary) << " moving)\nmoving markers:";
    for (const auto& m : in.boundary.moving_markers) std::cout << " " << m;
    std::cout << "\n";
}

}  // namespace

void add_motion_field_command(CLI::App& app) {
    auto args = std::make_shared<MotionFieldArgs>();
    CLI::App* cmd = app.add_subcommand(
        "motion-field", "Write the displacement a motion gives the boundary nodes (CSV, or OpenFOAM's pointDisplacement)");
    add_input_options(cmd, args->setup);
    cmd->add_option("-o,--output", args->output,
                    "FILE.csv (node,dx,dy[,dz] per boundary node, in node order), or an OpenFOAM case folder: "
                    "CASE/<time>/pointDisplacement (MESH must be that case)")
        ->required();
    cmd->add_option("--foam-time", args->foam_time, "The time folder of the pointDisplacement file")
        ->capture_default_str();
    cmd->add_option("--frame", args->frame, "The frame of a time series (0-based)")
        ->capture_default_str()
        ->check(CLI::Validator(
            [](std::string& text) -> std::string {
                // Not CLI11's NonNegativeNumber: its range printed as 0 to 1.8e308, and "1e3" was "Could not convert".
                int value = 0;
                if (!CLI::detail::lexical_cast(text, value) || value < 0)
                    return "expected a frame number, a whole number >= 0 (frames count from 0), got " + text;
                return {};
            },
            "", ""));
    cmd->add_flag("-q,--quiet", args->quiet, "Print nothing but errors");
    cmd->footer(
        "The displacement is the new position minus the old of every boundary node (zero for the fixed ones), "
        "what every method moves the boundary by.\nFor OpenFOAM, every patch gets a fixedValue (constraint "
        "patches keep their type); the moving markers are printed.\n\n"
        "Examples:\n  dgwarp convert wing.su2 case/ && dgwarp motion-field case -m fold.json -o case\n"
        "  dgwarp motion-field wing.su2 -m fold.json -o fold-displacement.csv");
    cmd->callback([args] { run_motion_field(*args); });
}

}  // namespace dgwarp::cli
