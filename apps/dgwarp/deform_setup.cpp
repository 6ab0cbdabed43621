#include "deform_setup.hpp"

#include <iomanip>
#include <sstream>

#include "dgwarp/core/error.hpp"
#include "dgwarp/core/parallel_for.hpp"
#include "dgwarp/io/mesh_io.hpp"
#include "dgwarp/io/plan_file.hpp"
#include "report.hpp"
#include "stopwatch.hpp"

namespace dgwarp::cli {

namespace {

double parse_length_scale(const std::string& text) {
    if (text == "auto") return 0.0;
    std::size_t used = 0;
    double value = 0;
    try {
        value = std::stod(text, &used);
    } catch (const std::exception&) {
        used = 0;
    }
    if (used != text.size() || !(value > 0))
        throw CLI::ValidationError("--length-scale", "expected a positive number or 'auto', got '" + text + "'");
    return value;
}

std::string joined(const std::vector<std::string>& names) {
    std::string s;
    for (const auto& n : names) s += (s.empty() ? "" : ", ") + n;
    return s.empty() ? "none" : s;
}

std::string ms(double seconds) {
    std::ostringstream s;
    s << std::fixed << std::setprecision(seconds < 0.01 ? 2 : 1) << seconds * 1e3 << " ms";
    return s.str();
}

std::int64_t moving_count(const BoundarySet& b) {
    std::int64_t n = 0;
    for (auto m : b.moving) n += m;
    return n;
}

}  // namespace

void add_setup_options(CLI::App* cmd, SetupArgs& a) {
    cmd->add_option("mesh", a.mesh, "Mesh file (.su2, .msh)")->required();
    cmd->add_option("-m,--motion", a.motion, "Motion file (JSON, docs/MOTION.md)")->required();
    cmd->add_option("--zone", a.zone, "Zone of a multi-zone SU2 file (1-based)")->check(CLI::PositiveNumber);
    cmd->add_option("--threads", a.threads, "Threads to use (default: all cores)")->check(CLI::PositiveNumber);
    cmd->add_option("--a-translation", a.a_translation, "DG-IDW weight a of the translation (paper: 7)")
        ->capture_default_str()
        ->check(CLI::PositiveNumber);
    cmd->add_option("--a-rotation", a.a_rotation, "DG-IDW weight a of the rotation (paper: 1.4)")
        ->capture_default_str()
        ->check(CLI::PositiveNumber);
    cmd->add_option("--length-scale", a.length_scale,
                    "Reference length L the distances are divided by: a number (1 reproduces the paper) or "
                    "'auto' (the moving boundary's diagonal, reduced so that max(a) L fits in the gap between the "
                    "moving and the static boundary; docs/DG-IDW.md)")
        ->capture_default_str();
}

Setup set_up(const SetupArgs& args, const std::string& plan_file) {
    if (args.threads > 0) set_num_threads(args.threads);
    Setup s;
    s.args = args;
    s.plan_file = plan_file;
    s.options.a_translation = args.a_translation;
    s.options.a_rotation = args.a_rotation;
    s.options.length_scale = parse_length_scale(args.length_scale);

    Stopwatch sw;
    s.mesh = read_mesh(args.mesh, {args.zone});
    s.spec = read_motion_file(args.motion);
    s.seconds.read = sw.lap();
    s.boundary = resolve_boundary(s.mesh, s.spec);
    s.seconds.resolve = sw.lap();
    if (plan_file.empty())
        s.plan = prepare_dg_idw(s.mesh.dim, s.mesh.points, s.boundary.boundary, s.options);
    else
        s.plan = load_dg_idw_plan(plan_file, s.mesh.points, s.boundary.boundary);
    s.seconds.prepare = sw.lap();
    s.orientation = cell_orientations(s.mesh);
    s.original_cell_quality = cell_qualities(s.mesh, s.orientation);
    s.original_quality = summarize_quality(s.original_cell_quality);
    s.seconds.quality = sw.lap();
    return s;
}

void deform_mesh(const Setup& s, const BoundaryMotion& motion, std::vector<double>& out) {
    deform_dg_idw(s.plan, s.mesh.points, motion, out, s.options);
}

void print_setup(std::ostream& out, const Setup& s, std::size_t frames) {
    const auto& b = s.boundary.boundary;
    const auto& st = s.plan.stats;
    out << "mesh      " << s.args.mesh << ": " << describe_mesh(s.mesh) << "\n";
    out << "motion    " << s.args.motion << ": " << frames << " frame" << (frames == 1 ? "" : "s")
        << "; moving: " << joined(s.boundary.moving_markers) << "; static: " << joined(s.boundary.static_markers)
        << "\n";
    out << "boundary  " << b.nodes.size() << " nodes (" << moving_count(b) << " moving)\n";
    out << "plan      DG-IDW, " << s.plan.simplices.size() / static_cast<std::size_t>(s.mesh.dim + 1)
        << " graph simplices, " << s.plan.num_volume_nodes() << " volume nodes, " << st.outside_count
        << " outside the graph's hull, " << plan_bytes(s.plan) / 1024 << " KiB"
        << (s.plan_file.empty() ? "" : ", loaded from " + s.plan_file) << "\n";
    out << "time      read " << ms(s.seconds.read) << ", prepare " << ms(s.seconds.prepare);
    if (s.plan_file.empty())
        out << " (graph " << ms(st.graph_seconds) << ", locate " << ms(st.locate_seconds) << ", weights "
            << ms(st.weights_seconds) << ")";
    out << "\n";
    for (const auto& w : s.boundary.warnings) std::cerr << "warning: " << w << "\n";
}

nlohmann::json setup_json(const Setup& s, const std::string& command) {
    const auto& b = s.boundary.boundary;
    const auto& st = s.plan.stats;
    return {{"schema_version", json_schema_version},
            {"command", command},
            {"file", s.args.mesh},
            {"motion", s.args.motion},
            {"method", "dg-idw"},
            {"mesh", mesh_json(s.mesh)},
            {"boundary",
             {{"nodes", b.nodes.size()},
              {"moving_nodes", moving_count(b)},
              {"moving_markers", s.boundary.moving_markers},
              {"static_markers", s.boundary.static_markers}}},
            {"plan",
             {{"file", s.plan_file.empty() ? nlohmann::json(nullptr) : nlohmann::json(s.plan_file)},
              {"graph_simplices", s.plan.simplices.size() / static_cast<std::size_t>(s.mesh.dim + 1)},
              {"volume_nodes", s.plan.num_volume_nodes()},
              {"outside_hull", st.outside_count},
              {"on_graph_vertex", st.snapped_count},
              {"shared_graph_vertices", st.shared_vertex_count},
              {"bytes", plan_bytes(s.plan)}}},
            {"options",
             {{"a_translation", s.options.a_translation},
              {"a_rotation", s.options.a_rotation},
              {"length_scale", s.options.length_scale == 0 ? s.plan.auto_length_scale : s.options.length_scale},
              {"length_scale_auto", s.options.length_scale == 0}}},
            {"seconds",
             {{"read", s.seconds.read},
              {"resolve", s.seconds.resolve},
              {"prepare", s.seconds.prepare},
              {"graph", st.graph_seconds},
              {"locate", st.locate_seconds},
              {"weights", st.weights_seconds},
              {"original_quality", s.seconds.quality}}},
            {"original_quality", quality_json(s.original_quality)},
            {"warnings", s.boundary.warnings}};
}

}  // namespace dgwarp::cli
