#include "dgwarp/motion/resolve_motion.hpp"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <sstream>
#include <utility>

#include "dgwarp/core/error.hpp"
#include "dgwarp/graph/coincident_points.hpp"
#include "dgwarp/motion/marker_node_motions.hpp"

namespace dgwarp {

namespace {

/// One frame's view: the mesh, the spec and what their frames share.
struct Context {
    const Mesh& mesh;
    const MotionSpec& spec;
    const SeriesContext& series;
    const BoundarySet& boundary;
};

std::string where(const MotionSpec& spec, std::size_t frame) {
    std::string w = spec.source.empty() ? std::string("motion") : spec.source;
    if (frame_count(spec) > 1) w += ", frame " + std::to_string(frame);
    return w;
}

std::string point_text(std::span<const double> p) {
    std::ostringstream s;
    s << "(";
    for (std::size_t i = 0; i < p.size(); ++i) s << (i ? ", " : "") << p[i];
    s << ")";
    return s.str();
}

double bounding_box_diagonal(const Mesh& mesh) {
    const auto dim = static_cast<std::size_t>(mesh.dim);
    if (mesh.num_points() == 0) return 0;
    double sum = 0;
    for (std::size_t i = 0; i < dim; ++i) {
        double lo = std::numeric_limits<double>::infinity(), hi = -lo;
        for (std::size_t p = i; p < mesh.points.size(); p += dim) {
            lo = std::min(lo, mesh.points[p]);
            hi = std::max(hi, mesh.points[p]);
        }
        sum += (hi - lo) * (hi - lo);
    }
    return std::sqrt(sum);
}

std::span<const double> point(const Mesh& mesh, NodeId node) {
    const auto dim = static_cast<std::size_t>(mesh.dim);
    return {mesh.points.data() + static_cast<std::size_t>(node) * dim, dim};
}

/// The series context and the boundary set of (mesh, spec), and per boundary
/// node whether it is on a static and on a moving marker.
struct Series {
    SeriesContext context;
    BoundarySet boundary;
    std::vector<char> on_static, on_moving;
    SlideSet slides;
};

/// Whether marker m slides: SlideMotion in every frame. Throws MeshError
/// when it slides in some frames only.
bool marker_slides(const MotionSpec& spec, const std::string& name) {
    std::size_t sliding = 0;
    for (const MotionFrame& frame : spec.frames)
        sliding += std::holds_alternative<SlideMotion>(marker_motion(spec, frame, name));
    if (sliding > 0 && sliding < spec.frames.size())
        throw MeshError((spec.source.empty() ? std::string("motion") : spec.source) + ": marker '" + name +
                            "' slides in " + std::to_string(sliding) + " of the " + std::to_string(spec.frames.size()) +
                            " frames: a sliding marker slides in every frame",
                        name);
    return sliding > 0;
}

/// Marker m's partner when it is cyclic (CyclicMotion in every frame, the
/// same partner, which names it back), else -1. Throws MeshError naming the
/// marker when it is cyclic in some frames only, with different partners, or
/// with a partner that is not cyclic with it.
std::int64_t cyclic_partner(const Mesh& mesh, const MotionSpec& spec, std::size_t m) {
    const std::string& name = mesh.markers[m].name;
    const std::string at = spec.source.empty() ? std::string("motion") : spec.source;
    std::size_t cyclic = 0;
    std::string partner;
    for (const MotionFrame& frame : spec.frames) {
        const auto* c = std::get_if<CyclicMotion>(&marker_motion(spec, frame, name));
        if (!c) continue;
        if (cyclic > 0 && c->partner != partner)
            throw MeshError(at + ": marker '" + name + "' is cyclic with '" + partner + "' and with '" + c->partner +
                                "': a cyclic marker has one partner in every frame",
                            name);
        partner = c->partner;
        ++cyclic;
    }
    if (cyclic == 0) return -1;
    if (cyclic < spec.frames.size())
        throw MeshError(at + ": marker '" + name + "' is cyclic in " + std::to_string(cyclic) + " of the " +
                            std::to_string(spec.frames.size()) + " frames: a cyclic marker is cyclic in every frame",
                        name);
    const auto it = std::find_if(mesh.markers.begin(), mesh.markers.end(),
                                 [&](const Marker& k) { return k.name == partner; });
    if (it == mesh.markers.end() || partner == name)
        throw MeshError(at + ": marker '" + name + "' is cyclic with '" + partner + "', " +
                            (partner == name ? "itself" : "which the mesh does not have") +
                            ": the partner is the marker that is the other half of the periodic boundary",
                        name);
    for (const MotionFrame& frame : spec.frames) {
        const auto* back = std::get_if<CyclicMotion>(&marker_motion(spec, frame, partner));
        if (!back || back->partner != name)
            throw MeshError(at + ": marker '" + name + "' is cyclic with '" + partner + "', but '" + partner + "' is " +
                                (back ? "cyclic with '" + back->partner + "'" : std::string("not cyclic")) +
                                ": both halves of a periodic boundary name each other ({\"cyclic\": \"" + name +
                                "\"} for '" + partner + "')",
                            name);
    }
    return it - mesh.markers.begin();
}

/// Adds `nodes` (sorted, none of them in `slides`) to `slides` as free nodes
/// (planes 0), keeping the nodes sorted.
void add_free_nodes(SlideSet& slides, const Mesh& mesh, const std::vector<NodeId>& nodes) {
    const auto dim = static_cast<std::size_t>(mesh.dim);
    SlideSet out;
    std::size_t i = 0, j = 0;
    while (i < slides.nodes.size() || j < nodes.size()) {
        const bool take_slide = j == nodes.size() || (i < slides.nodes.size() && slides.nodes[i] < nodes[j]);
        const NodeId node = take_slide ? slides.nodes[i] : nodes[j];
        out.nodes.push_back(node);
        if (take_slide) {
            out.planes.push_back(slides.planes[i]);
            out.directions.insert(out.directions.end(), slides.directions.begin() + static_cast<std::ptrdiff_t>(3 * i),
                                  slides.directions.begin() + static_cast<std::ptrdiff_t>(3 * i + 3));
            ++i;
        } else {
            out.planes.push_back(0);
            out.directions.insert(out.directions.end(), {0.0, 0.0, 0.0});
            ++j;
        }
        const double* x = mesh.points.data() + static_cast<std::size_t>(node) * dim;
        out.origins.insert(out.origins.end(), x, x + dim);
    }
    slides = std::move(out);
}

Series make_series(const Mesh& mesh, const MotionSpec& spec) {
    check_marker_names(mesh, spec);
    Series s;
    SeriesContext& c = s.context;
    const std::size_t n_markers = mesh.markers.size();
    c.marker_nodes.reserve(n_markers);
    for (const Marker& m : mesh.markers) c.marker_nodes.push_back(marker_nodes(m));
    c.marker_moving.assign(n_markers, 0);
    c.marker_sliding.assign(n_markers, 0);
    c.marker_cyclic.assign(n_markers, 0);
    std::vector<std::size_t> sliding;
    std::vector<CyclicPair> pairs;
    for (std::size_t m = 0; m < n_markers; ++m) {
        if (marker_slides(spec, mesh.markers[m].name)) {
            c.marker_sliding[m] = 1;
            sliding.push_back(m);
            continue;
        }
        if (const std::int64_t partner = cyclic_partner(mesh, spec, m); partner >= 0) {
            c.marker_cyclic[m] = 1;
            if (static_cast<std::size_t>(partner) > m) pairs.push_back({m, static_cast<std::size_t>(partner)});
            continue;
        }
        for (const MotionFrame& frame : spec.frames)
            if (!std::holds_alternative<FixedMotion>(marker_motion(spec, frame, mesh.markers[m].name)))
                c.marker_moving[m] = 1;
    }

    BoundarySet& boundary = s.boundary;
    for (const auto& nodes : c.marker_nodes) boundary.nodes.insert(boundary.nodes.end(), nodes.begin(), nodes.end());
    std::sort(boundary.nodes.begin(), boundary.nodes.end());
    boundary.nodes.erase(std::unique(boundary.nodes.begin(), boundary.nodes.end()), boundary.nodes.end());
    const std::size_t n = boundary.nodes.size();
    s.on_static.assign(n, 0);
    s.on_moving.assign(n, 0);
    c.slots.resize(n_markers);
    for (std::size_t m = 0; m < n_markers; ++m) {
        c.slots[m].reserve(c.marker_nodes[m].size());
        for (NodeId node : c.marker_nodes[m]) {
            const auto slot = static_cast<std::int32_t>(
                std::lower_bound(boundary.nodes.begin(), boundary.nodes.end(), node) - boundary.nodes.begin());
            c.slots[m].push_back(slot);
            if (!c.marker_sliding[m] && !c.marker_cyclic[m])
                (c.marker_moving[m] ? s.on_moving : s.on_static)[static_cast<std::size_t>(slot)] = 1;
        }
    }
    boundary.moving.resize(n);
    for (std::size_t b = 0; b < n; ++b)
        boundary.moving[b] =
            s.on_moving[b] && !(spec.shared_nodes == SharedNodeRule::static_wins && s.on_static[b]) ? 1 : 0;
    // The sliding nodes: on sliding markers only, and not at a corner (which
    // stays: neither moving nor static markers hold it, so it is static).
    // They move, by the motion the step's first pass gives them (SlidePass).
    // The cyclic markers' nodes on no other marker move too, as free sliding
    // nodes, coupled to their images (cyclic_pairs.hpp).
    if (!sliding.empty() || !pairs.empty()) {
        std::vector<NodeId> held;
        for (std::size_t b = 0; b < n; ++b)
            if (s.on_moving[b] || s.on_static[b]) held.push_back(boundary.nodes[b]);
        SlidePlanes planes = sliding.empty() ? SlidePlanes{} : slide_planes(mesh, sliding, held);
        s.slides = std::move(planes.slides);
        if (!pairs.empty()) {
            std::vector<NodeId> free;
            for (std::size_t m = 0; m < n_markers; ++m)
                if (c.marker_cyclic[m]) free.insert(free.end(), c.marker_nodes[m].begin(), c.marker_nodes[m].end());
            std::sort(free.begin(), free.end());
            free.erase(std::unique(free.begin(), free.end()), free.end());
            std::erase_if(free, [&](NodeId node) {
                const auto in = [node](const std::vector<NodeId>& v) { return std::binary_search(v.begin(), v.end(), node); };
                return in(held) || in(s.slides.nodes) || in(planes.corners);
            });
            add_free_nodes(s.slides, mesh, free);
        }
        s.slides.slots.reserve(s.slides.size());
        for (const NodeId node : s.slides.nodes) {
            const auto b = static_cast<std::size_t>(
                std::lower_bound(boundary.nodes.begin(), boundary.nodes.end(), node) - boundary.nodes.begin());
            s.slides.slots.push_back(static_cast<std::int32_t>(b));
            boundary.moving[b] = 1;
        }
        if (!pairs.empty()) {
            CyclicGroups& g = s.slides.cyclic;
            g = cyclic_groups(mesh, pairs);
            for (const NodeId node : g.nodes) {
                g.slots.push_back(static_cast<std::int32_t>(
                    std::lower_bound(boundary.nodes.begin(), boundary.nodes.end(), node) - boundary.nodes.begin()));
                const auto at = std::lower_bound(s.slides.nodes.begin(), s.slides.nodes.end(), node);
                g.slide.push_back(at != s.slides.nodes.end() && *at == node
                                      ? static_cast<std::int32_t>(at - s.slides.nodes.begin())
                                      : -1);
                const std::span<const double> x = point(mesh, node);
                g.origins.insert(g.origins.end(), {x[0], x[1], x.size() == 3 ? x[2] : 0.0});
            }
        }
    }
    c.diagonal = bounding_box_diagonal(mesh);
    c.tolerance = spec.shared_tolerance > 0 ? spec.shared_tolerance : 1e-9 * c.diagonal;
    return s;
}

/// Whether two motions of node x agree: equal, or the same new position within tol.
bool agree(const NodeMotion& a, const NodeMotion& b, std::span<const double> x, double tol) {
    if (a == b) return true;
    double pa[3], pb[3];
    apply_motion(a, x, pa);
    apply_motion(b, x, pb);
    double d2 = 0;
    for (std::size_t i = 0; i < x.size(); ++i) d2 += (pa[i] - pb[i]) * (pa[i] - pb[i]);
    return std::sqrt(d2) <= tol;
}

using NodeMotions = std::vector<std::vector<NodeMotion>>;  // per marker, per node of the marker

/// Node j of moving marker m's motion (zero when the marker has none in this frame).
const NodeMotion& node_motion(const NodeMotions& motions, std::size_t m, std::size_t j) {
    static const NodeMotion zero{};
    return motions[m].empty() ? zero : motions[m][j];
}

/// Per boundary node, the motion of the first moving marker on it (`from`:
/// that marker, -1 when none) and the first moving marker whose motion
/// disagrees with it (`clash`, -1 when none).
struct FirstMotions {
    BoundaryMotion motion;
    std::vector<std::int32_t> from, clash;
};

FirstMotions first_motions(const Context& c, const NodeMotions& motions) {
    const std::size_t n = c.boundary.nodes.size();
    FirstMotions f{BoundaryMotion(n), std::vector<std::int32_t>(n, -1), std::vector<std::int32_t>(n, -1)};
    for (std::size_t m = 0; m < c.mesh.markers.size(); ++m) {
        if (!c.series.marker_moving[m]) continue;
        for (std::size_t j = 0; j < c.series.marker_nodes[m].size(); ++j) {
            const NodeMotion& nm = node_motion(motions, m, j);
            const auto b = static_cast<std::size_t>(c.series.slots[m][j]);
            if (f.from[b] < 0) {
                f.motion[b] = nm;
                f.from[b] = static_cast<std::int32_t>(m);
            } else if (f.clash[b] < 0 && !agree(f.motion[b], nm, point(c.mesh, c.series.marker_nodes[m][j]),
                                                c.series.tolerance)) {
                f.clash[b] = static_cast<std::int32_t>(m);
            }
        }
    }
    return f;
}

/// Warnings for the moving markers that turn by more than 180 degrees in one
/// step, or move a node farther than the mesh's bounding-box diagonal.
void warn_large_motions(const Context& c, const NodeMotions& motions, const std::string& at,
                        std::vector<Warning>& warnings) {
    const Mesh& mesh = c.mesh;
    for (std::size_t m = 0; m < mesh.markers.size(); ++m) {
        if (!c.series.marker_moving[m]) continue;
        double largest = 0, largest_angle = 0;
        NodeId largest_node = -1;
        for (std::size_t j = 0; j < c.series.marker_nodes[m].size(); ++j) {
            const NodeMotion& nm = node_motion(motions, m, j);
            const NodeId node = c.series.marker_nodes[m][j];
            const auto x = point(mesh, node);
            double moved[3], d2 = 0;
            apply_motion(nm, x, moved);
            for (std::size_t i = 0; i < x.size(); ++i) d2 += (moved[i] - x[i]) * (moved[i] - x[i]);
            if (d2 > largest * largest) {
                largest = std::sqrt(d2);
                largest_node = node;
            }
            const Vec3& w = nm.rotation;
            largest_angle = std::max(largest_angle, std::sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]));
        }
        if (largest_angle > std::numbers::pi * (1 + 1e-12)) {
            std::ostringstream w;
            w << at << ": marker '" << mesh.markers[m].name << "' turns by " << largest_angle * 180 / std::numbers::pi
              << " degrees in one step; the methods interpolate the rotation vector (axis x angle), so a turn over "
                 "180 degrees is not the same as the shorter turn the other way: split it into frames";
            Warning warning{WarningCode::large_rotation, w.str(), mesh.markers[m].name};
            warning.value = largest_angle * 180 / std::numbers::pi;
            warnings.push_back(std::move(warning));
        }
        if (largest > c.series.diagonal && largest_node >= 0) {
            std::ostringstream w;
            w << at << ": marker '" << mesh.markers[m].name << "' moves node " << largest_node << " by " << largest
              << ", more than the diagonal of the mesh's bounding box (" << c.series.diagonal << ")";
            Warning warning{WarningCode::large_displacement, w.str(), mesh.markers[m].name};
            warning.node = largest_node;
            warning.value = largest;
            warnings.push_back(std::move(warning));
        }
    }
}

