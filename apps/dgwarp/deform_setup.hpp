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
#include "dgwarp/job/job_inputs.hpp"
#include "dgwarp/job/job_plan.hpp"
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

/// The names joined ("a, b"), or "none".
std::string names_or_none(const std::vector<std::string>& names);

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

/// The mesh, the motion and the boundary, read and checked once
/// (job/job_inputs.hpp), and the command line they were read by.
struct Inputs : JobInputs {
    SetupArgs args;
};

/// Reads the motion file, calls `check_outputs` with it when given (so that
/// outputs are checked before the long work: their names may depend on its
/// frames, and none may be a file it names), then reads the mesh and resolves
/// the boundary (every check of resolve_boundary): mesh, spec, boundary, read
/// and resolve seconds.
Inputs read_motion_inputs(const SetupArgs& args, ProgressLine& progress,
                          const std::function<void(const MotionSpec&)>& check_outputs = {});

/// A method's plan for the inputs (job/job_plan.hpp's plan_job with the
/// command line's options): built, or loaded from `plan_file`; the options
/// of another method than the one that runs refused. With `distributed`
/// under mpirun: prepared on every process (mpi_session.hpp), *distributed
/// its run, and the plan rank 0's own (docs/MPI.md); a plan file is then refused.
JobPlan plan_method(const Inputs& in, Method method, const std::string& plan_file, ProgressLine& progress,
                    std::shared_ptr<DistributedRun>* distributed = nullptr);

/// Lines about the mesh, motion and boundary; the boundary's warnings through `warnings`.
void print_inputs(std::ostream& out, const Inputs& in, std::size_t frames, WarningPrinter& warnings);
/// Lines about the plan and its prepare time; its warnings through `warnings`.
void print_plan(std::ostream& out, const Inputs& in, const JobPlan& p, WarningPrinter& warnings);

/// The JSON report's common part (docs/JSON.md).
/// Its `options` are the command line's (options_json); with a loaded plan,
/// the plan's are the ones used: replace them with options_json(p.options, true).
nlohmann::json inputs_json(const Inputs& in, const std::string& command);

}  // namespace dgwarp::cli
