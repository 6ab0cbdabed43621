#include "py_step_motion.hpp"

#include <algorithm>

#include "arrays.hpp"
#include "dgwarp/core/error.hpp"
#include "dgwarp/quality/mesh_quality.hpp"
#include "py_options.hpp"

namespace py = pybind11;

namespace dgwarp::python {

const OriginalCells& PyPlan::original() const {
    std::call_once(original_once_, [this] { original_ = measure_original(mesh->mesh); });
    return original_;
}

ResolvedFrame resolve_motion_frame(const PyPlan& p, const MotionSpec& spec, std::size_t frame) {
    const std::size_t frames = frame_count(spec);
    if (frame >= frames)
        throw py::index_error("frame " + std::to_string(frame) + " of a motion with " + std::to_string(frames) +
                              " frame" + (frames == 1 ? "" : "s"));
    if (spec.shared_nodes != p.shared_nodes)
        throw py::value_error("the motion's shared_nodes is '" + std::string(shared_nodes_name(spec.shared_nodes)) +
                              "'; the plan was prepared with '" + shared_nodes_name(p.shared_nodes) + "'");
    const Mesh& mesh = p.mesh->mesh;
    check_marker_names(mesh, spec);
    const MotionFrame& f = frame_spec(spec, frame);
    const std::string source = spec.source.empty() ? std::string("motion") : spec.source;
    const SeriesContext& c = p.boundary.context;
    for (std::size_t m = 0; m < mesh.markers.size(); ++m) {
        const std::string& name = mesh.markers[m].name;
        const MarkerMotion& motion = marker_motion(spec, f, name);
        if (std::holds_alternative<FixedMotion>(motion) || c.marker_moving[m]) continue;
        // A sliding or cyclic marker of the plan: the step's motion may say so again (or leave it out).
        if (c.marker_sliding[m] && std::holds_alternative<SlideMotion>(motion)) continue;
        if (c.marker_cyclic[m] && std::holds_alternative<CyclicMotion>(motion)) continue;
        const char* held = c.marker_sliding[m] ? "sliding" : c.marker_cyclic[m] ? "cyclic" : "static";
        if (std::holds_alternative<SlideMotion>(motion) || std::holds_alternative<CyclicMotion>(motion))
            throw MeshError(source + " makes marker '" + name + "' " + motion_kind_name(motion) +
                                ", which the plan holds " + held +
                                "; prepare the plan with a motion that makes it " + motion_kind_name(motion),
                            name);
        throw MeshError(source + " moves marker '" + name + "', which the plan holds " + held +
                            "; prepare the plan with it among the moving markers",
                        name);
    }
    return resolve_frame(mesh, spec, p.boundary, frame);
}

BoundaryMotion motion_from_arrays(const PyPlan& p, py::handle t, py::handle w, py::handle c) {
    const BoundarySet& b = p.boundary.boundary;
    const auto n = static_cast<py::ssize_t>(b.nodes.size());
    const int dim = p.mesh->mesh.dim;
    BoundaryMotion motion(b.nodes.size());
    // Fills component `field` of every boundary node from `obj` (rows of `width` values, 2 or 3).
    const auto fill = [&](py::handle obj, const char* name, Vec3 NodeMotion::*field, bool moving_only) {
        if (obj.is_none()) return;
        const py::array a = float_array(obj, name);
        const py::ssize_t alt = field == &NodeMotion::rotation ? 0 : dim;
        if (a.ndim() == 1) {
            const auto v = float_vector(a, name, 3, alt);
            Vec3 value{};
            std::copy(v.data(), v.data() + v.size(), value.begin());
            for (std::size_t i = 0; i < motion.size(); ++i)
                if (b.moving[i] || !moving_only) motion[i].*field = value;
            return;
        }
        const auto v = float_matrix(a, name, n, 3, alt);
        const auto width = static_cast<std::size_t>(v.shape(1));
        const double* d = v.data();
        for (std::size_t i = 0; i < motion.size(); ++i) {
            Vec3& value = motion[i].*field;
            for (std::size_t k = 0; k < width; ++k) value[k] = d[i * width + k];
            if (moving_only && !b.moving[i] && value != Vec3{})
                throw py::value_error(std::string(name) + "[" + std::to_string(i) + "] is not zero, but boundary node " +
                                      std::to_string(i) + " (mesh node " + std::to_string(b.nodes[i]) +
                                      ") is static; static nodes' rows must be zero (Plan.moving says which move)");
        }
    };
    fill(t, "translation", &NodeMotion::translation, true);
    fill(w, "rotation", &NodeMotion::rotation, true);
    fill(c, "center", &NodeMotion::center, false);
    if (dim == 2)
        for (std::size_t i = 0; i < motion.size(); ++i) {
            if (motion[i].rotation[0] != 0 || motion[i].rotation[1] != 0)
                throw py::value_error("rotation of boundary node " + std::to_string(i) +
                                      ": a 2D mesh turns about z only (rotation vector (0, 0, angle))");
            if (motion[i].translation[2] != 0)
                throw py::value_error("translation of boundary node " + std::to_string(i) +
                                      ": a 2D mesh moves in the xy plane only (z = 0)");
        }
    return motion;
}

bool finish_step(const PyPlan& p, std::span<double> points, const py::object& untangle, double target, bool measure,
                 FrameReport& report, std::optional<FrameCells> measured) {
    FrameOptions options;
    options.untangle_target = target;
    if (!untangle.is_none()) options.repair = untangle.cast<bool>() ? Repair::untangle : Repair::none;
    const Method method = plan_method(plan_of(p));
    const bool repairs = options.repair == Repair::untangle ||
                         (options.repair == Repair::method_default && method == Method::dg_harmonic);
    if (!repairs && !measure) return false;
    const Mesh& mesh = p.mesh->mesh;
    py::gil_scoped_release release;
    finish_frame(method, mesh, p.original(), p.boundary.boundary.nodes, options, points, report, {}, std::move(measured));
    return true;
}

}  // namespace dgwarp::python
