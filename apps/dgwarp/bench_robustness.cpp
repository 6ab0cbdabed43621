// dgwarp bench --robustness: every method on random scenes, against the laplacian reference.
#include "bench_robustness.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>

#include <unistd.h>

#include <nlohmann/json.hpp>

#include "dgwarp/cases/child_process.hpp"
#include "dgwarp/cases/random_scene.hpp"
#include "dgwarp/core/atomic_write.hpp"
#include "dgwarp/core/error.hpp"
#include "dgwarp/core/stopwatch.hpp"
#include "dgwarp/io/mesh_io.hpp"
#include "dgwarp/methods/method.hpp"
#include "dgwarp/motion/resolve_motion.hpp"
#include "dgwarp/picture/mesh_picture.hpp"
#include "dgwarp/quality/mesh_quality.hpp"
#include "flag_values.hpp"
#include "output_files.hpp"

namespace dgwarp::cli {

namespace {

/// One method on one scene.
struct SceneRun {
    Method method;
    bool ran = false;
    std::string status;              // "" when it ran; why not, or its error
    std::int64_t inverted = 0;       // cells valid in the original and inverted now
    double min_quality = 0;
    double near_wall_ratio = 0;      // median over the cells touching a body of quality / original quality
    double prepare_seconds = 0, step_seconds = 0;
    std::int64_t worst_cell = -1;
    DgHarmonicGuardReport guard;     // dg-harmonic: its guard's measure and whether laplacian's result was kept
    bool valid() const { return ran && inverted == 0; }
};

struct SceneResult {
    std::uint64_t seed = 0;
    std::string description;
    std::size_t nodes = 0, cells = 0, boundary_nodes = 0;
    double original_min = 0;
    std::string error;  // the scene could not be made
    std::vector<SceneRun> runs;  // in all_methods order

