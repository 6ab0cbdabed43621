// dgwarp bench --robustness: every method on random scenes, against the laplacian reference.
#include "bench_robustness.hpp"

#include <charconv>
#include <iostream>

#include <unistd.h>

#include "dgwarp/core/atomic_write.hpp"
#include "flag_values.hpp"
#include "dgwarp/core/stopwatch.hpp"
#include "dgwarp/io/mesh_io.hpp"
#include "output_files.hpp"

namespace dgwarp::cli {

void check_bench_outputs(const std::string& markdown, const std::string& json, const std::string& pictures,
                         const std::string& cache) {
    if (!markdown.empty()) {
        require_extension("--markdown", markdown, {".md"}, "Markdown");
        check_output_file(markdown, {});
    }
    if (!json.empty()) {
        require_extension("--json", json, {".json"}, "JSON");
        check_output_file(json, {});
    }
    if (!pictures.empty()) make_output_folder(pictures);
    if (!cache.empty()) make_output_folder(cache);
}

std::string parse_seed_range(const std::string& text, RobustnessCampaign& campaign) {
    const auto dash = text.find('-');
    const auto number = [](std::string_view s, int& v) {
        const auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
        return ec == std::errc() && p == s.data() + s.size() && v >= 0;
    };
    int first = 0, last = 0;
    if (dash == std::string::npos ? !number(text, first)
                                  : !number(std::string_view(text).substr(0, dash), first) ||
                                        !number(std::string_view(text).substr(dash + 1), last))
        return "expected A-B or A (whole numbers >= 0), got '" + text + "'";
    if (dash == std::string::npos) last = first;
    if (last < first) return "the range " + text + " is empty";
    campaign.first_seed = first;
    campaign.last_seed = last;
    return "";
}

void run_robustness(const RobustnessArgs& a) {
    const RobustnessCampaign& c = a.campaign;
    check_bench_outputs(a.markdown, a.json, a.pictures, a.cache);
    Stopwatch total;
    use_threads(1);  // one-thread step times; and Gmsh runs in forked children, before any thread starts
    const std::filesystem::path cache =
        a.cache.empty() ? std::filesystem::temp_directory_path() / ("dgwarp-robustness-" + std::to_string(::getpid()))
                        : std::filesystem::path(a.cache);
    const std::vector<std::string> mesh_errors = mesh_random_scenes(c, cache, a.mesh_timeout, [&](int seed) {
        if (!a.quiet) std::cerr << "robustness: meshing " << c.dim << "D seed " << seed << " ..." << std::endl;
    });
    std::vector<SceneResult> scenes;
    for (int seed = c.first_seed; seed <= c.last_seed; ++seed) {
        const RandomScene scene = random_scene(c.dim, static_cast<std::uint64_t>(seed));
        SceneResult s;
        s.seed = static_cast<std::uint64_t>(seed);
        s.error = mesh_errors[static_cast<std::size_t>(seed - c.first_seed)];
        if (s.error.empty())
            s = run_scene(scene, read_mesh(random_scene_file(cache, c.dim, s.seed)), c.rbf_max_boundary);
        else
            s.description = describe_scene(scene);
        if (!a.quiet) std::cout << scene_line(s) << std::endl;
        scenes.push_back(std::move(s));
    }
    const std::vector<MethodSummary> summary = summarize_scenes(scenes);
    std::cout << "\n" << summary_markdown(summary);
    const std::vector<std::uint64_t> reference_invalid = reference_invalid_seeds(scenes);
    std::cout << "scenes where laplacian is not valid:";
    for (auto seed : reference_invalid) std::cout << " " << seed;
    std::cout << (reference_invalid.empty() ? " none" : "") << "\n";
    std::string picture;
    const MethodSummary& d = summary[static_cast<std::size_t>(Method::dg_harmonic)];
    if (!a.pictures.empty() && c.dim == 2 && d.worst_seed >= 0) {
        const auto png = write_worst_scene_picture(cache, static_cast<std::uint64_t>(d.worst_seed), a.pictures);
        picture = a.markdown.empty()
                      ? png.string()
                      : std::filesystem::relative(png, std::filesystem::absolute(a.markdown).parent_path()).string();
    }
    const double seconds = total.lap();
    if (!a.markdown.empty())
        write_file_atomically(a.markdown, [&](std::ostream& out) {
            out << robustness_markdown(c, scenes, summary, picture, seconds);
        });
    if (!a.json.empty())
        write_file_atomically(a.json, [&](std::ostream& out) {
            out << robustness_json(c, scenes, summary, seconds).dump(1) << "\n";
        });
    if (a.cache.empty()) std::filesystem::remove_all(cache);
}

}  // namespace dgwarp::cli
