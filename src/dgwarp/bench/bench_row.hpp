#pragma once
// `dgwarp bench`: every method on one of the paper's cases and motions
// (cases/paper_cases.hpp), measured as the paper measures: one step from the
// original mesh, Knupp's quality, prepare and step seconds. Plain data; the
// renderings are bench_report.hpp's.
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "dgwarp/bench/paper_figures.hpp"
#include "dgwarp/cases/paper_cases.hpp"
#include "dgwarp/core/progress.hpp"
#include "dgwarp/mesh/mesh.hpp"
#include "dgwarp/methods/method.hpp"
#include "dgwarp/quality/mesh_quality.hpp"

namespace dgwarp {

/// What one method did on one case and motion.
struct MethodResult {
    Method method = Method::dg_idw;
    std::string label;          // the method's name, or a variant ("dg-idw L=auto"): no paper figures
    std::string status = "ok";  // "ok", "skipped: why", "failed: why"
    bool ran = false;           // quality and times are set
    double prepare_seconds = 0, step_seconds = 0;
    QualitySummary quality;
};

/// One case, size and motion with every method.
struct BenchRow {
    std::string case_name;
    int size = 0;
    std::string motion, motion_description;
    std::size_t nodes = 0, cells = 0, boundary_nodes = 0, moving_nodes = 0;
    QualitySummary original;
    std::vector<MethodResult> methods;
    std::optional<PaperEntry> paper;
    std::vector<std::string> pictures;  // PNG paths relative to the Markdown file
};

/// The methods a bench run leaves out, as too costly for one run.
struct BenchLimits {
    bool quick = false;                // no 3D RBF or laplacian
    double rbf_max_boundary = 20000;   // RBF: a dense N_b × N_b solve beyond this is skipped
    double idw_max_work = 1e11;        // IDW: N_volume × N_boundary beyond this is skipped
    double laplacian_max_nodes = 3e5;  // laplacian: a sparse factorisation per increment beyond this is skipped
};

/// Why `method` is not run on a mesh of `nodes` nodes (`boundary` on the
/// boundary) in `dim` dimensions, as "skipped: why"; "" to run it.
std::string bench_skip_reason(Method method, const BenchLimits& limits, std::size_t nodes, std::size_t boundary,
                              int dim);

/// What measure_motion tells its caller while it works; each may be empty.
struct BenchObserver {
    /// A ProgressFn for the phase `what` ("bench: rect-box 0 rotate-30 dg-idw: preparing").
    std::function<ProgressFn(const std::string& what)> progress;
    /// A method starts ("bench: rect-box 0 rotate-30 dg-idw"), and has ended.
    std::function<void(const std::string& what)> started;
    std::function<void()> ended;
    /// A paper method's deformed mesh and its cells' quality (for pictures),
    /// the label being the method's name.
    std::function<void(const std::string& label, const Mesh& deformed, std::span<const double> quality)> deformed;
};

/// Every method (and the DG-IDW variants: L=auto, continuous weights, with
/// untangle) on `mesh` of case `name`, size `size`, moved by `motion`: the row
/// of the bench's tables, with the paper's entry when it has one. A method
/// that fails has status "failed: why"; one beyond `limits`, "skipped: why".
BenchRow measure_motion(const std::string& name, int size, const Mesh& mesh, const CaseMotion& motion,
                        const BenchLimits& limits, const BenchObserver& observer = {});

}  // namespace dgwarp
