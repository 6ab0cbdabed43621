#include "dgwarp/motion/planar_motion.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>

#include "dgwarp/core/error.hpp"

namespace dgwarp {

namespace {

std::string text(double x) {
    std::ostringstream s;
    s << x;
    return s.str();
}

double norm(const Vec3& a) { return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]); }

/// Maps one marker's motion; `size` is the mesh's bounding-box diagonal.
class MotionMap {
public:
    MotionMap(const PlanarCase& planar, double size) : planar_(planar), size_(size) {}

    MarkerMotion operator()(const std::string& marker, const MarkerMotion& motion) const {
        marker_ = &marker;
        return std::visit([&](const auto& m) -> MarkerMotion { return map(m); }, motion);
    }

private:
    MarkerMotion map(const FixedMotion& m) const { return m; }
    MarkerMotion map(const SlideMotion& m) const { return m; }
    MarkerMotion map(const CyclicMotion& m) const { return m; }  // the 2D markers keep their names
    MarkerMotion map(const RigidMotion& m) const { return RigidMotion{common_motion(m.motion)}; }
    MarkerMotion map(const PeriodicMotion& m) const {
        PeriodicMotion out = m;
        if (out.pitch) {
            const double along = axis_along_normal(out.pitch->axis);
            out.pitch->axis = {0, 0, along > 0 ? 1.0 : -1.0};
            out.pitch->center = point(out.pitch->center);
        }
        if (out.plunge) out.plunge->amplitude = common_vector(out.plunge->amplitude, "plunge amplitude");
        return out;
    }
    MarkerMotion map(const PrescribedDisplacements& m) const {
        return PrescribedDisplacements{
            table(m.displacements, [&](const Vec3& d, bool second) { return vector(d, "displacement", second); })};
    }
    MarkerMotion map(const PrescribedPositions& m) const {
        return PrescribedPositions{table(m.positions, [&](const Vec3& p, bool second) { return point(p, second); })};
    }
    MarkerMotion map(const PrescribedNodeMotions& m) const {
        return PrescribedNodeMotions{
            table(m.motions, [&](const NodeMotion& n, bool second) { return node_motion(n, second); })};
    }

    [[noreturn]] void out_of_plane(const std::string& what) const {
        throw MeshError("marker '" + *marker_ + "': " + what + "; a 2D case (its planes: marker" +
                            (planar_.plane_markers.size() == 1 ? " '" : "s '") + joined() +
                            "') moves in its planes only",
                        *marker_);
    }

    std::string joined() const {
        std::string s;
        for (const auto& n : planar_.plane_markers) s += (s.empty() ? "" : "', '") + n;
        return s;
    }

    Vec3 point(const Vec3& x, bool second = false) const {
        const auto p = planar_point(planar_, x, second);
        return {p[0], p[1], 0};
    }

    /// A vector at a node of the first plane (`second`: of the second); an
    /// error when it leaves the plane.
    Vec3 vector(const Vec3& d, const char* what, bool second = false) const {
        double along = 0;
        const auto v = planar_vector(planar_, d, second, &along);
        if (std::abs(along) > 1e-9 * (size_ + norm(d)))
            out_of_plane(std::string("its ") + what + " has a component " + text(along) + " along the normal of " +
                         (planar_.wedge ? "a wedge plane" : "the planes"));
        return {v[0], v[1], 0};
    }

    /// The same vector at every node: in both planes, alike in both (a wedge: along its axis).
    Vec3 common_vector(const Vec3& d, const char* what) const {
        const Vec3 first = vector(d, what), second = vector(d, what, true);
        if (!alike(first, second)) out_of_plane(std::string("its ") + what + " is not along the wedge's axis");
        return first;
    }

    /// +1 or -1: the axis's direction along the normal; an error when it is
    /// another axis (always for a wedge: no rotation keeps both its planes).
    double axis_along_normal(const Vec3& w) const {
        double along = 0;
        const auto in = planar_vector(planar_, w, false, &along);
        if (planar_.wedge || std::hypot(in[0], in[1]) > 1e-9 * norm(w))
            out_of_plane(planar_.wedge ? "it turns, which an axisymmetric case cannot"
                                       : "it turns about an axis that is not the planes' normal");
        return along;
    }

