#pragma once
// What `dgwarp deform` and `dgwarp prepare` share: reading the mesh and the
// motion, classifying the boundary, and building (or loading) a method's plan.
#include <CLI/CLI.hpp>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <nlohmann/json.hpp>
#include <ostream>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "dgwarp/io/mesh_io.hpp"
#include "dgwarp/io/motion_file.hpp"
#include "dgwarp/io/number_text.hpp"
#include "dgwarp/mesh/planar_case.hpp"
#include "dgwarp/mesh/mesh.hpp"
#include "dgwarp/methods/method.hpp"
#include "dgwarp/methods/option_table.hpp"
#include "dgwarp/motion/resolve_motion.hpp"
#include "dgwarp/quality/mesh_quality.hpp"
#include "dgwarp/run/run_deformation.hpp"
#include "mpi_session.hpp"
#include "progress_line.hpp"
#include "warning_printer.hpp"

namespace dgwarp::cli {

/// Every method option's default as text (option_text of MethodOptions{}).
std::map<std::string, std::string, std::less<>> default_option_texts();

struct SetupArgs {
    std::string mesh;
    std::string motion;
    std::string method = "dg-harmonic";  // a method name, or "all" where a command allows it (default: the robust method)
    bool method_given = false;      // --method was on the command line (else a --plan file decides)
    std::set<std::string> given;    // the method options given on the command line ("--length-scale", ...)
    int zone = 1;
    std::string su2_config;  // an SU2 configuration whose MARKER_SYM markers slide
    std::vector<std::string> rename_markers;  // "OLD=NEW", applied to the mesh read
    /// The output the run writes (deform's -o): marker names its format cannot
    /// hold are made into names it can (make_marker_names_writable), in the
    /// mesh and the motion alike, with a warning; "" for none.
    std::string writable_for;
    int threads = 0;
    /// The method options (methods/option_table.hpp) by name without "--",
    /// as text: the library's defaults, or what the command line gave (`given`).
    std::map<std::string, std::string, std::less<>> options = default_option_texts();

