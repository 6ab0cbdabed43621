// dgwarp prepare MESH --motion M.json -o PLAN: build the plan once, reuse it every step.
#include <iostream>
#include <memory>

#include "commands.hpp"
#include "deform_setup.hpp"
#include "dgwarp/core/stopwatch.hpp"
#include "dgwarp/plan/plan_file.hpp"
#include "dgwarp/run/report_json.hpp"
#include "output_files.hpp"

namespace dgwarp::cli {

namespace {

struct PrepareArgs {
    SetupArgs setup;
    std::string output;
    bool json = false;
    bool quiet = false;
};

void run_prepare(const PrepareArgs& a) {
    const Method method = chosen_methods(a.setup, false).front();
    // Before any work, and without advising a method prepare cannot save.
    refuse_other_methods_options(a.setup, method, {Method::dg_idw, Method::dg_harmonic});
    if (method != Method::dg_idw && method != Method::dg_harmonic)
        throw CLI::ValidationError("--method", "only dg-idw and dg-harmonic plans can be saved, not " +
                                                   std::string(method_name(method)));
    require_extension("--output", a.output, {".plan"}, "a plan file");
    ProgressLine progress(!a.json && !a.quiet);
    Inputs in = read_motion_inputs(a.setup, progress, [&a](const MotionSpec& spec) {
        std::vector<std::filesystem::path> inputs = motion_named_files(spec);
        inputs.insert(inputs.end(), {a.setup.mesh, a.setup.motion});
        check_output_file(a.output, inputs);
    });
    JobPlan p;
    measure_original_cells(in, [&] { p = plan_method(in, method, "", progress); });
    Stopwatch sw;
    save_plan(a.output, p.plan);
    const double write_seconds = sw.lap();
    if (a.json) {
        nlohmann::json j = inputs_json(in, "prepare");
        j["method"] = method_name(method);
        j["plan"] = plan_json(p);
        for (const auto& w : job_plan_warnings(p)) {
            j["warnings"].push_back(w.text);
            j["warning_items"].push_back(warning_json(w));
        }
        j["output"] = a.output;
        j["seconds"]["write"] = write_seconds;
        std::cout << j.dump(2) << "\n";
    } else if (!a.quiet) {
        WarningPrinter warnings(true);
        print_inputs(std::cout, in, frame_count(in.spec), warnings);
        print_plan(std::cout, in, p, warnings);
        std::cout << "wrote " << a.output << "\n";
    }
}

}  // namespace

void add_prepare_command(CLI::App& app) {
    auto args = std::make_shared<PrepareArgs>();
    CLI::App* cmd = app.add_subcommand(
        "prepare", "Build a dg-idw or dg-harmonic plan (graph, node location, weights or factor) once and save it");
    add_setup_options(cmd, args->setup);
    cmd->get_option("--method")->description("Method of the plan: dg-idw or dg-harmonic (only these plans can be saved)");
    cmd->add_option("-o,--output", args->output, "Plan file to write (NAME.plan)")->required();
    cmd->add_flag("--json", args->json, "Print a JSON report (schema in docs/JSON.md)");
    cmd->add_flag("-q,--quiet", args->quiet, "Print nothing but errors");
    cmd->footer(
        "The plan depends on the mesh and on which markers move (from the motion file), not on the\n"
        "motion's values: reuse it for every step with 'dgwarp deform --plan' (the plan's method is used).\n"
        "Plans can be saved for --method dg-idw and dg-harmonic. The plan keeps the method's options\n"
        "(--a-translation, --a-rotation, --length-scale, --dg-idw-weights; --harmonic-*): deform --plan uses\n"
        "them, and refuses a different value given there.\n"
        "The plan file's name must end in .plan, and it may not be one of the inputs.\n\n"
        "Examples:\n"
        "  dgwarp prepare naca0012.su2 --motion examples/motions/airfoil_rotate.json -o naca0012.plan\n"
        "  dgwarp deform naca0012.su2 --motion examples/motions/airfoil_rotate.json --plan naca0012.plan -o turned.vtu");
    cmd->callback([args] { run_prepare(*args); });
}

}  // namespace dgwarp::cli
