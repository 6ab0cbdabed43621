#pragma once
// dgwarp bench --robustness: every method on the random scenes of a range of
// seeds, against the laplacian reference (bench/robustness.hpp, docs/ROBUSTNESS.md).
#include <string>

#include "dgwarp/bench/robustness.hpp"

namespace dgwarp::cli {

struct RobustnessArgs {
    RobustnessCampaign campaign;
    bool quiet = false;
    std::string markdown, json, cache, pictures;
    int mesh_timeout = 600;  // seconds per Gmsh run
};

/// The outputs of a bench run, checked before its work (the extensions, that
/// the files can be written, the folders made); "" skips one.
void check_bench_outputs(const std::string& markdown, const std::string& json, const std::string& pictures,
                         const std::string& cache);

/// "A-B" or "A" into the campaign's first and last seeds; "" when fine, else why not.
std::string parse_seed_range(const std::string& text, RobustnessCampaign& campaign);

/// Runs the campaign: prints a line per scene and the summary per method;
/// writes the Markdown and JSON reports when asked.
void run_robustness(const RobustnessArgs& args);

}  // namespace dgwarp::cli
