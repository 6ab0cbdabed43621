// write_motion_file: a MotionSpec as a motion file (docs/MOTION.md) and the
// node files it names, so that read_motion_file gives the spec back.
#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <functional>
#include <map>
#include <numbers>
#include <set>
#include <span>
#include <string>
#include <vector>

#include "dgwarp/core/atomic_write.hpp"
#include "dgwarp/io/json_fields.hpp"
#include "dgwarp/io/motion_file.hpp"
#include "dgwarp/io/number_text.hpp"

namespace dgwarp {

namespace {

// The reader's factor: an angle of d degrees is d * degree radians.
constexpr double degree = std::numbers::pi / 180.0;

std::size_t decimal_length(double value) {
    char buf[32];
    return static_cast<std::size_t>(std::to_chars(buf, buf + sizeof buf, value).ptr - buf);
}

/// The angle in degrees that the reader turns back into `radians` exactly
/// (d * degree == radians), the shortest in decimals when several do (45, not
/// 45.00000000000001); radians / degree when none within a few ulps does.
double degrees_of(double radians) {
    const double guess = radians / degree;
    double best = guess;
    bool exact = false;
    double d = guess;
    for (int i = 0; i < 8; ++i) d = std::nextafter(d, -INFINITY);
    for (int i = 0; i <= 16; ++i, d = std::nextafter(d, INFINITY)) {
        if (d * degree != radians) continue;
        if (!exact || decimal_length(d) < decimal_length(best)) best = d;
        exact = true;
    }
    return best;
}

/// [x, y] when z is +0 (the reader's 2-component form gives z = +0), else [x, y, z].
Json vector_json(const Vec3& v) {
    if (v[2] == 0 && !std::signbit(v[2])) return Json::array({v[0], v[1]});
    return Json::array({v[0], v[1], v[2]});
}

/// A rotation vector as angle_deg and axis. The reader gives component i as
/// (angle_deg·degree)·axis_i / |axis|. About a coordinate axis (at most one
/// non-zero component k) that is exact with a positive angle and the axis
/// ±e_k, whose zero entries carry the signs of w's zeros (the reader's
/// rotations by negative angles have -0 components). Otherwise the axis is w
/// itself, to within rounding.
void put_rotation(Json& rotate, const Vec3& w) {
    const int nonzero = int(w[0] != 0) + int(w[1] != 0) + int(w[2] != 0);
    if (nonzero <= 1) {
        const std::size_t k = w[0] != 0 ? 0 : w[1] != 0 ? 1 : 2;
        Json axis = Json::array();
        for (std::size_t i = 0; i < 3; ++i) axis.push_back(std::copysign(i == k ? 1.0 : 0.0, w[i]));
        rotate["angle_deg"] = degrees_of(std::abs(w[k]));
        rotate["axis"] = axis;
        return;
    }
    rotate["angle_deg"] = degrees_of(std::sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]));
    rotate["axis"] = Json::array({w[0], w[1], w[2]});
}

Json rigid_json(const NodeMotion& m) {
    Json j = Json::object();
    if (m.rotation != Vec3{0, 0, 0} || m.center != Vec3{0, 0, 0}) {
        Json rotate = Json::object();
        put_rotation(rotate, m.rotation);
        rotate["center"] = vector_json(m.center);
        j["rotate"] = rotate;
    }
    if (m.translation != Vec3{0, 0, 0} || !j.contains("rotate")) j["translate"] = vector_json(m.translation);
    return j;
}

Json periodic_json(const PeriodicMotion& p) {
    Json j = Json::object();
    if (p.pitch) {
        const Pitch& q = *p.pitch;
        j["pitch"] = {{"amplitude_deg", degrees_of(q.amplitude)},
                      {"mean_deg", degrees_of(q.mean)},
                      {"frequency", q.frequency},
                      {"phase_deg", degrees_of(q.phase)},
                      {"axis", Json::array({q.axis[0], q.axis[1], q.axis[2]})},
                      {"center", vector_json(q.center)}};
    }
    if (p.plunge)
        j["plunge"] = {{"amplitude", vector_json(p.plunge->amplitude)},
                       {"frequency", p.plunge->frequency},
                       {"phase_deg", degrees_of(p.plunge->phase)}};
    return {{"periodic", j}};
}