/// Throws MeshError when moving markers disagree on a moving node they share
/// (static nodes stay whatever their markers say), naming each pair of
/// markers, how many nodes and an example.
void refuse_disagreements(const Context& c, const FirstMotions& f, const NodeMotions& motions,
                          const std::string& at) {
    const Mesh& mesh = c.mesh;
    std::map<std::pair<std::int32_t, std::int32_t>, std::pair<std::size_t, std::size_t>> clashes;  // -> count, example
    for (std::size_t b = 0; b < c.boundary.nodes.size(); ++b) {
        if (!c.boundary.moving[b] || f.clash[b] < 0) continue;
        auto& entry = clashes[{f.from[b], f.clash[b]}];
        if (entry.first++ == 0) entry.second = b;
    }
    if (clashes.empty()) return;
    std::ostringstream e;
    e << at << ": moving markers disagree on the nodes they share (rule "
      << (c.spec.shared_nodes == SharedNodeRule::moving_wins ? "moving_wins" : "static_wins") << "):";
    for (const auto& [pair, entry] : clashes) {
        const std::size_t b = entry.second;
        const NodeId node = c.boundary.nodes[b];
        const auto x = point(mesh, node);
        const std::size_t m1 = static_cast<std::size_t>(pair.first), m2 = static_cast<std::size_t>(pair.second);
        const auto& nodes2 = c.series.marker_nodes[m2];
        const auto j2 = static_cast<std::size_t>(std::lower_bound(nodes2.begin(), nodes2.end(), node) - nodes2.begin());
        double p1[3], p2[3];
        apply_motion(f.motion[b], x, p1);
        apply_motion(node_motion(motions, m2, j2), x, p2);
        e << " markers '" << mesh.markers[m1].name << "' and '" << mesh.markers[m2].name << "' on " << entry.first
          << " node" << (entry.first == 1 ? "" : "s") << " (e.g. node " << node << " moves to "
          << point_text({p1, x.size()}) << " with '" << mesh.markers[m1].name << "' and to "
          << point_text({p2, x.size()}) << " with '" << mesh.markers[m2].name << "');";
    }
    std::string message = e.str();
    message.back() = '.';
    message += " Give the markers the same motion on the nodes they share (see shared_nodes in docs/MOTION.md).";
    const auto& [pair, entry] = *clashes.begin();
    throw MeshError(message, mesh.markers[static_cast<std::size_t>(pair.first)].name, c.boundary.nodes[entry.second]);
}

