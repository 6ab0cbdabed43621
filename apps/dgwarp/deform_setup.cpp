#include "deform_setup.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <sstream>

#include "dgwarp/core/error.hpp"
#include "dgwarp/core/joined.hpp"
#include "dgwarp/core/stopwatch.hpp"
#include "dgwarp/io/marker_names.hpp"
#include "dgwarp/io/mesh_io.hpp"
#include "dgwarp/io/number_text.hpp"
#include "dgwarp/methods/option_table.hpp"
#include "dgwarp/run/run_deformation.hpp"
#include "flag_values.hpp"
#include "report.hpp"

namespace dgwarp::cli {

namespace {

std::string method_list() {
    std::string s;
    for (Method m : all_methods) s += (s.empty() ? "" : ", ") + std::string(method_name(m));
    return s;
}

}  // namespace

std::string names_or_none(const std::vector<std::string>& names) { return names.empty() ? "none" : joined(names); }

// An option of another method than the one that runs would be silently
// ignored: a usage error instead (with --method all, every option applies).
void refuse_other_methods_options(const SetupArgs& args, Method method, const std::vector<Method>& usable) {
    if (args.method == "all") return;
    for (const std::string& flag : args.given) {
        const Method owner = option_method(flag).value();
        if (owner == method) continue;
        const std::string owner_name(method_name(owner));
        std::string message = "is an option of " + owner_name + "; it does nothing with " + std::string(method_name(method));
        // Advise --method only where the command can run that method.
        if (!usable.empty() && std::find(usable.begin(), usable.end(), owner) == usable.end()) {
            std::string list;
            for (Method m : usable) list += (list.empty() ? "" : " and ") + std::string(method_name(m));
            message += ", and this command does not run " + owner_name + " (only " + list + "): drop it";
        } else if (!args.method_given) {
            message += " (the default method): add --method " + owner_name;
        }
        throw CLI::ValidationError(flag, message);
    }
}

void add_input_options(CLI::App* cmd, SetupArgs& a) {
    cmd->add_option("mesh", a.mesh, "Mesh file (.su2, .msh, .vtu, .cgns) or OpenFOAM case folder")->required();
    cmd->add_option("-m,--motion", a.motion, "Motion file (JSON, docs/MOTION.md)")->required();
    cmd->add_option("--zone", a.zone, "Zone of a multi-zone SU2 file (1-based)")->check(positive_whole_number());
    add_rename_marker_option(cmd, a.rename_markers);
    cmd->add_option("--su2-config", a.su2_config,
                    "An SU2 configuration file (CASE.cfg): its MARKER_SYM markers slide in their planes unless the "
                    "motion names them (docs/MOTION.md \"Sliding by type\")");
}

void add_setup_options(CLI::App* cmd, SetupArgs& a) {
    // Records that a method option was given (a plan file decides the others).
    const auto given = [&a](std::string flag) {
        return [&a, flag = std::move(flag)](const std::string&) { a.given.insert(flag); };
    };
    add_input_options(cmd, a);
    cmd->add_option("--method", a.method,
                    "Deformation method: " + method_list() + " (README: which to choose), or all (each in turn, "
                    "one output per method, compared)")
        ->capture_default_str()
        ->each([&a](const std::string&) { a.method_given = true; });
    add_threads_option(cmd, a.threads, "all cores");
    // One flag per method option of the library's table, its default the library's.
    const MethodOptions defaults;
    for (const MethodOption& row : method_option_table) {
        if (row.tuning) continue;  // the methods' internal constants: not flags
        const std::string flag = "--" + std::string(row.name);
        const std::string name(row.name);
        if (row.kind == OptionKind::on_off) {
            cmd->add_flag_function(
                   flag, [&a, name](std::int64_t) { a.options[name] = "true"; }, std::string(row.help))
                ->each(given(flag));
            continue;
        }
        std::string help(row.help);
        if (row.kind != OptionKind::word || row.name != "dg-idw-weights")
            help += " (default " + option_text(row, defaults) + "; " + expected_values(row) + ")";
        else
            help += " (default paper, or a loaded plan's)";
        cmd->add_option(flag, a.options[name], help)
            ->type_name(row.kind == OptionKind::whole_number     ? "INT"
                        : row.kind == OptionKind::number_or_auto ? "NUMBER|auto"
                        : row.kind == OptionKind::word           ? "WORD"
                                                                  : "NUMBER")
            ->check(CLI::Validator(
                [&row](std::string& text) -> std::string {
                    try {
                        parse_option_value(row, text);
                    } catch (const Error&) {
                        return "expected " + expected_values(row) + ", got " + text;
                    }
                    return {};
                },
                "", ""))
            ->each(given(flag));
    }
}

std::vector<Method> chosen_methods(const SetupArgs& args, bool allow_all) {
    if (allow_all && args.method == "all") return {std::begin(all_methods), std::end(all_methods)};
    if (auto m = method_from_name(args.method)) return {*m};
    throw CLI::ValidationError("--method", "unknown method '" + args.method + "'; choose one of " + method_list() +
                                               (allow_all ? ", or all" : ""));
}

std::map<std::string, std::string, std::less<>> default_option_texts() {
    std::map<std::string, std::string, std::less<>> texts;
    const MethodOptions defaults;
    for (const MethodOption& row : method_option_table)
        if (!row.tuning) texts[std::string(row.name)] = option_text(row, defaults);
    return texts;
}

MethodOptions method_options(const SetupArgs& args) {
    MethodOptions o;
    for (const std::string& flag : args.given) set_method_option(o, flag, args.option(std::string_view(flag).substr(2)));
    return o;
}

Inputs read_motion_inputs(const SetupArgs& args, ProgressLine& progress,
                          const std::function<void(const MotionSpec&)>& check_outputs) {
    use_threads(args.threads);
    Inputs in;
    in.args = args;
    Stopwatch sw;
    in.spec = read_motion_file(args.motion);
    if (check_outputs) check_outputs(in.spec);
    progress.phase("reading " + args.mesh);
    in.mesh = read_mesh(args.mesh, {args.zone}, progress.reporter("reading " + args.mesh), in.extras);
    apply_marker_renames(in.mesh, args.rename_markers);
    in.read_seconds = sw.lap();
    progress.phase("classifying the boundary");
    classify_inputs(in, {args.su2_config, args.writable_for, "--rename-marker"});
    if (const std::string zone = zone_notice(in.extras, args.mesh, args.zone); !zone.empty())
        in.boundary.warnings.insert(in.boundary.warnings.begin(),
                                    {WarningCode::other, zone + "; an .su2 output keeps the other zones as they are"});
    progress.clear();
    return in;
}

JobPlan plan_method(const Inputs& in, Method method, const std::string& plan_file, ProgressLine& progress,
                    std::shared_ptr<DistributedRun>* distributed) {
    PlanRequest r;
    r.method = method;
    r.options = method_options(in.args);
    r.plan_file = plan_file;
    r.method_given = in.args.method_given;
    for (const std::string& flag : in.args.given) r.given.insert(flag.substr(2));
    // The options of another method refused before the work (a plan file's method once it is read).
    r.check_method = [&](Method m) { refuse_other_methods_options(in.args, m); };
    std::string phase_name = "preparing " + std::string(method_name(method));
    std::vector<double> process_seconds;
    if (distributed && mpi_processes() > 1) {
        if (!plan_file.empty())
            throw CLI::ValidationError("--plan", "a saved plan is for one process: under mpirun each process "
                                                 "prepares its own part (run without --plan)");
        phase_name += " on " + std::to_string(mpi_processes()) + " processes";
        // On every process; a decomposed OpenFOAM case on as many processes as
        // processors: each process deforms its processor's points (the solver's decomposition).
        r.prepare = [&](const MethodOptions& options) {
            Plan rank0_plan;
            *distributed = mpi_prepare(in.mesh, in.boundary.boundary, method, options,
                                       processor_node_parts(in, mpi_processes()), rank0_plan, process_seconds);
            return rank0_plan;
        };
    }
    const auto phase = [&](const std::string& what) { progress.phase(r.prepare ? phase_name : what); };
    JobPlan p = plan_job(in, r, phase, progress.reporter(phase_name));
    if (r.prepare) {
        p.process_prepare_seconds = std::move(process_seconds);
        p.outside_hull_over_processes = mpi_outside_hull(**distributed);
    }
    progress.clear();
    return p;
}

void print_inputs(std::ostream& out, const Inputs& in, std::size_t frames, WarningPrinter& warnings) {
    const auto& b = in.boundary.boundary;
    out << "mesh      " << in.args.mesh << ": " << describe_mesh(output_mesh(in)) << "\n";
    if (in.planar)
        out << "2D case   one cell thick between its " << (in.planar->wedge ? "wedge" : "empty") << " patches ("
            << names_or_none(in.planar->plane_markers) << "), deformed as the 2D mesh of the first plane: "
            << describe_mesh(in.mesh) << "; the other plane's nodes move as their twins"
            << (in.planar->axis_marker.empty() ? "" : "; the axis (" + in.planar->axis_marker + ") slides") << "\n";
    out << "motion    " << in.args.motion << ": " << frames << " frame" << (frames == 1 ? "" : "s")
        << "; moving: " << names_or_none(in.boundary.moving_markers)
        << "; static: " << names_or_none(in.boundary.static_markers);
    if (!in.boundary.sliding_markers.empty()) out << "; sliding: " << names_or_none(in.boundary.sliding_markers);
    if (!in.sliding_by_type.empty())
        out << "; sliding by their patch or BC type (unless the motion names them): " << names_or_none(in.sliding_by_type);
    if (!in.boundary.cyclic_markers.empty()) {
        out << "; cyclic, each node moving as its image on the other half: " << names_or_none(in.boundary.cyclic_markers);
        if (!in.coupled_by_type.empty()) out << " (OpenFOAM cyclic patches and their neighbourPatch, unless the motion names them)";
    }
    out << "\n";
    out << "boundary  " << b.nodes.size() << " nodes (" << moving_count(b) << " moving";
    if (!in.boundary.slides.empty()) out << ", of them " << in.boundary.slides.size() << " sliding or cyclic";
    out << ")\n";
    for (const auto& w : in.boundary.warnings) warnings.print(w.text);
}

void print_plan(std::ostream& out, const Inputs& in, const JobPlan& p, WarningPrinter& warnings) {
    const PlanSummary s = job_plan_summary(p);
    out << "plan      " << method_name(p.method);
    if (s.graph_simplices_used > 0) {
        if (s.graph_simplices) out << ", " << *s.graph_simplices << " graph simplices";
        else out << ", " << s.graph_simplices_used << " graph simplices holding volume nodes";
        out << ", " << s.outside_hull << " nodes outside the graph's hull";
    }
    out << ", " << plan_memory_bytes(p.plan) / 1024 << " KiB"
        << (p.plan_file.empty() ? "" : ", loaded from " + p.plan_file) << "\n";
    out << "time      read " << milliseconds(in.read_seconds) << ", prepare " << milliseconds(p.prepare_seconds);
    if (!s.phase_seconds.empty()) {
        out << " (";
        for (std::size_t i = 0; i < s.phase_seconds.size(); ++i)
            out << (i ? ", " : "") << s.phase_seconds[i].first << " " << milliseconds(s.phase_seconds[i].second);
        out << ")";
    }
    out << "\n";
    for (const auto& w : job_plan_warnings(p)) warnings.print(w.text);
}

nlohmann::json inputs_json(const Inputs& in, const std::string& command) {
    return {{"schema_version", json_schema_version},
            {"command", command},
            {"file", in.args.mesh},
            {"motion", in.args.motion},
            {"mesh", mesh_json(output_mesh(in))},
            {"boundary", boundary_json(in)},
            {"options", options_json(method_options(in.args), in.args.given.count("--dg-idw-weights") > 0)},
            {"seconds", {{"read", in.read_seconds}, {"resolve", in.resolve_seconds}, {"original_quality", in.quality_seconds}}},
            {"original_quality", quality_json(in.original.summary)},
            {"warnings", warning_texts_json(in.boundary.warnings)},
            {"warning_items", warning_items_json(in.boundary.warnings)}};
}

}  // namespace dgwarp::cli
