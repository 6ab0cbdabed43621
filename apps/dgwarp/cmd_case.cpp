// dgwarp case NAME -o FILE [--motions DIR]: write one of the paper's test meshes, and its motions.
#include <iostream>
#include <memory>

#include "commands.hpp"
#include "dgwarp/cases/paper_cases.hpp"
#include "dgwarp/cases/random_scene.hpp"
#include "dgwarp/core/error.hpp"
#include "dgwarp/io/mesh_io.hpp"
#include "dgwarp/io/motion_file.hpp"
#include "flag_values.hpp"
#include "output_files.hpp"

namespace dgwarp::cli {

namespace {

struct CaseArgs {
    std::string name;
    std::string output;
    std::string motions;  // folder for the motion files; "" = none
    int size = 0;
    bool quiet = false;
    std::int64_t seed = -1;  // random: the scene's seed
    int dim = 2;             // random: 2 or 3
};

/// Writes each motion of the case as DIR/<motion>.json (and its node files).
void write_case_motions(const CaseArgs& a, const std::vector<CaseMotion>& motions) {
    const std::filesystem::path dir = a.motions;
    for (const CaseMotion& m : motions) {
        const std::string comment = "dgwarp case " + a.name + (a.size ? " --size " + std::to_string(a.size) : "") +
                                    (a.name == "random" ? " --seed " + std::to_string(a.seed) + " --dim " +
                                                              std::to_string(a.dim)
                                                        : "") +
                                    ", motion " + m.name + ": " + m.description;
        for (const auto& file : write_motion_file(dir / (m.name + ".json"), m.spec, comment))
            if (!a.quiet) std::cout << "wrote " << file.string() << "\n";
    }
}

void run_case(const CaseArgs& a) {
    const bool random = a.name == "random";
    if (random && a.seed < 0) throw CLI::ValidationError("--seed", "the random case needs --seed N (N >= 0)");
    if (!random && a.seed >= 0) throw CLI::ValidationError("--seed", "is for the random case only");
    if (random && a.size != 0) throw CLI::ValidationError("--size", "the random case has no sizes (--seed, --dim)");
    if (!random && a.dim != 2) throw CLI::ValidationError("--dim", "is for the random case only");
    const int sizes = random ? 1 : case_size_count(a.name);  // the name is checked by the option
    if (a.size < 0 || a.size >= sizes)
        throw CLI::ValidationError("--size", "case '" + a.name + "' has " +
                                                 (sizes == 1 ? std::string("size 0 only")
                                                             : "sizes 0 to " + std::to_string(sizes - 1)) +
                                                 ", got " + std::to_string(a.size));
    if (a.output.empty() && a.motions.empty())
        throw CLI::ValidationError("case", "give -o FILE (the mesh), --motions DIR (its motions), or both");
    if (!a.output.empty()) {
        require_mesh_extension("--output", a.output);
        check_mesh_output(a.output, {});
    }
    if (!a.motions.empty()) make_output_folder(a.motions);  // before the work, with the system's reason
    Mesh mesh;
    std::vector<CaseMotion> motions;
    if (random) {
        const RandomScene scene = random_scene(a.dim, static_cast<std::uint64_t>(a.seed));
        if (!a.quiet) std::cout << describe_scene(scene) << std::endl;
        mesh = make_random_scene_mesh(scene);
        motions.push_back({"move", describe_scene(scene), random_scene_motion(scene)});
    } else {
        mesh = make_case(a.name, a.size);
        motions = case_motions(a.name, mesh);
    }
    if (!a.output.empty()) {
        write_mesh(a.output, mesh);
        if (!a.quiet) {
            std::cout << "wrote " << a.output << ": " << a.name << ", " << mesh.num_points() << " nodes, "
                      << mesh.cells.size() << " cells; motions:";
            for (const CaseMotion& m : motions) std::cout << " " << m.name;
            std::cout << (a.motions.empty() ? " (--motions DIR writes them)" : "") << "\n";
        }
    }
    if (!a.motions.empty()) write_case_motions(a, motions);
}

}  // namespace

void add_case_command(CLI::App& app) {
    auto args = std::make_shared<CaseArgs>();
    CLI::App* cmd = app.add_subcommand("case", "Write one of the paper's test meshes (deterministic)");
    std::string names;
    std::vector<std::string> known = case_names();
    known.push_back("random");
    for (const auto& n : known) names += (names.empty() ? "" : ", ") + n;
    cmd->add_option("name", args->name, "The case: " + names + " (a random scene: --seed, --dim; docs/ROBUSTNESS.md)")
        ->required()
        ->check(one_of(known, "a case"));
    cmd->add_option("-o,--output", args->output, "Output mesh (.su2, .msh, .vtu, .cgns, or an OpenFOAM case folder for a 3D case)");
    cmd->add_option("--motions", args->motions,
                    "Folder to write the case's motions to, one motion file per motion (<motion>.json, with its node "
                    "file for per-node motions; docs/MOTION.md): 'dgwarp deform' with one of them does what "
                    "'dgwarp bench' does for that motion");
    cmd->add_option("--size", args->size, "Size of squeezed-sphere: 0 (~202k nodes), 1 (~408k), 2 (~865k); of wing-body: 0 (coarse), 1 (the paper's, ~258k)");
    cmd->add_option("--seed", args->seed, "random: the scene's seed (the same seed and --dim give the same scene)")
        ->check(whole_number_between(0, 1000000000));
    cmd->add_option("--dim", args->dim, "random: 2 or 3 (default 2)")->check(whole_number_between(2, 3));
    cmd->add_flag("-q,--quiet", args->quiet, "Print nothing but errors");
    cmd->footer("At least one of -o and --motions. The per-node motions (twisted-bar, squeezed-sphere) name the "
                "mesh's nodes:\nuse them with the mesh of the same case and --size.\n\n"
                "Examples:\n  dgwarp case naca0012 -o naca0012.su2 --motions naca0012-motions\n"
                "  dgwarp deform naca0012.su2 -m naca0012-motions/rotate-45.json -o turned.vtu\n"
                "  dgwarp case squeezed-sphere --size 1 -o sphere.msh\n"
                "  dgwarp case wing-body --size 1 -o wing-body.su2\n"
                "  dgwarp case random --seed 17 --dim 2 -o scene.su2 --motions scene-motions");
    cmd->callback([args] { run_case(*args); });
}

}  // namespace dgwarp::cli
