// dgwarp convert IN OUT: convert a mesh between formats.
#include <iostream>
#include <memory>

#include "commands.hpp"
#include "flag_values.hpp"
#include "dgwarp/io/mesh_io.hpp"
#include "output_files.hpp"
#include "progress_line.hpp"
#include "report.hpp"

namespace dgwarp::cli {

namespace {

struct ConvertArgs {
    std::string input;
    std::string output;
    int zone = 1;
    int gmsh_version = 41;
    std::string foam_format;  // "", "ascii" or "binary"
    std::vector<std::string> rename_markers;
    bool quiet = false;
};

void run_convert(const ConvertArgs& a) {
    require_mesh_extension("output", a.output);
    if (!a.foam_format.empty() && !writes_openfoam(a.output))
        throw CLI::ValidationError("--foam-format", "is for an OpenFOAM case output (a folder, a name ending in '/')");
    check_mesh_output(a.output, mesh_input_files(a.input));
    ProgressLine progress(!a.quiet);
    MeshExtras extras;
    Mesh mesh = read_mesh(a.input, {a.zone}, progress.reporter("reading " + a.input), extras);
    apply_marker_renames(mesh, a.rename_markers);
    // Names the output cannot hold: made into names it can, and said.
    const std::vector<MarkerRename> made = make_marker_names_writable(mesh, a.output);
    for (const MarkerRename& r : made)
        if (!a.quiet) {
            progress.clear();
            std::cerr << "warning: " << a.output << " cannot hold the marker name '" << r.from << "': it is written as '"
                      << r.to << "' (--rename-marker '" << r.from << "=NEW' names it otherwise)\n";
        }
    // A renamed CGNS input is written whole: a copy of the file would keep its names.
    if (extras.cgns && (!made.empty() || !a.rename_markers.empty())) extras.cgns.reset();
    progress.phase("writing " + a.output);
    WriteOptions options;
    options.gmsh_version = a.gmsh_version;
    if (!a.foam_format.empty()) options.foam_format = a.foam_format == "binary" ? foam::Format::binary : foam::Format::ascii;
    options.extras = &extras;  // SU2 to SU2 keeps the other zones, FFD boxes, periodic data
    check_mesh_writable(a.output, mesh, options);  // names the file in the error
    if (const std::string w = dropped_extras_warning(extras, a.input, a.output); !w.empty() && !a.quiet) {
        progress.clear();
        std::cerr << "warning: " << w << "\n";
    }
    write_mesh(a.output, mesh, {}, options);
    progress.clear();
    if (!a.quiet) std::cout << a.input << " -> " << a.output << ": " << describe_mesh(mesh) << "\n";
}

}  // namespace

void add_convert_command(CLI::App& app) {
    auto args = std::make_shared<ConvertArgs>();
    CLI::App* cmd = app.add_subcommand("convert", "Convert a mesh between formats (chosen by file extension)");
    cmd->add_option("input", args->input, "Input mesh (.su2, .msh, .vtu, .cgns, or an OpenFOAM case or polyMesh folder)")
        ->required();
    cmd->add_option("output", args->output,
                    "Output mesh (.su2, .msh, .vtu, .cgns, or an OpenFOAM case folder: a folder, a name ending in '/' or "
                    "without extension)")
        ->required();
    cmd->add_option("--zone", args->zone, "Zone of a multi-zone SU2 input (1-based)")->check(positive_whole_number());
    cmd->add_option("--gmsh-version", args->gmsh_version, "MSH version to write: 41 (4.1) or 22 (2.2)")
        ->check(CLI::IsMember({41, 22}));
    cmd->add_option("--foam-format", args->foam_format,
                    "OpenFOAM output: ascii or binary (default: the OpenFOAM input's, else ascii)")
        ->check(CLI::IsMember({"ascii", "binary"}));
    add_rename_marker_option(cmd, args->rename_markers);
    cmd->add_flag("-q,--quiet", args->quiet, "Print nothing on success");
    cmd->footer(
        "The output is written to a temporary file and renamed into place, so an existing file is\n"
        "never left half-written. The output may not be the input, nor a read-only file.\n"
        "An OpenFOAM output gets a whole polyMesh in CASE/constant/polyMesh (points, faces, owner,\n"
        "neighbour, boundary; one patch per marker, defaultFaces for boundary faces in none);\n"
        "OpenFOAM meshes are 3D (docs/OPENFOAM.md). A CGNS output of a CGNS input is a copy of the\n"
        "input with the mesh's coordinates; of another format, a whole file (docs/CGNS.md).\n\n"
        "Examples:\n"
        "  dgwarp convert mesh.su2 mesh.msh\n"
        "  dgwarp convert mesh.msh mesh.su2\n"
        "  dgwarp convert mesh.su2 mesh.msh --gmsh-version 22\n"
        "  dgwarp convert multizone.su2 zone2.vtu --zone 2\n"
        "  dgwarp convert cavity/ cavity.su2          (an OpenFOAM case)\n"
        "  dgwarp convert wing.cgns wing.su2\n"
        "  dgwarp convert wing.su2 wing-case/ --foam-format binary\n"
        "  dgwarp convert grid.cgns case/ --rename-marker 'UserDefined 1=wing'");
    cmd->callback([args] { run_convert(*args); });
}

}  // namespace dgwarp::cli