    NodeMotion node_motion(const NodeMotion& m, bool second) const {
        NodeMotion out;
        out.translation = vector(m.translation, "translation", second);
        if (norm(m.rotation) > 0) out.rotation = {0, 0, axis_along_normal(m.rotation) > 0 ? norm(m.rotation) : -norm(m.rotation)};
        out.center = point(m.center, second);
        return out;
    }

    NodeMotion common_motion(const NodeMotion& m) const {
        NodeMotion out;
        out.translation = common_vector(m.translation, "translation");
        if (norm(m.rotation) > 0) out.rotation = {0, 0, axis_along_normal(m.rotation) > 0 ? norm(m.rotation) : -norm(m.rotation)};
        out.center = point(m.center);
        return out;
    }

    template <class Value, class Map>
    NodeTable<Value> table(const NodeTable<Value>& t, const Map& value) const {
        NodeTable<Value> out;
        out.components = 2;
        out.source = t.source;
        std::vector<std::size_t> order(t.nodes.size());
        std::iota(order.begin(), order.end(), 0);
        const auto num = static_cast<NodeId>(planar_.node_2d.size());
        for (NodeId n : t.nodes)
            if (n < 0 || n >= num)
                throw MeshError("marker '" + *marker_ + "': node " + std::to_string(n) + " in " +
                                    (t.source.empty() ? std::string("the node table") : t.source) +
                                    " is not a node of the mesh, which has " + std::to_string(num) + " nodes (ids 0-based)",
                                *marker_, n);
        const auto two_d = [&](std::size_t e) { return planar_.node_2d[static_cast<std::size_t>(t.nodes[e])]; };
        std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return two_d(a) < two_d(b); });
        for (std::size_t i = 0; i < order.size(); ++i) {
            const std::size_t e = order[i];
            const Value mapped = value(t.values[e], planar_.side[static_cast<std::size_t>(t.nodes[e])] == 2);
            if (!out.nodes.empty() && out.nodes.back() == two_d(e)) {
                // A node and its twin: alike.
                if (!alike(out.values.back(), mapped))
                    throw MeshError("marker '" + *marker_ + "': nodes " + std::to_string(t.nodes[order[i - 1]]) + " and " +
                                        std::to_string(t.nodes[e]) + " in " +
                                        (t.source.empty() ? std::string("the node table") : t.source) +
                                        " are twins across the 2D case's layer but move differently",
                                    *marker_, t.nodes[e]);
                continue;
            }
            out.nodes.push_back(two_d(e));
            out.values.push_back(mapped);
            if (!t.lines.empty()) out.lines.push_back(t.lines[e]);
        }
        return out;
    }

    bool alike(const Vec3& a, const Vec3& b) const {
        return std::hypot(a[0] - b[0], a[1] - b[1]) <= 1e-9 * size_;
    }
    bool alike(const NodeMotion& a, const NodeMotion& b) const {
        return alike(a.translation, b.translation) && a.rotation == b.rotation && alike(a.center, b.center);
    }

    const PlanarCase& planar_;
    double size_;
    mutable const std::string* marker_ = nullptr;
};

}  // namespace

MotionSpec planar_motion(const PlanarCase& planar, const Mesh& mesh, const MotionSpec& spec) {
    const BoundingBox box = bounding_box(mesh);
    const MotionMap map(planar, std::hypot(box.max[0] - box.min[0], box.max[1] - box.min[1], box.max[2] - box.min[2]));
    const auto is_plane = [&](const std::string& name) {
        return std::find(planar.plane_markers.begin(), planar.plane_markers.end(), name) != planar.plane_markers.end();
    };
    MotionSpec out = spec;
    out.default_motion = map("(default)", spec.default_motion);
    // A wedge's axis slides along it unless the motion names it.
    const bool axis_named = std::any_of(spec.frames.begin(), spec.frames.end(), [&](const MotionFrame& f) {
        return f.markers.count(planar.axis_marker) > 0;
    });
    for (std::size_t k = 0; k < spec.frames.size(); ++k) {
        out.frames[k].markers.clear();
        for (const auto& [name, motion] : spec.frames[k].markers) {
            if (is_plane(name)) {
                if (!std::holds_alternative<SlideMotion>(motion))
                    throw MeshError("marker '" + name + "' is a plane of the 2D case: it slides", name);
                continue;
            }
            out.frames[k].markers.emplace(name, map(name, motion));
        }
        if (!planar.axis_marker.empty() && !axis_named) out.frames[k].markers.emplace(planar.axis_marker, SlideMotion{});
    }
    return out;
}

}  // namespace dgwarp