    const SceneRun& run(Method m) const {
        return *std::find_if(runs.begin(), runs.end(), [&](const SceneRun& r) { return r.method == m; });
    }
};

double median(std::vector<double> v) {
    if (v.empty()) return std::nan("");
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

/// The p-th percentile (0-100), nearest rank.
double percentile(std::vector<double> v, double p) {
    if (v.empty()) return std::nan("");
    std::sort(v.begin(), v.end());
    const auto rank = static_cast<std::size_t>(std::ceil(p / 100 * static_cast<double>(v.size())));
    return v[std::min(v.size() - 1, rank == 0 ? 0 : rank - 1)];
}

std::filesystem::path scene_file(const std::filesystem::path& dir, int dim, std::uint64_t seed) {
    return dir / ("random-" + std::to_string(dim) + "d-" + std::to_string(seed) + ".msh");
}

/// The cells with a node on a body's marker (not the box's walls).
std::vector<std::int64_t> cells_near_bodies(const Mesh& mesh) {
    std::vector<std::uint8_t> on_body(mesh.num_points(), 0);
    for (const Marker& m : mesh.markers)
        if (m.name != "walls")
            for (NodeId n : marker_nodes(m)) on_body[static_cast<std::size_t>(n)] = 1;
    std::vector<std::int64_t> cells;
    for (std::size_t c = 0; c < mesh.cells.size(); ++c)
        for (NodeId n : mesh.cells.nodes_of(c))
            if (on_body[static_cast<std::size_t>(n)]) {
                cells.push_back(static_cast<std::int64_t>(c));
                break;
            }
    return cells;
}

SceneResult run_scene(const RobustnessArgs& a, const RandomScene& scene, const Mesh& mesh) {
    SceneResult s;
    s.seed = scene.seed;
    s.description = describe_scene(scene);
    s.nodes = mesh.num_points();
    s.cells = mesh.cells.size();
    const MotionSpec spec = random_scene_motion(scene);
    const ResolvedBoundary b = resolve_boundary(mesh, spec);
    const BoundaryMotion motion = resolve_frame(mesh, spec, b, 0).motion;
    s.boundary_nodes = b.boundary.nodes.size();
    const auto orientation = cell_orientations(mesh);
    const std::vector<double> original = cell_qualities(mesh, orientation);
    s.original_min = summarize_quality(original).min;
    const std::vector<std::int64_t> near = cells_near_bodies(mesh);
    Mesh deformed = mesh;
    for (Method m : all_methods) {
        SceneRun r;
        r.method = m;
        if (m == Method::rbf && static_cast<double>(s.boundary_nodes) > a.rbf_max_boundary) {
            r.status = "skipped: " + std::to_string(s.boundary_nodes) + " boundary nodes (dense solve)";
            s.runs.push_back(r);
            continue;
        }
        try {
            Stopwatch sw;
            const Plan plan = prepare(m, mesh.dim, mesh.points, mesh.cells, b.boundary);
            r.prepare_seconds = sw.lap();
            r.guard = deform(plan, mesh.points, motion, deformed.points).guard;
            r.step_seconds = sw.lap();
            const std::vector<double> q = cell_qualities(deformed, orientation);
            const QualitySummary summary = summarize_quality(q);
            r.min_quality = summary.min;
            r.worst_cell = summary.worst_cell;
            r.inverted = static_cast<std::int64_t>(newly_inverted_cells(q, original).size());
            const std::vector<double> ratio = quality_ratios(q, original);
            std::vector<double> near_ratio;
            near_ratio.reserve(near.size());
            for (std::int64_t c : near) near_ratio.push_back(ratio[static_cast<std::size_t>(c)]);
            r.near_wall_ratio = median(near_ratio);
            r.ran = true;
        } catch (const Error& e) {
            r.status = std::string("failed: ") + e.what();
        }
        s.runs.push_back(r);
    }
    return s;
}

std::string fixed(double v, int digits = 3) {
    if (std::isnan(v)) return "-";
    char b[32];
    std::snprintf(b, sizeof b, "%.*f", digits, v);
    return b;
}

std::string scene_line(const SceneResult& s) {
    std::ostringstream o;
    o << "seed " << s.seed << ": ";
    if (!s.error.empty()) return o.str() + s.error;
    o << s.nodes << " nodes, original min " << fixed(s.original_min);
    for (const SceneRun& r : s.runs) {
        o << " | " << method_name(r.method) << " ";
        if (!r.ran) o << (r.status.rfind("skipped", 0) == 0 ? "skipped" : "failed");
        else o << fixed(r.min_quality) << (r.inverted ? " (" + std::to_string(r.inverted) + " inverted)" : "");
    }
    return o.str();
}

/// Per method: the campaign's figures.
struct MethodSummary {
    Method method;
    int ran = 0, valid = 0, valid_where_reference_valid = 0, reference_valid = 0;
    double ratio_median = 0, ratio_p5 = 0, ratio_worst = 0;  // min quality / laplacian's, where laplacian is valid
    std::int64_t worst_seed = -1;                            // the seed of ratio_worst (or of a fold)
    double near_wall_median = 0, step_median_ms = 0;
    int redone = 0;  // dg-harmonic: scenes where its guard kept laplacian's result
};

std::vector<MethodSummary> summarize(const std::vector<SceneResult>& scenes) {
    std::vector<MethodSummary> out;
    for (Method m : all_methods) {
        MethodSummary s;
        s.method = m;
        std::vector<double> ratios, near, steps;
        double worst = 1e300;
        for (const SceneResult& scene : scenes) {
            if (!scene.error.empty()) continue;
            const SceneRun& r = scene.run(m);
            const SceneRun& ref = scene.run(Method::laplacian);
            if (!r.ran) continue;
            ++s.ran;
            s.valid += r.valid();
            s.redone += r.guard.kept_redo;
            near.push_back(r.near_wall_ratio);
            steps.push_back(1e3 * r.step_seconds);
            if (!ref.valid() || !(ref.min_quality > 0)) continue;
            ++s.reference_valid;
            s.valid_where_reference_valid += r.valid();
            const double ratio = r.valid() ? r.min_quality / ref.min_quality : 0.0;
            ratios.push_back(ratio);
            if (ratio < worst) {
                worst = ratio;
                s.worst_seed = static_cast<std::int64_t>(scene.seed);
            }
        }
        s.ratio_median = median(ratios);
        s.ratio_p5 = percentile(ratios, 5);
        s.ratio_worst = ratios.empty() ? std::nan("") : worst;
        s.near_wall_median = median(near);
        s.step_median_ms = median(steps);
        out.push_back(s);
    }
    return out;
}

std::string summary_markdown(const std::vector<MethodSummary>& summary) {
    std::ostringstream o;
    o << "| method | ran | valid | valid where laplacian is | min / laplacian's: median | 5th percentile | worst "
         "(seed) | near-wall ratio, median | step ms, median | laplacian's result kept |\n"
         "|---|---|---|---|---|---|---|---|---|---|\n";
    for (const MethodSummary& s : summary)
        o << "| " << method_name(s.method) << " | " << s.ran << " | " << s.valid << " | "
          << s.valid_where_reference_valid << " of " << s.reference_valid << " | " << fixed(s.ratio_median) << " | "
          << fixed(s.ratio_p5) << " | " << fixed(s.ratio_worst)
          << (s.worst_seed >= 0 ? " (" + std::to_string(s.worst_seed) + ")" : "") << " | "
          << fixed(s.near_wall_median) << " | " << fixed(s.step_median_ms, 2) << " | "
          << (s.method == Method::dg_harmonic ? std::to_string(s.redone) : "") << " |\n";
    return o.str();
}

std::string scenes_markdown(const std::vector<SceneResult>& scenes) {
    std::ostringstream o;
    o << "| seed | nodes | original min |";
    for (Method m : all_methods) o << " " << method_name(m) << " |";
    o << " scene |\n|---|---|---|";
    for (std::size_t k = 0; k < std::size(all_methods); ++k) o << "---|";
    o << "---|\n";
    for (const SceneResult& s : scenes) {
        if (!s.error.empty()) {
            o << "| " << s.seed << " | | |";
            for (std::size_t k = 0; k < std::size(all_methods); ++k) o << " |";
            o << " " << s.error << " |\n";
            continue;
        }
        o << "| " << s.seed << " | " << s.nodes << " | " << fixed(s.original_min) << " |";
        for (const SceneRun& r : s.runs) {
            o << " ";
            if (!r.ran) o << (r.status.rfind("skipped", 0) == 0 ? "skipped" : "failed");
            else if (r.inverted) o << "**" << r.inverted << " inv.**";
            else o << fixed(r.min_quality);
            if (r.guard.kept_redo) o << " (L)";
            o << " |";
        }
        o << " " << s.description << " |\n";
    }
    return o.str();
}

nlohmann::json robustness_json(const RobustnessArgs& a, const std::vector<SceneResult>& scenes,
                               const std::vector<MethodSummary>& summary, double seconds) {
    nlohmann::json j;
    j["dim"] = a.dim;
    j["seeds"] = {a.first_seed, a.last_seed};
    j["commit"] = a.commit;
    j["seconds"] = seconds;
    for (const SceneResult& s : scenes) {
        nlohmann::json sj = {{"seed", s.seed}, {"description", s.description}, {"nodes", s.nodes}, {"cells", s.cells},
                             {"boundary_nodes", s.boundary_nodes}, {"original_min", s.original_min}};
        if (!s.error.empty()) sj["error"] = s.error;
        for (const SceneRun& r : s.runs) {
            nlohmann::json rj = {{"method", method_name(r.method)}, {"ran", r.ran}, {"status", r.status}};
            if (r.ran) {
                rj["inverted"] = r.inverted;
                rj["min_quality"] = r.min_quality;
                rj["near_wall_ratio"] = std::isnan(r.near_wall_ratio) ? nlohmann::json() : nlohmann::json(r.near_wall_ratio);
                rj["prepare_seconds"] = r.prepare_seconds;
                rj["step_seconds"] = r.step_seconds;
                if (r.guard.checked)
                    rj["guard"] = {{"one_pass_min_quality", r.guard.one_pass.min_quality},
                                   {"one_pass_inverted", r.guard.one_pass.inverted},
                                   {"redone", r.guard.redone},
                                   {"kept_redo", r.guard.kept_redo},
                                   {"increments", r.guard.increments}};
            }
            sj["methods"].push_back(rj);
        }
        j["scenes"].push_back(sj);
    }
    for (const MethodSummary& s : summary) {
        const auto num = [](double v) { return std::isnan(v) ? nlohmann::json() : nlohmann::json(v); };
        j["summary"].push_back({{"method", method_name(s.method)},
                                {"ran", s.ran},
                                {"valid", s.valid},
                                {"laplacian_valid", s.reference_valid},
                                {"valid_where_laplacian_valid", s.valid_where_reference_valid},
                                {"ratio_median", num(s.ratio_median)},
                                {"ratio_p5", num(s.ratio_p5)},
                                {"ratio_worst", num(s.ratio_worst)},
                                {"worst_seed", s.worst_seed},
                                {"near_wall_median", num(s.near_wall_median)},
                                {"step_median_ms", num(s.step_median_ms)},
                                {"laplacian_kept", s.redone}});
    }
    return j;
}

/// A close-up PNG of the default method's result on scene `seed` around its worst cell (2D only).
std::string write_worst_picture(const RobustnessArgs& a, const std::filesystem::path& cache, std::uint64_t seed) {
    const RandomScene scene = random_scene(a.dim, seed);
    const Mesh mesh = read_mesh(scene_file(cache, a.dim, seed));
    const MotionSpec spec = random_scene_motion(scene);
    const ResolvedBoundary b = resolve_boundary(mesh, spec);
    Mesh deformed = mesh;
    deform(prepare(Method::dg_harmonic, 2, mesh.points, mesh.cells, b.boundary), mesh.points,
           resolve_frame(mesh, spec, b, 0).motion, deformed.points);
    const auto orientation = cell_orientations(mesh);
    const std::vector<double> q = cell_qualities(deformed, orientation);
    const QualitySummary s = summarize_quality(q);
    double cx = 0, cy = 0;
    const auto nodes = deformed.cells.nodes_of(static_cast<std::size_t>(s.worst_cell));
    for (NodeId n : nodes) {
        cx += deformed.points[2 * static_cast<std::size_t>(n)] / static_cast<double>(nodes.size());
        cy += deformed.points[2 * static_cast<std::size_t>(n) + 1] / static_cast<double>(nodes.size());
    }
    PictureOptions o;
    o.width = 800;
    o.height = 600;
    o.window = std::array<double, 4>{cx - 0.4, cx + 0.4, cy - 0.3, cy + 0.3};
    o.title = "dg-harmonic, random scene " + std::to_string(a.dim) + "D seed " + std::to_string(seed) +
              ": around its worst cell";
    std::filesystem::create_directories(a.pictures);
    const auto png = std::filesystem::path(a.pictures) / ("robustness-" + std::to_string(a.dim) + "d-" +
                                                          std::to_string(seed) + "-dg-harmonic.png");
    write_mesh_picture(png, deformed, q, o);
    return png.string();
}

}  // namespace

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

std::string parse_seed_range(const std::string& text, RobustnessArgs& args) {
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
    args.first_seed = first;
    args.last_seed = last;
    return "";
}

void run_robustness(const RobustnessArgs& a) {
    check_bench_outputs(a.markdown, a.json, a.pictures, a.cache);
    Stopwatch total;
    use_threads(1);  // one-thread step times; and Gmsh runs in forked children, before any thread starts
    const std::filesystem::path cache =
        a.cache.empty() ? std::filesystem::temp_directory_path() / ("dgwarp-robustness-" + std::to_string(::getpid()))
                        : std::filesystem::path(a.cache);
    std::filesystem::create_directories(cache);
    std::vector<SceneResult> scenes;
    // The meshes first (child processes: a Gmsh crash or hang costs one scene).
    std::vector<std::string> mesh_errors;
    for (int seed = a.first_seed; seed <= a.last_seed; ++seed) {
        const auto file = scene_file(cache, a.dim, static_cast<std::uint64_t>(seed));
        std::string error;
        if (!std::filesystem::exists(file)) try {
                if (!a.quiet) std::cerr << "robustness: meshing " << a.dim << "D seed " << seed << " ..." << std::endl;
                const RandomScene scene = random_scene(a.dim, static_cast<std::uint64_t>(seed));
                run_in_child_process([&] { write_mesh(file, make_random_scene_mesh(scene)); }, a.mesh_timeout,
                                     "Gmsh's mesh of random scene " + std::to_string(seed));
            } catch (const Error& e) {
                error = e.what();
            }
        mesh_errors.push_back(error);
    }
    for (int seed = a.first_seed; seed <= a.last_seed; ++seed) {
        const RandomScene scene = random_scene(a.dim, static_cast<std::uint64_t>(seed));
        SceneResult s;
        s.seed = static_cast<std::uint64_t>(seed);
        s.error = mesh_errors[static_cast<std::size_t>(seed - a.first_seed)];
        if (s.error.empty()) {
            const Mesh mesh = read_mesh(scene_file(cache, a.dim, s.seed));
            s = run_scene(a, scene, mesh);
        } else {
            s.description = describe_scene(scene);
        }
        if (!a.quiet) std::cout << scene_line(s) << std::endl;
        scenes.push_back(std::move(s));
    }
    const std::vector<MethodSummary> summary = summarize(scenes);
    std::cout << "\n" << summary_markdown(summary);
    std::vector<std::uint64_t> reference_invalid;
    for (const SceneResult& s : scenes)
        if (s.error.empty() && !s.run(Method::laplacian).valid()) reference_invalid.push_back(s.seed);
    std::cout << "scenes where laplacian is not valid:";
    for (auto seed : reference_invalid) std::cout << " " << seed;
    std::cout << (reference_invalid.empty() ? " none" : "") << "\n";
    std::string picture;
    const MethodSummary& d = summary[static_cast<std::size_t>(Method::dg_harmonic)];
    if (!a.pictures.empty() && a.dim == 2 && d.worst_seed >= 0)
        picture = write_worst_picture(a, cache, static_cast<std::uint64_t>(d.worst_seed));
    const double seconds = total.lap();
    if (!a.markdown.empty())
        write_file_atomically(a.markdown, [&](std::ostream& out) {
            out << "# Robustness: random scenes, " << a.dim << "D, seeds " << a.first_seed << "-" << a.last_seed
                << "\n\nMade by `dgwarp bench --robustness --dim " << a.dim << " --seeds " << a.first_seed << "-"
                << a.last_seed << "`" << (a.commit.empty() ? "" : " at commit " + a.commit) << " in "
                << fixed(seconds / 60, 1)
                << " min (docs/ROBUSTNESS.md says what the scenes and the columns are). Each method's step from the "
                   "original mesh, one thread, without any repair (dg-harmonic's last resort is the CLI's).\n\n"
                << summary_markdown(summary) << "\nScenes where laplacian is not valid:";
            for (auto seed : reference_invalid) out << " " << seed;
            out << (reference_invalid.empty() ? " none" : "") << ".\n\n";
            if (!picture.empty())
                out << "The default's worst scene, around its worst cell:\n\n![" << picture << "]("
                    << std::filesystem::relative(picture, std::filesystem::absolute(a.markdown).parent_path()).string()
                    << ")\n\n";
            out << "Per scene: the min quality of each method (**N inv.**: N cells inverted).\n\n"
                << scenes_markdown(scenes);
        });
    if (!a.json.empty())
        write_file_atomically(a.json, [&](std::ostream& out) {
            out << robustness_json(a, scenes, summary, seconds).dump(1) << "\n";
        });
    if (a.cache.empty()) std::filesystem::remove_all(cache);
}

}  // namespace dgwarp::cli