/// Writes one node table in the form its reader takes (node_table_read.hpp).
void write_vec3_table(std::ostream& out, const NodeTable<Vec3>& t, bool surface) {
    const std::size_t n = t.components == 2 ? 2 : 3;
    if (!surface) out << (n == 2 ? "node,dx,dy\n" : "node,dx,dy,dz\n");
    const char sep = surface ? '\t' : ',';
    for (std::size_t e = 0; e < t.nodes.size(); ++e) {
        write_number(out, static_cast<long long>(t.nodes[e]));
        for (std::size_t i = 0; i < n; ++i) {
            out << sep;
            write_number(out, t.values[e][i]);
        }
        out << '\n';
    }
}

void write_node_motion_table(std::ostream& out, const NodeTable<NodeMotion>& t) {
    // The 2D form leaves out tz, wx, wy, cz, which must then be zero.
    const bool planar = t.components == 2 && std::all_of(t.values.begin(), t.values.end(), [](const NodeMotion& m) {
                            return m.translation[2] == 0 && m.rotation[0] == 0 && m.rotation[1] == 0 &&
                                   m.center[2] == 0;
                        });
    out << (planar ? "node,tx,ty,wz,cx,cy\n" : "node,tx,ty,tz,wx,wy,wz,cx,cy,cz\n");
    for (std::size_t e = 0; e < t.nodes.size(); ++e) {
        const NodeMotion& m = t.values[e];
        write_number(out, static_cast<long long>(t.nodes[e]));
        const double planar_values[] = {m.translation[0], m.translation[1], m.rotation[2], m.center[0], m.center[1]};
        const double full_values[] = {m.translation[0], m.translation[1], m.translation[2], m.rotation[0], m.rotation[1],
                                      m.rotation[2],    m.center[0],      m.center[1],      m.center[2]};
        for (double v : planar ? std::span<const double>(planar_values) : std::span<const double>(full_values)) {
            out << ',';
            write_number(out, v);
        }
        out << '\n';
    }
}

/// `j` on one line, with a blank after each ':' and ',' (as the examples in docs/MOTION.md).
void write_inline(std::ostream& out, const Json& j) {
    if (j.is_object()) {
        out << '{';
        bool first = true;
        for (const auto& [key, value] : j.items()) {
            out << (first ? "" : ", ") << Json(key).dump() << ": ";
            write_inline(out, value);
            first = false;
        }
        out << '}';
    } else if (j.is_array()) {
        out << '[';
        for (std::size_t i = 0; i < j.size(); ++i) {
            if (i) out << ", ";
            write_inline(out, j[i]);
        }
        out << ']';
    } else {
        out << j.dump();
    }
}

/// The motion file's text: one key of the top level per line, and in
/// "markers" one marker, in "frames" one frame per line.
void write_motion_json(std::ostream& out, const Json& root) {
    out << "{\n";
    std::size_t n = 0;
    for (const auto& [key, value] : root.items()) {
        out << "  " << Json(key).dump() << ": ";
        const bool markers = key == "markers", frames = key == "frames";
        if ((markers || frames) && !value.empty()) {
            out << (markers ? "{\n" : "[\n");
            std::size_t i = 0;
            for (const auto& [name, item] : value.items()) {
                out << "    ";
                if (markers) out << Json(name).dump() << ": ";
                write_inline(out, item);
                out << (++i < value.size() ? ",\n" : "\n");
            }
            out << (markers ? "  }" : "  ]");
        } else {
            write_inline(out, value);
        }
        out << (++n < root.size() ? ",\n" : "\n");
    }
    out << "}\n";
}

/// Turns a spec into JSON, writing its node tables beside `path` as it goes.
class MotionWriter {
public:
    explicit MotionWriter(const std::filesystem::path& path) : path_(path) {}

    Json marker_json(const MarkerMotion& motion, const std::string& marker, std::size_t frame, bool several_frames);

    std::vector<std::filesystem::path> written;

private:
    /// The node file for a table: one per table source (markers sharing a
    /// file share it here too), named <stem>_<marker>[_<frame>]<ext>.
    std::string node_file(const MarkerMotion& motion, const std::string& source, const void* table,
                          const std::string& marker, std::size_t frame, bool several_frames, const char* ext,
                          const std::function<void(std::ostream&)>& write);

    std::filesystem::path path_;
    std::map<std::string, std::string> files_;  // table key -> file name
    std::set<std::string> names_;
};