/// Throws MeshError when a moving marker gives a node a motion, or a new
/// position, that no method can compute with (motion_value_problem: not
/// finite, or beyond max_motion_value): every method would refuse the step,
/// so the resolution (which `check` runs too) refuses it, naming the marker
/// and the node.
void refuse_unusable_motions(const Context& c, const NodeMotions& motions, const std::string& at) {
    const Mesh& mesh = c.mesh;
    for (std::size_t m = 0; m < mesh.markers.size(); ++m) {
        if (!c.series.marker_moving[m]) continue;
        for (std::size_t j = 0; j < c.series.marker_nodes[m].size(); ++j) {
            const NodeMotion& nm = node_motion(motions, m, j);
            const NodeId node = c.series.marker_nodes[m][j];
            const auto x = point(mesh, node);
            std::string problem = motion_value_problem(nm);
            if (problem.empty()) {
                double moved[3] = {0, 0, 0};
                apply_motion(nm, x, moved);
                if (!std::all_of(moved, moved + x.size(), [](double v) { return std::fabs(v) <= max_motion_value; })) {
                    std::ostringstream e;
                    e << "it moves the node from " << point_text(x) << " to " << point_text({moved, x.size()})
                      << ", beyond " << max_motion_value << " in magnitude, more than the methods' double arithmetic holds";
                    problem = e.str();
                }
            }
            if (problem.empty()) continue;
            throw MeshError(at + ": marker '" + mesh.markers[m].name + "' cannot move node " + std::to_string(node) +
                                ": " + problem + "; give the motion in the mesh's units",
                            mesh.markers[m].name, node);
        }
    }
}

