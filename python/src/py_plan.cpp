// dgwarp.prepare, dgwarp.load_plan and dgwarp.Plan: the library's prepare /
// deform (methods/method.hpp) and plan files (plan/plan_file.hpp) for Python,
// with the boundary classified and each step's motion resolved as the CLI's
// `dgwarp prepare` / `dgwarp deform` do (apps/dgwarp/deform_setup.cpp,
// cmd_deform.cpp), through the same library calls: the markers the mesh
// file's types make slide or couple too (io/marker_types.hpp), but a 2D case
// stays 3D (docs/PYTHON.md).
#include "py_plan.hpp"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <algorithm>
#include <cmath>

#include "arrays.hpp"
#include "bindings.hpp"
#include "dgwarp/core/error.hpp"
#include "dgwarp/io/marker_types.hpp"
#include "dgwarp/io/mesh_io.hpp"
#include "dgwarp/plan/plan_file.hpp"
#include "dgwarp/methods/derivative.hpp"
#include "dgwarp/methods/option_table.hpp"
#include "dgwarp/core/stopwatch.hpp"
#include "dgwarp/run/report_json.hpp"
#include "dgwarp/run/run_deformation.hpp"
#include "errors.hpp"
#include "progress_bridge.hpp"
#include "py_motion.hpp"
#include "py_options.hpp"
#include "py_step_motion.hpp"

namespace py = pybind11;

