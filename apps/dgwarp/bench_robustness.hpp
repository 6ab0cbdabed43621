#pragma once
// dgwarp bench --robustness: every method on the random scenes of a range of
// seeds (cases/random_scene.hpp), against the laplacian reference
// (docs/ROBUSTNESS.md).
#include <string>

namespace dgwarp::cli {

struct RobustnessArgs {
    int first_seed = 1, last_seed = 20;
    int dim = 2;
    bool quiet = false;
    std::string markdown, json, cache, pictures, commit;
    int mesh_timeout = 600;          // seconds per Gmsh run
    double rbf_max_boundary = 6000;  // RBF: a dense N_b × N_b solve beyond this is skipped
};

/// The outputs of a bench run, checked before its work (the extensions, that
/// the files can be written, the folders made); "" skips one.
void check_bench_outputs(const std::string& markdown, const std::string& json, const std::string& pictures,
                         const std::string& cache);

/// "A-B" or "A" into args.first_seed, args.last_seed; "" when fine, else why not.
std::string parse_seed_range(const std::string& text, RobustnessArgs& args);

/// Runs the campaign: prints a line per scene and the summary per method;
/// writes the Markdown and JSON reports when asked.
void run_robustness(const RobustnessArgs& args);

}  // namespace dgwarp::cli