/// A warning when the boundary motion itself folds boundary faces: a face
/// whose moved normal (3D; in 2D its direction) points against its original
/// one turned by its nodes' mean rotation. No method can keep the cells on
/// such a face valid, and none of them is all-boundary, so the step's report
/// would not say so (issue #27: a face turned inside a rim held by
/// static_wins).
/// Returns the number of folded faces.
std::int64_t warn_folded_faces(const Context& c, const BoundaryMotion& motion, const std::string& at,
                               std::vector<Warning>& warnings) {
    const Mesh& mesh = c.mesh;
    const BoundarySet& boundary = c.boundary;
    if (std::none_of(boundary.moving.begin(), boundary.moving.end(), [](std::uint8_t m) { return m != 0; })) return 0;
    std::int64_t total = 0;
    const auto dim = static_cast<std::size_t>(mesh.dim);
    const std::vector<double> moved = moved_boundary_points(mesh, boundary, motion);
    using P = std::array<double, 3>;
    const auto sub = [](const P& a, const P& b) { return P{a[0] - b[0], a[1] - b[1], a[2] - b[2]}; };
    const auto cross = [](const P& a, const P& b) {
        return P{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    };
    // The face's normal (3D: triangle, or a quadrilateral's diagonals) or direction (2D).
    const auto normal = [&](const std::vector<P>& x) {
        if (x.size() == 2) return sub(x[1], x[0]);
        if (x.size() == 4) return cross(sub(x[2], x[0]), sub(x[3], x[1]));
        return cross(sub(x[1], x[0]), sub(x[2], x[0]));
    };
    for (std::size_t m = 0; m < mesh.markers.size(); ++m) {
        if (c.series.marker_sliding[m] || c.series.marker_cyclic[m]) continue;  // its faces move with the volume
        const ElementList& faces = mesh.markers[m].elements;
        std::size_t folded = 0, example = 0;
        std::vector<P> before, after;
        for (std::size_t f = 0; f < faces.size(); ++f) {
            const auto nodes = faces.nodes_of(f);
            before.clear();
            after.clear();
            Vec3 w{0, 0, 0};
            bool moves = false;
            for (NodeId n : nodes) {
                const auto b = static_cast<std::size_t>(
                    std::lower_bound(boundary.nodes.begin(), boundary.nodes.end(), n) - boundary.nodes.begin());
                moves = moves || boundary.moving[b];
                P x{0, 0, 0}, y{0, 0, 0};
                for (std::size_t d = 0; d < dim; ++d) {
                    x[d] = mesh.points[static_cast<std::size_t>(n) * dim + d];
                    y[d] = moved[b * dim + d];
                }
                before.push_back(x);
                after.push_back(y);
                for (int d = 0; d < 3; ++d) w[d] += motion[b].rotation[d] / static_cast<double>(nodes.size());
            }
            if (!moves || nodes.size() < 2 || nodes.size() > 4) continue;
            if (dim == 2) w[0] = w[1] = 0;
            const std::array<double, 9> r = rotation_matrix(w);
            const P n0 = normal(before), n1 = normal(after);
            const P turned{r[0] * n0[0] + r[1] * n0[1] + r[2] * n0[2], r[3] * n0[0] + r[4] * n0[1] + r[5] * n0[2],
                           r[6] * n0[0] + r[7] * n0[1] + r[8] * n0[2]};
            const double d = turned[0] * n1[0] + turned[1] * n1[1] + turned[2] * n1[2];
            if (d < 0 && folded++ == 0) example = f;  // turned over; edge-on (0) is not
        }
        if (folded == 0) continue;
        total += static_cast<std::int64_t>(folded);
        std::ostringstream w;
        w << at << ": the boundary motion itself folds " << folded << " of marker '" << mesh.markers[m].name
          << "''s " << faces.size() << " faces (e.g. its element " << example
          << "): they turn over against their nodes' rotation, so no method can keep the cells on them valid; "
             "change the motion (a moving marker held at a static rim by shared_nodes: static_wins does this, "
             "docs/MOTION.md)";
        Warning warning{WarningCode::boundary_folds_faces, w.str(), mesh.markers[m].name,
                        static_cast<std::int64_t>(folded)};
        warning.element = static_cast<std::int64_t>(example);
        warnings.push_back(std::move(warning));
    }
    return total;
}

/// Resolves one frame (see the header's rules). Appends warnings.
BoundaryMotion resolve_at(const Context& c, const MotionFrame& frame, double time, const std::string& at,
                          std::vector<Warning>& warnings, std::int64_t* folded_faces = nullptr) {
    const Mesh& mesh = c.mesh;
    std::vector<const MarkerMotion*> marker_motions(mesh.markers.size());
    for (std::size_t m = 0; m < mesh.markers.size(); ++m)
        marker_motions[m] = &marker_motion(c.spec, frame, mesh.markers[m].name);
    const NodeMotions motions = marker_node_motions(mesh, c.series.marker_nodes, marker_motions, time, at);

    refuse_unusable_motions(c, motions, at);
    FirstMotions f = first_motions(c, motions);
    warn_large_motions(c, motions, at, warnings);
    refuse_disagreements(c, f, motions, at);
    for (std::size_t b = 0; b < c.boundary.nodes.size(); ++b)
        if (!c.boundary.moving[b]) f.motion[b] = NodeMotion{};  // static nodes stay
    const std::int64_t folded = warn_folded_faces(c, f.motion, at, warnings);
    if (folded_faces) *folded_faces = folded;
    return std::move(f.motion);
}

/// A warning when other markers move nodes of a cyclic group (a node and its
/// images) differently, through their rotations: the two halves then cannot
/// stay images of each other.
void warn_cyclic_mismatch(const Mesh& mesh, const SlideSet& slides, double tolerance, const BoundaryMotion& motion,
                          const std::string& at, std::vector<Warning>& warnings) {
    const CyclicGroups& g = slides.cyclic;
    if (g.empty()) return;
    const CyclicVectors held = held_cyclic_displacements(g, mesh.dim, motion);
    NodeId node = -1;
    const std::int64_t count = cyclic_disagreements(g, held.vectors, held.held, tolerance, &node);
    if (count == 0) return;
    Warning w{WarningCode::cyclic_mismatch,
              at + ": on " + std::to_string(count) + (count == 1 ? " node" : " nodes") +
                  " of cyclic markers, other markers move the node and its image differently (e.g. node " +
                  std::to_string(node) +
                  "): each moves as its own markers say, so there the two halves of the periodic boundary no longer "
                  "match; give both halves' walls the same motion (through the rotation between the halves)",
              "", count};
    w.node = node;
    warnings.push_back(std::move(w));
}

/// Warnings for markers the motion file names that have no nodes in the mesh.
void warn_empty_named_markers(const Context& c, std::vector<Warning>& warnings) {
    for (std::size_t m = 0; m < c.mesh.markers.size(); ++m) {
        if (!c.series.marker_nodes[m].empty()) continue;
        const std::string& name = c.mesh.markers[m].name;
        const bool named = std::any_of(c.spec.frames.begin(), c.spec.frames.end(),
                                       [&](const MotionFrame& f) { return f.markers.count(name) > 0; });
        if (named)
            warnings.push_back({WarningCode::empty_named_marker,
                                where(c.spec, 0) + " names marker '" + name +
                                    "', which has no elements in the mesh (an empty marker, such as SU2's "
                                    "MARKER_ELEMS= 0 or a Gmsh physical group without elements): its motion acts on "
                                    "no node",
                                name});
    }
}

/// A warning when boundary nodes share their coordinates (zero-length
/// boundary edges, such as a collapsed trailing edge).
void warn_coincident_boundary_nodes(const Context& c, std::vector<Warning>& warnings) {
    const CoincidentGroups groups = group_coincident_points(c.mesh.dim, c.mesh.points, c.boundary.nodes);
    if (groups.size() == c.boundary.nodes.size()) return;
    std::size_t nodes = 0, example = 0;
    for (std::size_t g = 0; g < groups.size(); ++g) {
        const auto size = static_cast<std::size_t>(groups.offsets[g + 1] - groups.offsets[g]);
        if (size < 2) continue;
        if (nodes == 0) example = g;
        nodes += size;
    }
    const auto first = static_cast<std::size_t>(groups.offsets[example]);
    const NodeId a = c.boundary.nodes[static_cast<std::size_t>(groups.members[first])];
    const NodeId b = c.boundary.nodes[static_cast<std::size_t>(groups.members[first + 1])];
    Warning w{WarningCode::coincident_boundary_nodes,
              std::to_string(nodes) + " boundary nodes are at the same coordinates as another boundary node " +
                  "(zero-length boundary edges, e.g. nodes " + std::to_string(a) + " and " + std::to_string(b) +
                  " at " + point_text(point(c.mesh, a)) +
                  "): each follows its own marker's motion; the methods use one position for them (DG-IDW and "
                  "DGM one graph vertex, RBF one centre) with the motion of the first moving one",
              "", static_cast<std::int64_t>(nodes)};
    w.node = a;
    warnings.push_back(std::move(w));
}

}  // namespace

