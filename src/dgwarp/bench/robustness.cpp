#include "dgwarp/bench/robustness.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "dgwarp/bench/statistics.hpp"
#include "dgwarp/cases/child_process.hpp"
#include "dgwarp/core/error.hpp"
#include "dgwarp/core/stopwatch.hpp"
#include "dgwarp/io/mesh_io.hpp"
#include "dgwarp/motion/resolve_motion.hpp"
#include "dgwarp/picture/mesh_picture.hpp"
#include "dgwarp/quality/mesh_quality.hpp"

namespace dgwarp {

const SceneRun& SceneResult::run(Method m) const {
    return *std::find_if(runs.begin(), runs.end(), [&](const SceneRun& r) { return r.method == m; });
}

std::filesystem::path random_scene_file(const std::filesystem::path& cache, int dim, std::uint64_t seed) {
    return cache / ("random-" + std::to_string(dim) + "d-" + std::to_string(seed) + ".msh");
}

std::vector<std::string> mesh_random_scenes(const RobustnessCampaign& c, const std::filesystem::path& cache,
                                            int timeout, const std::function<void(int seed)>& meshing) {
    std::filesystem::create_directories(cache);
    std::vector<std::string> errors;
    for (int seed = c.first_seed; seed <= c.last_seed; ++seed) {
        const auto file = random_scene_file(cache, c.dim, static_cast<std::uint64_t>(seed));
        std::string error;
        if (!std::filesystem::exists(file)) try {
                if (meshing) meshing(seed);
                const RandomScene scene = random_scene(c.dim, static_cast<std::uint64_t>(seed));
                run_in_child_process([&] { write_mesh(file, make_random_scene_mesh(scene)); }, timeout,
                                     "Gmsh's mesh of random scene " + std::to_string(seed));
            } catch (const Error& e) {
                error = e.what();
            }
        errors.push_back(error);
    }
    return errors;
}

namespace {

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

/// `v` with `digits` decimals; "-" for NaN.
std::string fixed(double v, int digits = 3) {
    if (std::isnan(v)) return "-";
    char b[32];
    std::snprintf(b, sizeof b, "%.*f", digits, v);
    return b;
}

/// "skipped" or "failed": why a method did not run, in a word.
const char* not_run_word(const SceneRun& r) { return r.status.rfind("skipped", 0) == 0 ? "skipped" : "failed"; }

}  // namespace

SceneResult run_scene(const RandomScene& scene, const Mesh& mesh, double rbf_max_boundary) {
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
        if (m == Method::rbf && static_cast<double>(s.boundary_nodes) > rbf_max_boundary) {
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

std::string scene_line(const SceneResult& s) {
    std::ostringstream o;
    o << "seed " << s.seed << ": ";
    if (!s.error.empty()) return o.str() + s.error;
    o << s.nodes << " nodes, original min " << fixed(s.original_min);
    for (const SceneRun& r : s.runs) {
        o << " | " << method_name(r.method) << " ";
        if (!r.ran) o << not_run_word(r);
        else o << fixed(r.min_quality) << (r.inverted ? " (" + std::to_string(r.inverted) + " inverted)" : "");
    }
    return o.str();
}

std::vector<MethodSummary> summarize_scenes(const std::vector<SceneResult>& scenes) {
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

std::vector<std::uint64_t> reference_invalid_seeds(const std::vector<SceneResult>& scenes) {
    std::vector<std::uint64_t> seeds;
    for (const SceneResult& s : scenes)
        if (s.error.empty() && !s.run(Method::laplacian).valid()) seeds.push_back(s.seed);
    return seeds;
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

namespace {

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
            if (!r.ran) o << not_run_word(r);
            else if (r.inverted) o << "**" << r.inverted << " inv.**";
            else o << fixed(r.min_quality);
            if (r.guard.kept_redo) o << " (L)";
            o << " |";
        }
        o << " " << s.description << " |\n";
    }
    return o.str();
}

}  // namespace

std::string robustness_markdown(const RobustnessCampaign& c, const std::vector<SceneResult>& scenes,
                                const std::vector<MethodSummary>& summary, const std::string& picture, double seconds) {
    std::ostringstream out;
    out << "# Robustness: random scenes, " << c.dim << "D, seeds " << c.first_seed << "-" << c.last_seed
        << "\n\nMade by `dgwarp bench --robustness --dim " << c.dim << " --seeds " << c.first_seed << "-"
        << c.last_seed << "`" << (c.commit.empty() ? "" : " at commit " + c.commit) << " in " << fixed(seconds / 60, 1)
        << " min (docs/ROBUSTNESS.md says what the scenes and the columns are). Each method's step from the "
           "original mesh, one thread, without any repair (dg-harmonic's last resort is the CLI's).\n\n"
        << summary_markdown(summary) << "\nScenes where laplacian is not valid:";
    const std::vector<std::uint64_t> reference_invalid = reference_invalid_seeds(scenes);
    for (auto seed : reference_invalid) out << " " << seed;
    out << (reference_invalid.empty() ? " none" : "") << ".\n\n";
    if (!picture.empty())
        out << "The default's worst scene, around its worst cell:\n\n![" << picture << "](" << picture << ")\n\n";
    out << "Per scene: the min quality of each method (**N inv.**: N cells inverted).\n\n" << scenes_markdown(scenes);
    return out.str();
}

nlohmann::json robustness_json(const RobustnessCampaign& c, const std::vector<SceneResult>& scenes,
                               const std::vector<MethodSummary>& summary, double seconds) {
    nlohmann::json j;
    j["dim"] = c.dim;
    j["seeds"] = {c.first_seed, c.last_seed};
    j["commit"] = c.commit;
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


std::filesystem::path write_worst_scene_picture(const std::filesystem::path& cache, std::uint64_t seed,
                                                const std::filesystem::path& folder) {
    const int dim = 2;
    const RandomScene scene = random_scene(dim, seed);
    const Mesh mesh = read_mesh(random_scene_file(cache, dim, seed));
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
    o.title = "dg-harmonic, random scene " + std::to_string(dim) + "D seed " + std::to_string(seed) +
              ": around its worst cell";
    std::filesystem::create_directories(folder);
    const auto png = folder / ("robustness-" + std::to_string(dim) + "d-" + std::to_string(seed) + "-dg-harmonic.png");
    write_mesh_picture(png, deformed, q, o);
    return png;
}

}  // namespace dgwarp