std::string MotionWriter::node_file(const MarkerMotion& motion, const std::string& source, const void* table,
                                    const std::string& marker, std::size_t frame, bool several_frames,
                                    const char* ext, const std::function<void(std::ostream&)>& write) {
    // The reader treats tables with one source as one file; built in code, one object.
    std::string key = std::to_string(motion.index()) + ':';
    key += source.empty() ? std::to_string(reinterpret_cast<std::uintptr_t>(table)) : source;
    if (const auto it = files_.find(key); it != files_.end()) return it->second;
    std::string base = path_.stem().string();
    base += '_';
    base += marker;
    if (several_frames) {
        base += '_';
        base += std::to_string(frame);
    }
    for (char& c : base)
        if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == '.')) c = '_';
    std::string name = base + ext;
    for (int i = 2; names_.count(name); ++i) {
        name = base;
        name += '_';
        name += std::to_string(i);
        name += ext;
    }
    names_.insert(name);
    const std::filesystem::path file = path_.parent_path() / name;
    write_file_atomically(file, write);
    written.push_back(file);
    return files_[key] = name;
}

Json MotionWriter::marker_json(const MarkerMotion& motion, const std::string& marker, std::size_t frame,
                               bool several_frames) {
    if (std::holds_alternative<FixedMotion>(motion)) return "fixed";
    if (std::holds_alternative<SlideMotion>(motion)) return "slide";
    if (const auto* c = std::get_if<CyclicMotion>(&motion)) return {{"cyclic", c->partner}};
    if (const auto* r = std::get_if<RigidMotion>(&motion)) return rigid_json(r->motion);
    if (const auto* p = std::get_if<PeriodicMotion>(&motion)) return periodic_json(*p);
    if (const auto* d = std::get_if<PrescribedDisplacements>(&motion)) {
        const NodeTable<Vec3>& t = d->displacements;
        return {{"displacement_file", node_file(motion, t.source, &t, marker, frame, several_frames, ".csv",
                                                [&](std::ostream& out) { write_vec3_table(out, t, false); })}};
    }
    if (const auto* p = std::get_if<PrescribedPositions>(&motion)) {
        const NodeTable<Vec3>& t = p->positions;
        return {{"surface_file", node_file(motion, t.source, &t, marker, frame, several_frames, ".dat",
                                           [&](std::ostream& out) { write_vec3_table(out, t, true); })}};
    }
    const NodeTable<NodeMotion>& t = std::get<PrescribedNodeMotions>(motion).motions;
    return {{"node_motion_file", node_file(motion, t.source, &t, marker, frame, several_frames, ".csv",
                                           [&](std::ostream& out) { write_node_motion_table(out, t); })}};
}

}  // namespace

std::vector<std::filesystem::path> write_motion_file(const std::filesystem::path& path, const MotionSpec& spec,
                                                     const std::string& comment) {
    MotionWriter writer(path);
    Json root = Json::object();
    if (!comment.empty()) root["comment"] = comment;
    const bool several = spec.frames.size() > 1;
    auto frame_json = [&](const MotionFrame& frame, std::size_t k) {
        Json markers = Json::object();
        for (const auto& [name, motion] : frame.markers) markers[name] = writer.marker_json(motion, name, k, several);
        return markers;
    };
    if (spec.frames.size() == 1) {
        root["markers"] = frame_json(spec.frames[0], 0);
    } else {
        root["frames"] = Json::array();
        for (std::size_t k = 0; k < spec.frames.size(); ++k)
            root["frames"].push_back({{"markers", frame_json(spec.frames[k], k)}});
    }
    if (spec.default_given || !std::holds_alternative<FixedMotion>(spec.default_motion))
        root["default"] = writer.marker_json(spec.default_motion, "default", 0, false);
    if (spec.time) root["time"] = {{"time_step", spec.time->time_step}, {"steps", spec.time->steps}};
    if (spec.shared_nodes == SharedNodeRule::static_wins) root["shared_nodes"] = "static_wins";
    if (spec.shared_tolerance > 0) root["shared_tolerance"] = spec.shared_tolerance;
    write_file_atomically(path, [&](std::ostream& out) { write_motion_json(out, root); });
    writer.written.push_back(path);
    return writer.written;
}

}  // namespace dgwarp