void check_marker_names(const Mesh& mesh, const MotionSpec& spec) {
    for (std::size_t f = 0; f < spec.frames.size(); ++f)
        for (const auto& entry : spec.frames[f].markers) {
            // Not a structured binding: clang before 16 cannot capture one in a lambda.
            const std::string& name = entry.first;
            const bool known = std::any_of(mesh.markers.begin(), mesh.markers.end(),
                                           [&](const Marker& m) { return m.name == name; });
            if (known) continue;
            std::string list;
            for (const Marker& m : mesh.markers) list += (list.empty() ? "" : ", ") + m.name;
            throw MeshError(where(spec, spec.time ? 0 : f) + " names marker '" + name +
                                "', which the mesh does not have; the mesh has: " +
                                (list.empty() ? std::string("no markers") : list),
                            name);
        }
}

ResolvedBoundary resolve_boundary(const Mesh& mesh, const MotionSpec& spec) {
    Series series = make_series(mesh, spec);
    const Context c{mesh, spec, series.context, series.boundary};
    ResolvedBoundary out;
    for (std::size_t m = 0; m < mesh.markers.size(); ++m)
        (c.series.marker_sliding[m]  ? out.sliding_markers
         : c.series.marker_cyclic[m] ? out.cyclic_markers
         : c.series.marker_moving[m] ? out.moving_markers
                                     : out.static_markers)
            .push_back(mesh.markers[m].name);

    std::size_t shared = 0;
    for (std::size_t b = 0; b < c.boundary.nodes.size(); ++b) shared += series.on_moving[b] && series.on_static[b];
    if (shared > 0) out.warnings.push_back(shared_nodes_warning(static_cast<std::int64_t>(shared), spec.shared_nodes));

    if (c.boundary.nodes.empty()) {
        std::string list;
        for (const Marker& m : mesh.markers) list += (list.empty() ? "" : ", ") + m.name;
        throw MeshError(where(spec, 0) + ": the mesh has no boundary nodes: " +
                            (list.empty() ? std::string("it has no markers")
                                          : "every marker (" + list + ") is empty, without elements") +
                            ". Every method moves the mesh from its boundary: give the mesh its boundary markers",
                        mesh.markers.empty() ? std::string() : mesh.markers.front().name);
    }
    if (out.moving_markers.empty())
        out.warnings.push_back({WarningCode::nothing_moves,
                                (spec.source.empty() ? std::string("motion") : spec.source) +
                                    ": nothing moves: the motion gives no marker a motion (an empty motion, or every "
                                    "marker fixed), so the deformed mesh is the input mesh"});
    warn_coincident_boundary_nodes(c, out.warnings);
    warn_empty_named_markers(c, out.warnings);

    // Resolve every frame the spec writes out (step 0 for periodic motions),
    // so that bad files and conflicts fail before any deformation.
    for (std::size_t f = 0; f < spec.frames.size(); ++f) {
        const BoundaryMotion motion = resolve_at(c, spec.frames[f], 0.0, where(spec, f), out.warnings);
        warn_cyclic_mismatch(mesh, series.slides, c.series.tolerance, motion, where(spec, f), out.warnings);
    }
    out.boundary = std::move(series.boundary);
    out.context = std::move(series.context);
    out.slides = std::move(series.slides);
    return out;
}

