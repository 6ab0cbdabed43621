#include "deform_setup.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <sstream>

#include "dgwarp/core/error.hpp"
#include "dgwarp/core/joined.hpp"
#include "dgwarp/core/stopwatch.hpp"
#include "dgwarp/io/marker_types.hpp"
#include "dgwarp/io/marker_names.hpp"
#include "dgwarp/io/mesh_io.hpp"
#include "dgwarp/io/su2/su2_config.hpp"
#include "dgwarp/motion/planar_motion.hpp"
#include "dgwarp/io/number_text.hpp"
#include "dgwarp/plan/plan_file.hpp"
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

// A loaded plan fixes its method's options: one given on the command line
// that differs from the plan's is a mistake, not silently dropped.
void refuse_conflict(const SetupArgs& args, const std::string& plan_file, const std::string& flag, bool differs,
                     const std::string& planned) {
    if (args.given.count(flag) && differs)
        throw CLI::ValidationError(flag, plan_file + " was prepared with " + flag + " " + planned +
                                             "; prepare it again with the option, or drop it");
}

std::int64_t moving_count(const BoundarySet& b) {
    std::int64_t n = 0;
    for (auto m : b.moving) n += m;
    return n;
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

PlanSummary planned_summary(const PlannedMethod& p) {
    PlanSummary s = plan_summary(p.plan);
    // Under mpirun: rank 0's plan's, with the nodes outside the hull of every process.
    if (p.distributed) s.outside_hull = mpi_outside_hull(*p.distributed);
    return s;
}

PlannedMethod plan_method(const Inputs& in, Method method, const std::string& plan_file, ProgressLine& progress,
                          bool distributed) {
    PlannedMethod p;
    p.method = method;
    p.options = method_options(in.args);
    p.plan_file = plan_file;
    Stopwatch sw;
    if (distributed && !plan_file.empty())
        throw CLI::ValidationError("--plan", "a saved plan is for one process: under mpirun each process prepares "
                                             "its own part (run without --plan)");
    if (distributed) {
        refuse_other_methods_options(in.args, method);
        progress.phase("preparing " + std::string(method_name(method)) + " on " + std::to_string(mpi_processes()) +
                       " processes");
        // A decomposed OpenFOAM case on as many processes as processors: each
        // process deforms its processor's points (the solver's decomposition).
        std::vector<std::vector<NodeId>> node_parts;
        if (in.extras.openfoam && in.extras.openfoam->processors.size() == static_cast<std::size_t>(mpi_processes()))
            for (const OpenFoamProcessor& processor : in.extras.openfoam->processors) {
                node_parts.push_back(processor.points);
                if (!in.planar) continue;
                // A 2D case: the 2D nodes of the processor's points.
                for (NodeId& v : node_parts.back()) v = in.planar->node_2d[static_cast<std::size_t>(v)];
                std::sort(node_parts.back().begin(), node_parts.back().end());
                node_parts.back().erase(std::unique(node_parts.back().begin(), node_parts.back().end()),
                                        node_parts.back().end());
            }
        p.distributed = mpi_prepare(in.mesh, in.boundary.boundary, method, p.options, node_parts, p.plan,
                                    p.process_prepare_seconds);
    } else if (!plan_file.empty()) {
        progress.phase("loading " + plan_file);
        Plan loaded = load_plan(plan_file, in.mesh.points, in.boundary.boundary);
        const Method planned = dgwarp::plan_method(loaded);
        if (in.args.method_given && planned != method)
            throw CLI::ValidationError("--plan", plan_file + " is a " + std::string(method_name(planned)) +
                                                     " plan; it cannot be used with --method " +
                                                     std::string(method_name(method)));
        p.method = planned;
        // The plan's options are the ones used; one given here that differs is a mistake.
        // The guard acts at step time: the run's value, and the mesh's cells it measures.
        const MethodOptions& asked = p.options;
        const MethodOptions in_plan = options_with_plan(loaded, asked);
        for (const MethodOption& row : method_option_table)
            if (row.method == planned && row.kept_by_plan)
                refuse_conflict(in.args, plan_file, "--" + std::string(row.name),
                                option_text(row, asked) != option_text(row, in_plan), option_text(row, in_plan));
        p.options = in_plan;
        // A plan file keeps the plan's arrays, not the guard: built again from the mesh's cells.
        attach_frame_guard(loaded, in.mesh, in.boundary.boundary, p.options);
        refuse_other_methods_options(in.args, p.method);
        p.plan = std::move(loaded);
    } else {
        refuse_other_methods_options(in.args, method);
        const std::string phase = "preparing " + std::string(method_name(method));
        progress.phase(phase);
        p.plan = prepare_for_frames(method, in.mesh, in.boundary.boundary, p.options, progress.reporter(phase));
    }
    if (!in.boundary.slides.empty()) p.slide = prepare_slide_pass(in.mesh, in.boundary, p.options);
    p.prepare_seconds = sw.lap();
    progress.clear();
    return p;
}

std::vector<Warning> plan_warnings(const PlannedMethod& p) {
    const PlanSummary s = planned_summary(p);
    if (s.outside_hull == 0) return {};
    return {{WarningCode::outside_hull, std::to_string(s.outside_hull) + " volume node" + (s.outside_hull == 1 ? " is" : "s are") +
            " outside the Delaunay graph's hull (the convex hull of the boundary nodes); " +
            std::string(method_name(p.method)) +
            " extrapolates the motion of the nearest hull simplex there. If the domain has an outer boundary "
            "(far field, walls), it should be a marker of the mesh", "", s.outside_hull}};
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

void print_plan(std::ostream& out, const Inputs& in, const PlannedMethod& p, WarningPrinter& warnings) {
    const PlanSummary s = planned_summary(p);
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
    for (const auto& w : plan_warnings(p)) warnings.print(w.text);
}

nlohmann::json options_json(const MethodOptions& o, bool weights_known) {
    nlohmann::json j = nlohmann::json::object();
    for (const MethodOption& row : method_option_table) {
        if (row.tuning) continue;
        const std::string key(row.report_key);
        const OptionValue v = row.get(o);
        switch (row.kind) {
            case OptionKind::number: j[key] = v.number; break;
            case OptionKind::whole_number: j[key] = static_cast<std::int64_t>(v.number); break;
            case OptionKind::number_or_auto: j[key] = v.automatic ? nlohmann::json("auto") : nlohmann::json(v.number); break;
            case OptionKind::word: j[key] = std::string(v.word); break;
            case OptionKind::on_off: j[key] = v.number != 0; break;
        }
    }
    // A plan file's weighting is known only once it is loaded.
    if (!weights_known) j["dg_idw_weights"] = nullptr;
    return j;
}

nlohmann::json cyclic_pairs_json(const std::vector<std::pair<std::string, std::string>>& pairs) {
    nlohmann::json out = nlohmann::json::array();
    for (const auto& [a, b] : pairs) out.push_back({a, b});
    return out;
}

nlohmann::json boundary_json(const Inputs& in) {
    const auto& b = in.boundary.boundary;
    return {{"nodes", b.nodes.size()},
            {"moving_nodes", moving_count(b)},
            {"moving_markers", in.boundary.moving_markers},
            {"static_markers", in.boundary.static_markers},
            {"sliding_markers", in.boundary.sliding_markers},
            {"sliding_nodes", in.boundary.slides.size()},
            {"sliding_by_type", in.sliding_by_type},
            {"cyclic_markers", in.boundary.cyclic_markers},
            {"cyclic_by_type", cyclic_pairs_json(in.coupled_by_type)},
            {"planar", in.planar ? nlohmann::json{{"plane_markers", in.planar->plane_markers},
                                                  {"nodes", in.mesh.num_points()},
                                                  {"cells", in.mesh.cells.size()},
                                                  {"normal", in.planar->normal},
                                                  {"thickness", in.planar->thickness}}
                                 : nlohmann::json(nullptr)}};
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

nlohmann::json plan_json(const Inputs&, const PlannedMethod& p) {
    const PlanSummary s = planned_summary(p);
    nlohmann::json phases = nlohmann::json::object();
    for (const auto& [name, seconds] : s.phase_seconds) phases[name] = seconds;
    const auto* dg_idw = std::get_if<DgIdwPlan>(&p.plan);
    nlohmann::json j = {{"method", method_name(p.method)},
            {"file", p.plan_file.empty() ? nlohmann::json(nullptr) : nlohmann::json(p.plan_file)},
            {"dg_idw_weights", dg_idw ? nlohmann::json(weighting_name(dg_idw->options.weighting)) : nlohmann::json(nullptr)},
            {"graph_simplices", s.graph_simplices ? nlohmann::json(*s.graph_simplices) : nlohmann::json(nullptr)},
            {"graph_simplices_used", s.graph_simplices_used},
            {"outside_hull", s.outside_hull},
            {"shared_graph_vertices", s.shared_vertices},
            {"coarse_points", s.coarse_points},
            {"floored_weights", s.floored_weights},
            {"bytes", plan_memory_bytes(p.plan)},
            {"seconds", p.prepare_seconds},
            {"phase_seconds", phases}};
    // Under mpirun: every process's prepare time (the counts above are rank 0's plan's).
    if (p.distributed) j["process_seconds"] = p.process_prepare_seconds;
    return j;
}

}  // namespace dgwarp::cli