    /// The text of method option `name` (a row of the table).
    const std::string& option(std::string_view name) const { return options.find(name)->second; }
};

/// Adds the mesh, --motion and --zone to `cmd` (what read_motion_inputs reads).
void add_input_options(CLI::App* cmd, SetupArgs& args);

/// Adds the input options, --method, --threads and method options to `cmd`.
void add_setup_options(CLI::App* cmd, SetupArgs& args);

/// The methods `args.method` names: one, or all of them for "all" (when allowed).
std::vector<Method> chosen_methods(const SetupArgs& args, bool allow_all);

/// Usage error (CLI::ValidationError) when an option of another method than
/// `method` was given (it would do nothing), unless every method runs.
/// `usable`: the methods the command can run (empty: every one); an option of
/// another is refused without advising --method.
void refuse_other_methods_options(const SetupArgs& args, Method method, const std::vector<Method>& usable = {});

/// The method options from the command line.
MethodOptions method_options(const SetupArgs& args);

/// The mesh, the motion and the boundary, read and checked once.
struct Inputs {
    SetupArgs args;
    /// The mesh deformed: the file's, or the 2D mesh of a 2D case stored as 3D (`planar`).
    Mesh mesh;
    MeshExtras extras;  // what the mesh file holds besides the mesh (SU2: other zones, FFD boxes)
    /// The motion, in `mesh`'s terms: markers that slide by their type added
    /// (`sliding_by_type`); for a 2D case, in its planes (motion/planar_motion.hpp).
    MotionSpec spec;
    std::vector<std::string> sliding_by_type;
    /// The OpenFOAM cyclic patch pairs coupled because of their type (TypedMotion::coupled).
    std::vector<std::pair<std::string, std::string>> coupled_by_type;
    /// A 2D case stored as 3D (an OpenFOAM 2D case): `mesh` is its 2D mesh,
    /// `file_mesh` the mesh read, which the outputs are (lift_points).
    std::optional<PlanarCase> planar;
    Mesh file_mesh;
    /// Empty patches that slide but make no 2D case: why (they slide in 3D).
    std::string not_planar;
    ResolvedBoundary boundary;
    /// The original cells every frame is judged against (run/original_cells.hpp):
    /// a cell flipped in the input counts as inverted before and after.
    OriginalCells original;
    double read_seconds = 0, resolve_seconds = 0, quality_seconds = 0;
};

/// The mesh outputs are written as: the file's (in.file_mesh for a 2D case).
const Mesh& output_mesh(const Inputs& in);

/// Writes output_mesh(in) with `points` (of output_mesh(in)) for its
/// coordinates: the array is swapped into the mesh for the write and back,
/// so that a frame's output costs no copy of the cells nor of the points.
/// `in` and `points` are as they were on return, also when the write throws.
void write_output_mesh(Inputs& in, const std::filesystem::path& path, std::vector<double>& points,
                       const MeshFields& fields, const WriteOptions& options);

/// `points` (of in.mesh) as points of output_mesh(in): themselves, or the 2D
/// case's 3D points (lift_points) in `buffer`.
std::span<const double> output_points(const Inputs& in, std::span<const double> points, std::vector<double>& buffer);
/// The same for an array: `points` itself, or `buffer`.
std::vector<double>& output_points(const Inputs& in, std::vector<double>& points, std::vector<double>& buffer);

/// Reads the motion file, calls `check_outputs` with it when given (so that
/// outputs are checked before the long work: their names may depend on its
/// frames, and none may be a file it names), then reads the mesh and resolves
/// the boundary (every check of resolve_boundary): mesh, spec, boundary, read
/// and resolve seconds.
Inputs read_motion_inputs(const SetupArgs& args, ProgressLine& progress,
                          const std::function<void(const MotionSpec&)>& check_outputs = {});

/// Calls work() (a method's prepare: mostly serial) with the original
/// mesh's orientation and quality measured beside it on a thread of its own
/// (measure_original_beside), then keeps them in `in` (in.original, in.quality_seconds: the
/// measure's own time, which overlaps work's) with warn_already_inverted's
/// warning. work() must not read in.original nor in.boundary.warnings.
void measure_beside(Inputs& in, const std::function<void()>& work);

/// Adds the boundary warning about the cells already inverted or degenerate
/// in the input (in.original.summary, its worst cell named), if any.
void warn_already_inverted(Inputs& in);

/// A method's plan for the inputs: built, or loaded from `plan_file` (a DG-IDW
/// or DG-harmonic plan file) and checked to fit the mesh and boundary.
struct PlannedMethod {
    Method method = Method::dg_idw;
    MethodOptions options;
    std::string plan_file;  // "" when built
    Plan plan;              // under mpirun: rank 0's own (docs/MPI.md)
    double prepare_seconds = 0;
    /// Under mpirun (`distributed`): the run on every process, and each
    /// process's prepare seconds; null and empty otherwise.
    std::shared_ptr<DistributedRun> distributed;
    std::vector<double> process_prepare_seconds;
    /// With sliding markers: their first pass (run/slide_pass.hpp), on this process.
    std::optional<SlidePass> slide;
};

/// `distributed`: prepare on every process of an mpirun (mpi_session.hpp);
/// a plan file is then refused.
PlannedMethod plan_method(const Inputs& in, Method method, const std::string& plan_file, ProgressLine& progress,
                          bool distributed = false);

/// plan_summary of p's plan; under mpirun, outside_hull is summed over the processes.
PlanSummary planned_summary(const PlannedMethod& p);

/// Warnings about a plan: volume nodes outside the Delaunay graph's hull
/// (DG-IDW and DGM extrapolate there).
std::vector<Warning> plan_warnings(const PlannedMethod& p);

/// Lines about the mesh, motion and boundary; the boundary's warnings through `warnings`.
void print_inputs(std::ostream& out, const Inputs& in, std::size_t frames, WarningPrinter& warnings);
/// Lines about the plan and its prepare time; its warnings through `warnings`.
void print_plan(std::ostream& out, const Inputs& in, const PlannedMethod& p, WarningPrinter& warnings);

/// The JSON report's `boundary` object (docs/JSON.md).
nlohmann::json boundary_json(const Inputs& in);
/// The JSON report's common part (docs/JSON.md).
/// Its `options` are the command line's (options_json); with a loaded plan,
/// the plan's are the ones used: replace them with options_json(p.options, true).
nlohmann::json inputs_json(const Inputs& in, const std::string& command);
/// The `options` object of the JSON reports; dg_idw_weights is null unless `weights_known`.
nlohmann::json options_json(const MethodOptions& o, bool weights_known);
nlohmann::json plan_json(const Inputs& in, const PlannedMethod& p);

}  // namespace dgwarp::cli
