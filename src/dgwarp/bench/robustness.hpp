#pragma once
// `dgwarp bench --robustness`: every method on the random scenes of a range of
// seeds (cases/random_scene.hpp), against the laplacian reference
// (docs/ROBUSTNESS.md): the scenes' meshes, each method's step measured, the
// summary per method, and their Markdown and JSON renderings.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "dgwarp/cases/random_scene.hpp"
#include "dgwarp/mesh/mesh.hpp"
#include "dgwarp/methods/method.hpp"

namespace dgwarp {

/// One method on one scene.
struct SceneRun {
    Method method = Method::dg_idw;
    bool ran = false;
    std::string status;              // "" when it ran; why not ("skipped: ..."), or its error ("failed: ...")
    std::int64_t inverted = 0;       // cells valid in the original and inverted now
    double min_quality = 0;
    double near_wall_ratio = 0;      // median over the cells touching a body of quality / original quality
    double prepare_seconds = 0, step_seconds = 0;
    std::int64_t worst_cell = -1;
    DgHarmonicGuardReport guard;     // dg-harmonic: its guard's measure and whether laplacian's result was kept
    bool valid() const { return ran && inverted == 0; }
};

/// Every method on one scene.
struct SceneResult {
    std::uint64_t seed = 0;
    std::string description;
    std::size_t nodes = 0, cells = 0, boundary_nodes = 0;
    double original_min = 0;
    std::string error;           // the scene's mesh could not be made
    std::vector<SceneRun> runs;  // in all_methods order

    const SceneRun& run(Method m) const;
};

/// Per method: the campaign's figures.
struct MethodSummary {
    Method method = Method::dg_idw;
    int ran = 0, valid = 0, valid_where_reference_valid = 0, reference_valid = 0;
    double ratio_median = 0, ratio_p5 = 0, ratio_worst = 0;  // min quality / laplacian's, where laplacian is valid
    std::int64_t worst_seed = -1;                            // the seed of ratio_worst (or of a fold)
    double near_wall_median = 0, step_median_ms = 0;
    int redone = 0;  // dg-harmonic: scenes where its guard kept laplacian's result
};

/// The campaign: its dimension and seeds, and what its report says of itself.
struct RobustnessCampaign {
    int dim = 2;
    int first_seed = 1, last_seed = 20;
    double rbf_max_boundary = 6000;  // RBF: a dense N_b × N_b solve beyond this is skipped
    std::string commit;              // printed in the reports ("" for none)
};

/// The mesh file of scene `seed` in the cache folder `cache`.
std::filesystem::path random_scene_file(const std::filesystem::path& cache, int dim, std::uint64_t seed);

/// Makes the meshes of the campaign's scenes missing in `cache`, each by
/// Gmsh in a child process killed after `timeout` seconds (a Gmsh crash or
/// hang costs one scene); call it before any thread starts (fork).
/// `meshing(seed)` is called before each. Per seed: "" or why its mesh could
/// not be made.
std::vector<std::string> mesh_random_scenes(const RobustnessCampaign& c, const std::filesystem::path& cache,
                                            int timeout, const std::function<void(int seed)>& meshing = {});

/// Every method's step from the original `mesh` of `scene` (one step, no
/// repair), measured against the original cells.
SceneResult run_scene(const RandomScene& scene, const Mesh& mesh, double rbf_max_boundary);

/// Per method, over the scenes that could be meshed; in all_methods order.
std::vector<MethodSummary> summarize_scenes(const std::vector<SceneResult>& scenes);

/// The seeds of the scenes where the reference (laplacian) is not valid.
std::vector<std::uint64_t> reference_invalid_seeds(const std::vector<SceneResult>& scenes);

/// "seed 7: 4120 nodes, original min 0.412 | dg-idw 0.301 | ...", for the terminal.
std::string scene_line(const SceneResult& scene);

/// The summary table (a row per method), as Markdown.
std::string summary_markdown(const std::vector<MethodSummary>& summary);

/// The whole report as Markdown: the summary, the scenes where laplacian is
/// not valid, the default's worst scene (`picture`, a path relative to the
/// report's folder; "" for none), and a row per scene.
std::string robustness_markdown(const RobustnessCampaign& c, const std::vector<SceneResult>& scenes,
                                const std::vector<MethodSummary>& summary, const std::string& picture, double seconds);

/// The whole report as JSON: dim, seeds, commit, seconds, a scene per seed
/// with each method's figures, and the summary per method.
nlohmann::json robustness_json(const RobustnessCampaign& c, const std::vector<SceneResult>& scenes,
                               const std::vector<MethodSummary>& summary, double seconds);

/// Writes a close-up PNG of the default method's result on the 2D scene
/// `seed` (its mesh in `cache`) around its worst cell into `folder`; returns its path.
std::filesystem::path write_worst_scene_picture(const std::filesystem::path& cache, std::uint64_t seed,
                                                const std::filesystem::path& folder);

}  // namespace dgwarp
