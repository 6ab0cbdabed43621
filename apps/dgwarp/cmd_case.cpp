// dgwarp case NAME -o FILE: write one of the paper's test meshes.
#include <iostream>
#include <memory>

#include "commands.hpp"
#include "dgwarp/cases/paper_cases.hpp"
#include "dgwarp/io/mesh_io.hpp"
#include "flag_values.hpp"
#include "output_files.hpp"

namespace dgwarp::cli {

namespace {

struct CaseArgs {
    std::string name;
    std::string output;
    int size = 0;
    bool quiet = false;
};

void run_case(const CaseArgs& a) {
    const int sizes = case_size_count(a.name);  // the name is checked by the option
    if (a.size < 0 || a.size >= sizes)
        throw CLI::ValidationError("--size", "case '" + a.name + "' has " +
                                                 (sizes == 1 ? std::string("size 0 only")
                                                             : "sizes 0 to " + std::to_string(sizes - 1)) +
                                                 ", got " + std::to_string(a.size));
    require_mesh_extension("--output", a.output);
    check_output_file(a.output, {});
    const Mesh mesh = make_case(a.name, a.size);
    write_mesh(a.output, mesh);
    if (a.quiet) return;
    std::cout << "wrote " << a.output << ": " << a.name << ", " << mesh.num_points() << " nodes, " << mesh.cells.size()
              << " cells; motions:";
    for (const CaseMotion& m : case_motions(a.name, mesh)) std::cout << " " << m.name;
    std::cout << "\n";
}

}  // namespace

void add_case_command(CLI::App& app) {
    auto args = std::make_shared<CaseArgs>();
    CLI::App* cmd = app.add_subcommand("case", "Write one of the paper's test meshes (deterministic)");
    std::string names;
    for (const auto& n : case_names()) names += (names.empty() ? "" : ", ") + n;
    cmd->add_option("name", args->name, "The case: " + names)->required()->check(one_of(case_names(), "a case"));
    cmd->add_option("-o,--output", args->output, "Output mesh (.su2, .msh, .vtu)")->required();
    cmd->add_option("--size", args->size, "Size of squeezed-sphere: 0 (~202k nodes), 1 (~404k), 2 (~826k); of wing-body: 0 (coarse), 1 (the paper's, ~258k)");
    cmd->add_flag("-q,--quiet", args->quiet, "Print nothing but errors");
    cmd->footer("Examples:\n  dgwarp case naca0012 -o naca0012.su2\n  dgwarp case squeezed-sphere --size 1 -o sphere.msh\n"
                "  dgwarp case wing-body --size 1 -o wing-body.su2");
    cmd->callback([args] { run_case(*args); });
}

}  // namespace dgwarp::cli