ResolvedFrame resolve_frame(const Mesh& mesh, const MotionSpec& spec, const ResolvedBoundary& resolved,
                            std::size_t frame) {
    assert(resolved.context.marker_nodes.size() == mesh.markers.size());
    assert(resolved.boundary.nodes.size() == resolved.boundary.moving.size());
    const Context c{mesh, spec, resolved.context, resolved.boundary};
    ResolvedFrame out;
    out.motion = resolve_at(c, frame_spec(spec, frame), frame_time(spec, frame), where(spec, frame), out.warnings,
                            &out.folded_faces);
    warn_cyclic_mismatch(mesh, resolved.slides, c.series.tolerance, out.motion, where(spec, frame), out.warnings);
    return out;
}

Warning shared_nodes_warning(std::int64_t count, SharedNodeRule rule) {
    return {WarningCode::shared_moving_static,
            std::to_string(count) + " boundary node" + (count == 1 ? " is" : "s are") +
                " on both a moving and a static marker; " +
                (rule == SharedNodeRule::moving_wins ? "they follow the moving markers (shared_nodes: moving_wins)"
                                                     : "they stay fixed (shared_nodes: static_wins)"),
            "", count};
}

std::vector<Warning> large_motion_warnings(const Mesh& mesh, const ResolvedBoundary& resolved,
                                           const BoundaryMotion& motion, const std::string& at) {
    assert(motion.size() == resolved.boundary.nodes.size());
    const MotionSpec none;
    const Context c{mesh, none, resolved.context, resolved.boundary};
    NodeMotions motions(mesh.markers.size());
    for (std::size_t m = 0; m < mesh.markers.size(); ++m) {
        if (!c.series.marker_moving[m]) continue;
        for (const std::int32_t b : c.series.slots[m]) motions[m].push_back(motion[static_cast<std::size_t>(b)]);
    }
    std::vector<Warning> warnings;
    warn_large_motions(c, motions, at, warnings);
    return warnings;
}

std::vector<double> moved_boundary_points(const Mesh& mesh, const BoundarySet& boundary,
                                          const BoundaryMotion& motion) {
    assert(motion.size() == boundary.nodes.size());
    const auto dim = static_cast<std::size_t>(mesh.dim);
    std::vector<double> out(boundary.nodes.size() * dim);
    for (std::size_t b = 0; b < boundary.nodes.size(); ++b)
        apply_motion(motion[b], point(mesh, boundary.nodes[b]), {out.data() + b * dim, dim});
    return out;
}

std::vector<double> node_displacements(const Mesh& mesh, const BoundarySet& boundary, const BoundaryMotion& motion) {
    const auto dim = static_cast<std::size_t>(mesh.dim);
    const std::vector<double> moved = moved_boundary_points(mesh, boundary, motion);
    std::vector<double> out(mesh.num_points() * dim, 0.0);
    for (std::size_t b = 0; b < boundary.nodes.size(); ++b) {
        const auto node = static_cast<std::size_t>(boundary.nodes[b]);
        for (std::size_t d = 0; d < dim; ++d) out[node * dim + d] = moved[b * dim + d] - mesh.points[node * dim + d];
    }
    return out;
}

}  // namespace dgwarp