namespace dgwarp::python {

namespace {

/// Marker names from None, one name, or a list of names.
std::vector<std::string> marker_list(py::handle obj, const char* what) {
    std::vector<std::string> names;
    if (obj.is_none()) return names;
    if (py::isinstance<py::str>(obj)) return {obj.cast<std::string>()};
    if (!py::isinstance<py::sequence>(obj))
        throw py::type_error(std::string(what) + " must be a list of marker names, got " +
                             py::str(py::type::of(obj)).cast<std::string>());
    for (auto item : obj) {
        if (!py::isinstance<py::str>(item))
            throw py::type_error(std::string(what) + " must hold marker names (str), got " +
                                 py::str(py::type::of(item)).cast<std::string>());
        names.push_back(item.cast<std::string>());
    }
    return names;
}

/// The boundary classified as `dgwarp prepare` classifies it for a motion
/// file that moves exactly the `moving` markers (resolve_boundary, with the
/// shared-node rule and tolerance of such a file); or, for a motion, as that
/// motion classifies it.
ResolvedBoundary classify(const PyMesh& mesh, py::handle moving, py::handle static_markers, SharedNodeRule rule,
                          double tolerance, SharedNodeRule& rule_used, double& tolerance_used, MotionSpec& used) {
    tolerance = shared_tolerance_arg(tolerance);
    MotionSpec spec;
    if (py::isinstance<PyMotion>(moving) || py::isinstance<py::dict>(moving)) {
        if (!static_markers.is_none())
            throw py::type_error("static: a motion classifies the markers itself (markers it does not move are static)");
        spec = motion_arg(moving)->spec;
    } else {
        const std::vector<std::string> moved = marker_list(moving, "moving");
        std::vector<std::string> fixed = marker_list(static_markers, "static");
        for (const std::string& name : moved) find_marker(mesh.mesh, name);  // MeshError naming the mesh's markers
        for (const std::string& name : fixed) {
            find_marker(mesh.mesh, name);
            if (std::find(moved.begin(), moved.end(), name) != moved.end())
                throw py::value_error("marker '" + name + "' is both moving and static");
        }
        if (!static_markers.is_none())
            for (const Marker& marker : mesh.mesh.markers)
                if (std::find(moved.begin(), moved.end(), marker.name) == moved.end() &&
                    std::find(fixed.begin(), fixed.end(), marker.name) == fixed.end())
                    throw py::value_error("marker '" + marker.name +
                                          "' is neither moving nor static: every marker's nodes are boundary nodes; "
                                          "list it in one of them (or leave static=None: every marker not moving)");
        MotionFrame frame;
        for (const std::string& name : moved) frame.markers[name] = RigidMotion{};  // moving, whatever its motion
        // Named static: not made to slide or couple by its type (below).
        for (const std::string& name : fixed) frame.markers[name] = FixedMotion{};
        spec.frames.push_back(std::move(frame));
        spec.shared_nodes = rule;
        spec.shared_tolerance = tolerance;
        spec.source = "prepare";
    }
    // The markers the mesh file's types make slide or couple (OpenFOAM's
    // empty, symmetryPlane, cyclic; CGNS's BCSymmetryPlane), unless named, as
    // `dgwarp deform` does; a 2D case stays 3D here, its empty patches sliding.
    const TypedMotion typed = apply_marker_types(mesh.mesh, mesh.extras, spec);
    rule_used = spec.shared_nodes;
    tolerance_used = spec.shared_tolerance;
    used = spec;
    ResolvedBoundary resolved;
    {
        py::gil_scoped_release release;
        resolved = resolve_boundary(mesh.mesh, spec);
    }
    if (!typed.uncoupled.empty()) resolved.warnings.push_back(uncoupled_cyclic_warning(typed.uncoupled));
    warn_all(resolved.warnings);
    return resolved;
}

/// A plan over one process's part (comm=) cannot run the sliding and cyclic
/// nodes' first pass, which needs every boundary node.
void refuse_slides_with_comm(const ResolvedBoundary& b) {
    if (b.slides.empty()) return;
    const std::string marker = b.sliding_markers.empty() ? b.cyclic_markers.front() : b.sliding_markers.front();
    throw py::value_error("marker '" + marker + "' " + (b.sliding_markers.empty() ? "is cyclic" : "slides") +
                          ": a plan prepared with comm= has no sliding or cyclic markers (their first pass needs "
                          "every boundary node); prepare it on one process");
}

/// What `dgwarp deform` warns about a plan (volume nodes outside the graph's hull).
void warn_plan(const PyPlan& p) {
    for (const Warning& w : plan_warnings(plan_method(plan_of(p)), plan_summary(plan_of(p)))) warn(w.text);
}

std::shared_ptr<PyPlan> prepare_plan(std::shared_ptr<PyMesh> mesh, py::handle moving, py::handle static_markers,
                                     const std::string& method_name_arg, const std::string& shared_nodes,
                                     double shared_tolerance, py::object progress, py::object comm,
                                     py::object global_ids, const py::kwargs& kwargs) {
    if (!mesh) throw py::type_error("prepare(): mesh must be a dgwarp.Mesh, got None");
    const Method method = method_arg(method_name_arg);
    auto p = std::make_shared<PyPlan>();
    p->options = method_options(method, kwargs, "prepare");
    p->mesh = mesh;
    p->boundary = classify(*mesh, moving, static_markers, shared_nodes_arg(shared_nodes), shared_tolerance,
                           p->shared_nodes, p->shared_tolerance, p->classified_by);
    if (!comm.is_none()) {
        // This process's part, prepared with the others (py_mpi.hpp).
        if (!progress.is_none()) throw py::value_error("prepare(comm=...) takes no progress callback");
        // On every process alike: a marker may slide by its type on some parts only (its faces there).
        collectively_on(comm, [&] { refuse_slides_with_comm(p->boundary); });
        p->distributed = prepare_distributed_plan(comm, method, mesh->mesh.dim, mesh->mesh.points, global_ids,
                                                  p->boundary.boundary, p->options);
        p->comm = comm;
        return p;
    }
    if (!global_ids.is_none()) throw py::value_error("global_ids is for prepare(comm=...)");
    ProgressBridge bridge(progress);
    bridge.run([&] {
        p->plan = prepare_for_frames(method, mesh->mesh, p->boundary.boundary, p->options, bridge.function());
        if (!p->boundary.slides.empty()) p->slide = prepare_slide_pass(mesh->mesh, p->boundary, p->options);
    });
    warn_plan(*p);
    return p;
}

/// The PyPlan of a plan read from a file (or its bytes) for `mesh`, as
/// load_plan documents it: the moving markers, unless given, those all of
/// whose nodes the plan moves; checked to fit the mesh; a DG-harmonic plan's
/// guard built again from the mesh's cells.
std::shared_ptr<PyPlan> plan_from_file_content(Plan plan, std::shared_ptr<PyMesh> mesh, py::handle moving,
                                               py::handle static_markers, const std::string& shared_nodes,
                                               double shared_tolerance) {
    auto p = std::make_shared<PyPlan>();
    p->mesh = mesh;
    p->plan = std::move(plan);
    const GraphPlanCore* core = graph_plan_core(p->plan);
    p->options = options_with_plan(p->plan, p->options);
    py::object moving_names = py::reinterpret_borrow<py::object>(moving);
    if (moving.is_none() && core) {
        // The markers all of whose nodes the plan moves (moving_wins: a moving
        // marker's nodes all move; a static marker's move only where shared).
        py::list names;
        for (const Marker& marker : mesh->mesh.markers) {
            const std::vector<NodeId> ids = marker_nodes(marker);
            const bool all_moving = !ids.empty() && std::all_of(ids.begin(), ids.end(), [&](NodeId id) {
                const auto& nodes = core->boundary_nodes;
                const auto it = std::lower_bound(nodes.begin(), nodes.end(), id);
                return it != nodes.end() && *it == id &&
                       core->boundary_moving[static_cast<std::size_t>(it - nodes.begin())];
            });
            if (all_moving) names.append(marker.name);
        }
        moving_names = names;
    }
    p->boundary = classify(*mesh, moving_names, static_markers, shared_nodes_arg(shared_nodes), shared_tolerance,
                           p->shared_nodes, p->shared_tolerance, p->classified_by);
    {
        py::gil_scoped_release release;
        if (const auto* d = std::get_if<DgIdwPlan>(&p->plan)) check_plan_fits(*d, mesh->mesh.points, p->boundary.boundary);
        if (auto* h = std::get_if<DgHarmonicPlan>(&p->plan)) {
            check_plan_fits(*h, mesh->mesh.points, p->boundary.boundary);
            // A plan file keeps the plan's arrays, not the guard: built again from the mesh's cells.
            attach_frame_guard(p->plan, mesh->mesh, p->boundary.boundary, p->options);
        }
        if (!p->boundary.slides.empty()) p->slide = prepare_slide_pass(mesh->mesh, p->boundary, p->options);
    }
    warn_plan(*p);
    return p;
}

std::shared_ptr<PyPlan> load_plan_file(const std::filesystem::path& path, std::shared_ptr<PyMesh> mesh,
                                       py::handle moving, py::handle static_markers, const std::string& shared_nodes,
                                       double shared_tolerance, py::object comm, py::object global_ids) {
    if (!mesh) throw py::type_error("load_plan(): mesh must be a dgwarp.Mesh, got None");
    if (!comm.is_none()) {
        // This process's part of a plan saved by Plan.save with comm= (py_mpi.hpp).
        if (moving.is_none())
            throw py::value_error("load_plan(comm=...): give the moving markers (each process classifies its own part)");
        auto p = std::make_shared<PyPlan>();
        p->mesh = mesh;
        p->boundary = classify(*mesh, moving, static_markers, shared_nodes_arg(shared_nodes), shared_tolerance,
                               p->shared_nodes, p->shared_tolerance, p->classified_by);
        // On every process alike: a marker may slide by its type on some parts only (its faces there).
        collectively_on(comm, [&] { refuse_slides_with_comm(p->boundary); });
        p->distributed = load_distributed_plan_file(comm, path, mesh->mesh.dim, mesh->mesh.points, global_ids,
                                                    p->boundary.boundary);
        p->comm = comm;
        p->options = options_with_plan(plan_of(*p), p->options);
        return p;
    }
    if (!global_ids.is_none()) throw py::value_error("global_ids is for load_plan(comm=...)");
    Plan plan;
    {
        py::gil_scoped_release release;
        plan = load_plan(path);
    }
    return plan_from_file_content(std::move(plan), std::move(mesh), moving, static_markers, shared_nodes,
                                  shared_tolerance);
}

// Pickling (docs/PYTHON.md, "Pickling"): a plan is its mesh (pickled with
// it), its method, options and boundary classification, and, for the
// methods whose plans can be saved (dg-idw, dg-harmonic), its plan file's
// bytes, read back as load_plan reads a file. The other methods' plans are
// prepared again from the same inputs when unpickled: their preparation is
// deterministic, so the plan deforms to the same bits either way.
constexpr const char* plan_state_tag = "dgwarp.Plan";
constexpr int plan_state_version = 2;  // 2: the sliding markers and the cyclic pairs too

py::tuple plan_state(const PyPlan& p) {
    if (p.distributed)
        throw py::type_error("a plan prepared with comm= does not pickle (each process prepares its own, together)");
    const Method method = plan_method(p.plan);
    py::object bytes = py::none();
    if (plan_can_be_saved(p.plan)) {
        std::vector<std::byte> file;
        {
            py::gil_scoped_release release;
            file = plan_file_bytes(p.plan);
        }
        bytes = py::bytes(reinterpret_cast<const char*>(file.data()), file.size());
    }
    // Each cyclic marker with its partner.
    py::list cyclic;
    const Mesh& mesh = p.mesh->mesh;
    for (std::size_t m = 0; m < mesh.markers.size(); ++m)
        if (p.boundary.context.marker_cyclic[m]) {
            const MotionSpec& spec = p.classified_by;
            const auto& motion = marker_motion(spec, spec.frames.at(0), mesh.markers[m].name);
            cyclic.append(py::make_tuple(mesh.markers[m].name, std::get<CyclicMotion>(motion).partner));
        }
    return py::make_tuple(plan_state_tag, plan_state_version, std::const_pointer_cast<PyMesh>(p.mesh),
                          std::string(method_name(method)), options_dict(method, p.options),
                          p.boundary.moving_markers, p.boundary.static_markers,
                          std::string(shared_nodes_name(p.shared_nodes)), p.shared_tolerance, bytes,
                          p.boundary.sliding_markers, cyclic);
}

std::shared_ptr<PyPlan> plan_from_state(const py::tuple& t) {
    if (t.size() < 2 || !py::isinstance<py::str>(t[0]) || t[0].cast<std::string>() != plan_state_tag)
        throw py::value_error("not the pickled state of a dgwarp.Plan");
    if (!py::isinstance<py::int_>(t[1]) || t[1].cast<int>() != plan_state_version)
        throw py::value_error("a dgwarp.Plan pickled by another version of dgwarp (state version " +
                              py::str(t[1]).cast<std::string>() + ", this one reads " +
                              std::to_string(plan_state_version) + "): pickle it again");
    if (t.size() != 12) throw py::value_error("not the pickled state of a dgwarp.Plan");
    auto mesh = t[2].cast<std::shared_ptr<PyMesh>>();
    const std::string method = t[3].cast<std::string>();
    const py::kwargs options = py::kwargs(t[4].cast<py::dict>());
    py::object moving = t[5].cast<py::list>(), fixed = t[6].cast<py::list>();
    const std::string shared_nodes = t[7].cast<std::string>();
    const double tolerance = t[8].cast<double>();
    const py::list sliding = t[10].cast<py::list>(), cyclic = t[11].cast<py::list>();
    if (!sliding.empty() || !cyclic.empty()) {
        // The classification as a motion in the motion-file form: moving
        // markers given a (zero) motion, sliding and cyclic ones as they were.
        py::dict markers;
        for (auto name : moving) markers[name] = py::dict(py::arg("translate") = py::make_tuple(0.0, 0.0));
        for (auto name : fixed) markers[name] = py::str("fixed");  // not made to slide by its type
        for (auto name : sliding) markers[name] = py::str("slide");
        for (auto pair : cyclic) {
            const py::tuple ab = pair.cast<py::tuple>();
            markers[ab[0]] = py::dict(py::arg("cyclic") = ab[1]);
        }
        py::dict motion(py::arg("markers") = markers, py::arg("shared_nodes") = shared_nodes);
        if (tolerance > 0) motion["shared_tolerance"] = tolerance;
        moving = motion;
        fixed = py::none();
    }
    if (t[9].is_none()) return prepare_plan(mesh, moving, fixed, method, shared_nodes, tolerance, py::none(), py::none(), py::none(),
                                            options);
    const std::string bytes = t[9].cast<std::string>();
    Plan plan;
    {
        py::gil_scoped_release release;
        plan = load_plan_bytes(std::as_bytes(std::span(bytes.data(), bytes.size())), "a pickled dgwarp.Plan");
    }
    if (method_name(plan_method(plan)) != method)
        throw py::value_error("a pickled dgwarp.Plan: its plan bytes are a " +
                              std::string(method_name(plan_method(plan))) + " plan, its state says " + method);
    // The options the plan file does not hold (dg-harmonic's guard bar) come
    // from the state; those it holds are the plan's own.
    const MethodOptions given = method_options(plan_method(plan), options, "a pickled dgwarp.Plan");
    auto p = plan_from_file_content(std::move(plan), mesh, moving, fixed, shared_nodes, tolerance);
    p->options = options_with_plan(p->plan, given);
    return p;
}

/// Plan.deform_derivative (J @ in) or, with `transpose`, deform_derivative_transpose (J.T @ in):
/// `in` checked against the rows the product takes, into `out` or a new array.
py::object derivative_product(const PyPlan& p, py::handle in, py::handle out, bool transpose) {
    const char* name = transpose ? "deform_derivative_transpose" : "deform_derivative";
    if (p.distributed) throw py::value_error(std::string(name) + ": not for a plan prepared with comm=");
    if (p.slide)
        throw py::value_error(std::string(name) + ": not for a plan with sliding or cyclic markers (marker '" +
                              (p.boundary.sliding_markers.empty() ? p.boundary.cyclic_markers.front()
                                                                  : p.boundary.sliding_markers.front()) +
                              "'): their nodes' motion comes from a first pass the derivative does not follow");
    const auto dim = static_cast<py::ssize_t>(p.mesh->mesh.dim);
    const auto points = static_cast<py::ssize_t>(p.mesh->mesh.num_points());
    const auto boundary = static_cast<py::ssize_t>(p.boundary.boundary.nodes.size());
    const auto v = float_matrix(in, transpose ? "weights" : "direction", transpose ? points : boundary, dim);
    const py::ssize_t rows = transpose ? boundary : points;
    py::array_t<double> result = out.is_none() ? py::array_t<double>({rows, dim}) : output_matrix(out, "out", rows, dim);
    {
        py::gil_scoped_release release;
        const std::span<const double> input(v.data(), static_cast<std::size_t>(v.size()));
        const std::span<double> output(result.mutable_data(), static_cast<std::size_t>(result.size()));
        if (transpose) deform_derivative_transpose(p.plan, input, output);
        else deform_derivative(p.plan, input, output);
    }
    return out.is_none() ? py::object(result) : py::reinterpret_borrow<py::object>(out);
}

py::object deform_step(const PyPlan& p, py::handle motion, long long frame_arg, py::handle translation,
                       py::handle rotation, py::handle center, py::handle out, const py::object& untangle,
                       double untangle_target, py::object progress, bool want_report) {
    if (frame_arg < 0) throw py::index_error("frame " + std::to_string(frame_arg) + ": frames are numbered from 0");
    const auto frame = static_cast<std::size_t>(frame_arg);
    const bool arrays = !translation.is_none() || !rotation.is_none() || !center.is_none();
    if (motion.is_none() && !arrays)
        throw py::type_error("deform() needs a motion (a dict in the motion-file form, a dgwarp.Motion) or "
                             "translation= / rotation= / center= arrays");
    BoundaryMotion boundary_motion;
    std::vector<Warning> warnings;
    std::int64_t folded_faces = 0;  // the boundary motion turns faces over: the guard's redo cannot help
    if (!motion.is_none()) {
        if (py::isinstance<py::array>(motion) && !arrays) {
            boundary_motion = motion_from_arrays(p, motion, py::none(), py::none());  // a translation per node
            warnings = large_motion_warnings(p.mesh->mesh, p.boundary, boundary_motion, "deform() arrays");
        } else {
            if (arrays)
                throw py::type_error("deform(): give a motion or translation= / rotation= / center=, not both");
            if (py::isinstance<py::str>(motion))
                throw py::type_error("deform(): a str motion is ambiguous; pass dgwarp.Motion(path) for a motion file");
            const MotionPtr m = motion_arg(motion);
            ResolvedFrame resolved = resolve_motion_frame(p, m->spec, frame);
            boundary_motion = std::move(resolved.motion);
            warnings = std::move(resolved.warnings);
            folded_faces = resolved.folded_faces;
        }
    } else {
        if (frame != 0) throw py::value_error("frame is for a motion of several frames, not for arrays");
        boundary_motion = motion_from_arrays(p, translation, rotation, center);
        // What a motion dict would warn about (as resolve_frame does).
        warnings = large_motion_warnings(p.mesh->mesh, p.boundary, boundary_motion, "deform() arrays");
    }
    if (!untangle.is_none() && !py::isinstance<py::bool_>(untangle))
        throw py::type_error("untangle must be None (the method's default), True or False");
    if (!(untangle_target >= 0 && untangle_target < 1))
        throw py::value_error("untangle_target must be in [0, 1), got " + std::to_string(untangle_target));
    const Mesh& mesh = p.mesh->mesh;
    const auto rows = static_cast<py::ssize_t>(mesh.num_points());
    py::array_t<double> result = out.is_none() ? py::array_t<double>({rows, static_cast<py::ssize_t>(mesh.dim)})
                                               : output_matrix(out, "out", rows, mesh.dim);
    const std::span<double> xs(result.mutable_data(), static_cast<std::size_t>(result.size()));
    FrameReport report;
    ProgressBridge bridge(progress);
    // As the CLI's frames (run/deform_frame.hpp): no guard where the boundary motion folds faces.
    const MethodOptions options = step_options(p.options, folded_faces);
    std::optional<FrameCells> measured;
    if (p.distributed) {
        // Collective: every process steps together; the repair and the report measure whole cells, which
        // a process's part does not have.
        if ((!untangle.is_none() && py::isinstance<py::bool_>(untangle) && untangle.cast<bool>()) || want_report ||
            !progress.is_none())
            throw py::value_error("a plan prepared with comm= steps without untangle, report or progress");
        py::gil_scoped_release release;
        Stopwatch sw;
        report.step = deform_distributed_plan(*p.distributed, mesh.points, boundary_motion, xs);
        report.step_seconds = sw.lap();
    } else {
        // As the CLI's frames: DG-harmonic's guard judges its one pass on the frame's measure.
        static const OriginalCells none;
        const OriginalCells& original = guards_frames(p.plan, options) ? p.original() : none;  // measured once
        bridge.run([&] {
            measured = step_frame(p.plan, mesh, original, p.boundary.boundary.nodes, p.slide ? &*p.slide : nullptr,
                                  boundary_motion, options, xs, report, bridge.function());
        });
    }
    report.warnings = std::move(warnings);
    for (Warning& w : step_warnings(report.step)) report.warnings.push_back(std::move(w));
    if (!p.distributed) finish_step(p, xs, untangle, untangle_target, want_report, report, std::move(measured));
    warn_all(report.warnings);
    py::object points = out.is_none() ? py::object(result) : py::reinterpret_borrow<py::object>(out);
    if (!want_report) return points;
    // The CLI's frame report (docs/JSON.md), as a dict.
    return py::make_tuple(points, py::module_::import("json").attr("loads")(frame_report_json(report).dump()));
}

}  // namespace

void bind_plan(py::module_& m) {
    py::class_<PyPlan, std::shared_ptr<PyPlan>>(
        m, "Plan",
        "A method's plan for one mesh and one split of its markers into moving and static ones:\n"
        "prepare once (dgwarp.prepare, dgwarp.load_plan), deform every step (Plan.deform).\n"
        "Immutable: several threads may deform with one plan at the same time.")
        .def("deform", &deform_step, py::arg("motion") = py::none(), py::kw_only(), py::arg("frame") = 0,
             py::arg("translation") = py::none(), py::arg("rotation") = py::none(), py::arg("center") = py::none(),
             py::arg("out") = py::none(), py::arg("untangle") = py::none(), py::arg("untangle_target") = 0.0,
             py::arg("progress") = py::none(), py::arg("report") = false,
             "One step: the new coordinates of every node, (num_points, dim) float64, measured from the\n"
             "original mesh (not from the previous step); with report=True, (coordinates, report).\n"
             "The motion, either:\n"
             "  motion:  a dict in the motion-file form (docs/MOTION.md) or a dgwarp.Motion, and `frame`\n"
             "           (0-based) for a motion of several frames; markers it does not name stay fixed;\n"
             "           it may not move a marker the plan holds static;\n"
             "  or arrays per boundary node (Plan.boundary_nodes order), each None (zero), one vector\n"
             "  for every moving node, or (n_boundary, 3) rows (translation and center also (n, dim)):\n"
             "  translation, rotation (axis x angle, radians; about z only in 2D), center; rows of\n"
             "  static nodes must be zero. A bare array as `motion` is the translation.\n"
             "  out:     a float64 C-contiguous (num_points, dim) array to write into (no allocation);\n"
             "           it is returned.\n"
             "  untangle: None (default: DG-harmonic repairs cells its step inverted, its last resort;\n"
             "           the other methods do nothing), True (repair cells at or below untangle_target\n"
             "           by moving volume nodes, as `dgwarp deform --untangle`), False (no repair).\n"
             "  progress: a callable taking the fraction done.\n"
             "  report:  also return the step's report, a dict as a frame of `dgwarp deform --json`\n"
             "           (docs/JSON.md): quality, ratio, inverted_by_motion, substeps, untangle and\n"
             "           last_resort, guard, seconds, warnings (texts) and warning_items (code, text, and\n"
             "           marker, count, node, element, value where they apply). It measures every cell.\n"
             "The GIL is released while the step runs. Raises InvalidResultError (ValueError) when the\n"
             "method cannot move the mesh validly (DGM without dgm_substep).")
        .def(
            "deform_derivative",
            [](const PyPlan& p, py::handle direction, py::handle out) {
                return derivative_product(p, direction, out, false);
            },
            py::arg("direction"), py::kw_only(), py::arg("out") = py::none(),
            "J @ direction, J = d(points) / d(boundary points) of a translation-only step (exact: such a\n"
            "step is linear in the translations). direction: (len(boundary_nodes), dim), a move of each\n"
            "boundary node in the order of boundary_nodes (static nodes' rows move nothing); returns\n"
            "(num_points, dim). dg-idw and dg-harmonic (its one pass: the guard's redo and the repair are\n"
            "not differentiated); other methods raise Error. One pass, single-threaded, GIL released.")
        .def(
            "deform_derivative_transpose",
            [](const PyPlan& p, py::handle weights, py::handle out) {
                return derivative_product(p, weights, out, true);
            },
            py::arg("weights"), py::kw_only(), py::arg("out") = py::none(),
            "J.T @ weights (IDWarp's warpDeriv): weights (num_points, dim), e.g. an objective's gradient\n"
            "with respect to the volume points; returns (len(boundary_nodes), dim), its gradient with\n"
            "respect to the boundary points (zero rows for static nodes). As deform_derivative.")
        .def("save", [](const PyPlan& p, const std::filesystem::path& path) {
                 // As `dgwarp prepare -o`: a plan file's name says what it is.
                 if (lower_case_extension(path) != ".plan")
                     throw py::value_error("save: a plan file's name ends in .plan, got " + path.string());
                 if (p.distributed) return save_distributed_plan_file(*p.distributed, path);  // collective
                 py::gil_scoped_release release;
                 save_plan(path, p.plan);
             },
             py::arg("path"),
             "Writes the plan to `path`, a name ending in .plan (atomically; DG-IDW and DG-harmonic plans; a\n"
             "plan prepared with comm=: collectively, every process's part in one file).\n"
             "dgwarp.load_plan(path, mesh)\n"
             "reads it back; so does `dgwarp deform --plan`.")
        .def_property_readonly("method", [](const PyPlan& p) { return std::string(method_name(plan_method(plan_of(p)))); },
                               "The method's name ('dg-idw', 'dgm', 'idw', 'rbf', 'dg-harmonic').")
        .def_property_readonly("options", [](const PyPlan& p) { return options_dict(plan_method(plan_of(p)), p.options); },
                               "The method's options as used (keyword-argument names).")
        .def_property_readonly("mesh", [](const PyPlan& p) { return std::const_pointer_cast<PyMesh>(p.mesh); },
                               "The mesh the plan was prepared for.")
        .def_property_readonly(
            "boundary_nodes",
            [](py::object self) {
                const auto& nodes = self.cast<const PyPlan&>().boundary.boundary.nodes;
                return read_only_view(nodes.data(), {static_cast<py::ssize_t>(nodes.size())}, self);
            },
            "The boundary nodes' mesh ids, sorted (int32, read-only view): the order of per-node motion arrays.")
        .def_property_readonly(
            "moving",
            [](py::object self) {
                const auto& flags = self.cast<const PyPlan&>().boundary.boundary.moving;
                py::array a(py::dtype("bool"), {static_cast<py::ssize_t>(flags.size())}, {}, flags.data(), self);
                py::detail::array_proxy(a.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
                return a;
            },
            "Per boundary node, whether it moves (bool, read-only view).")
        .def_property_readonly(
            "boundary_points",
            [](const PyPlan& p) {
                const Mesh& mesh = p.mesh->mesh;
                const auto& nodes = p.boundary.boundary.nodes;
                const auto dim = static_cast<std::size_t>(mesh.dim);
                py::array_t<double> a({static_cast<py::ssize_t>(nodes.size()), static_cast<py::ssize_t>(dim)});
                double* d = a.mutable_data();
                for (NodeId n : nodes)
                    for (std::size_t k = 0; k < dim; ++k) *d++ = mesh.points[static_cast<std::size_t>(n) * dim + k];
                return a;
            },
            "The boundary nodes' original coordinates, (n_boundary, dim) (a copy).")
        .def_property_readonly("moving_markers", [](const PyPlan& p) { return p.boundary.moving_markers; },
                               "The markers that move, in mesh order.")
        .def_property_readonly("static_markers", [](const PyPlan& p) { return p.boundary.static_markers; },
                               "The markers that stay, in mesh order.")
        .def_property_readonly("sliding_markers", [](const PyPlan& p) { return p.boundary.sliding_markers; },
                               "The markers that slide (named so, or by their type in the mesh file: OpenFOAM's\n"
                               "empty and symmetryPlane patches, CGNS's BCSymmetryPlane), in mesh order.")
        .def_property_readonly("cyclic_markers", [](const PyPlan& p) { return p.boundary.cyclic_markers; },
                               "The markers coupled to a partner (named so, or OpenFOAM's cyclic patches), in mesh order.")
        .def_property_readonly("shared_nodes", [](const PyPlan& p) { return std::string(shared_nodes_name(p.shared_nodes)); },
                               "What nodes on a moving and a static marker do: 'moving_wins' or 'static_wins'.")
        .def_property_readonly("memory_bytes", [](const PyPlan& p) {
            return p.distributed ? distributed_bytes(*p.distributed) : plan_memory_bytes(p.plan); },
                               "Bytes held by the plan's arrays.")
        .def_property_readonly(
            "summary",
            [](const PyPlan& p) {
                const PlanSummary s = plan_summary(plan_of(p));
                py::dict d;
                d["graph_simplices"] = s.graph_simplices;
                d["outside_hull"] = s.outside_hull;
                d["shared_vertices"] = s.shared_vertices;
                d["coarse_points"] = s.coarse_points;
                d["floored_weights"] = s.floored_weights;
                py::dict phases;
                for (const auto& [name, seconds] : s.phase_seconds) phases[py::str(name)] = seconds;
                d["phase_seconds"] = phases;
                return d;
            },
            "What the plan holds (graph simplices, volume nodes outside the graph's hull, shared graph vertices,\n"
            "coarse points) and how long each prepare phase took (empty for a loaded plan).")
        .def(py::pickle([](const PyPlan& p) { return plan_state(p); },
                        [](const py::tuple& state) { return plan_from_state(state); }))
        .def("__repr__", [](const PyPlan& p) {
            std::string moving;
            for (const auto& name : p.boundary.moving_markers) moving += (moving.empty() ? "" : ", ") + name;
            return "dgwarp.Plan(" + std::string(method_name(plan_method(plan_of(p)))) + ", " +
                   std::to_string(p.mesh->mesh.num_points()) + " nodes, " +
                   std::to_string(p.boundary.boundary.nodes.size()) + " boundary nodes, moving: " +
                   (moving.empty() ? "none" : moving) + ")";
        });

    m.def("prepare", &prepare_plan, py::arg("mesh").none(false), py::arg("moving"), py::arg("static") = py::none(),
          py::arg("method") = "dg-harmonic", py::kw_only(), py::arg("shared_nodes") = "moving_wins",
          py::arg("shared_tolerance") = 0.0, py::arg("progress") = py::none(), py::arg("comm") = py::none(),
          py::arg("global_ids") = py::none(),
          "Prepares `method`'s plan for `mesh`, once; Plan.deform then moves the mesh every step.\n"
          "  moving: the markers that move (a list of names, or one name), or a motion (dict or\n"
          "          dgwarp.Motion: the markers it moves, as `dgwarp prepare -m` classifies them);\n"
          "  static: the markers that stay (default: every other marker); every marker's nodes are\n"
          "          boundary nodes, so the two lists must cover all markers;\n"
          "  method: 'dg-harmonic' (default: the robust method), 'dg-idw', 'dgm', 'idw', 'rbf';\n"
          "  shared_nodes: 'moving_wins' (default) or 'static_wins': what nodes on a moving and a\n"
          "          static marker do; shared_tolerance as in motion files (0: 1e-9 x the diagonal);\n"
          "  progress: a callable taking the fraction done;\n"
          "  comm, global_ids: an mpi4py communicator and each local node's id in the whole mesh: `mesh`\n"
          "          is then this process's part, prepared and stepped collectively with the others\n"
          "          (bit-identical to one process; no untangle, report, save or pickle);\n"
          "  **options: the method's options, named as the CLI's flags with '_' for '-':\n"
          "          dg-idw: a_translation, a_rotation, length_scale (a number or 'auto'),\n"
          "          dg_idw_weights ('paper' or 'continuous'); dgm: dgm_substep (bool); idw:\n"
          "          idw_moving_exponent, idw_static_exponent; rbf: rbf_radius, rbf_greedy;\n"
          "          dg-harmonic: harmonic_wall_spacing, harmonic_growth, harmonic_redo_below (its guard:\n"
          "          a step below this fraction of the original minimum quality, or that inverts a cell,\n"
          "          is solved again by laplacian; -1: never); laplacian: laplacian_increments,\n"
          "          laplacian_exponent, laplacian_model ('elasticity' or 'laplacian').\n"
          "The GIL is released while the plan is built. Raises MeshError for an unknown marker or a\n"
          "degenerate boundary, InputError (ValueError) for an option out of range, ValueError for an\n"
          "option of another method, TypeError for an unknown keyword.");

    m.def("load_plan", &load_plan_file, py::arg("path"), py::arg("mesh").none(false), py::arg("moving") = py::none(),
          py::arg("static") = py::none(), py::kw_only(), py::arg("shared_nodes") = "moving_wins",
          py::arg("shared_tolerance") = 0.0, py::arg("comm") = py::none(), py::arg("global_ids") = py::none(),
          "Reads a plan saved by Plan.save (or `dgwarp prepare`) for `mesh`, checked to be for this mesh\n"
          "(MeshError otherwise). The moving markers are the markers all of whose nodes the plan moves;\n"
          "give `moving` (and `static`, `shared_nodes`) when the plan was prepared otherwise. The plan\n"
          "keeps its method and options. Raises IoError, ParseError for a damaged file. With comm= and\n"
          "global_ids (collective), this process's part of a plan saved by Plan.save of a plan prepared with\n"
          "comm=: give `moving`; the same number of processes and the same parts (MeshError otherwise).");
}

}  // namespace dgwarp::python
