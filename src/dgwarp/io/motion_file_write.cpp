// Writing a MotionSpec as a motion file (docs/MOTION.md) that reads back to
// the same per-node motions, bit for bit: rigid rotations about a coordinate
// axis as angle_deg (the double whose product with the reader's degree is the
// rotation exactly), any other rigid motion and the per-node tables as CSV
// files beside the JSON, numbers in shortest exact form.
#include <cctype>
#include <cmath>
#include <numbers>
#include <optional>
#include <sstream>

#include <nlohmann/json.hpp>

#include "dgwarp/core/error.hpp"
#include "dgwarp/io/atomic_write.hpp"
#include "dgwarp/io/motion_file.hpp"
#include "dgwarp/io/number_text.hpp"

namespace dgwarp {

namespace {

using Json = nlohmann::ordered_json;

constexpr double degree = std::numbers::pi / 180.0;  // as the reader's (motion_file.cpp)

/// The angle in degrees whose product with `degree` is `radians` exactly,
/// when there is one near radians / degree: a round number of degrees (or of
/// millionths of one) first, as a person wrote it, else the nearest double.
std::optional<double> exact_degrees(double radians) {
    const double a = radians / degree;
    for (const double round : {std::round(a), std::round(a * 1e6) / 1e6})
        if (round * degree == radians) return round;
    double up = a, down = a;
    for (int step = 0; step < 8; ++step) {
        if (up * degree == radians) return up;
        if (down * degree == radians) return down;
        up = std::nextafter(up, INFINITY);
        down = std::nextafter(down, -INFINITY);
    }
    return std::nullopt;
}

Json vector_json(const Vec3& v, int dim) {
    Json j = Json::array();
    for (int d = 0; d < dim; ++d) j.push_back(v[static_cast<std::size_t>(d)]);
    return j;
}

/// `rigid` as {"rotate": ..., "translate": ...} when that reads back exactly:
/// no rotation, or one about a coordinate axis by an angle that has an exact
/// form in degrees.
std::optional<Json> rigid_json(const NodeMotion& m, int dim) {
    Json j = Json::object();
    const Vec3& w = m.rotation;
    int axis = -1, nonzero = 0;
    for (int k = 0; k < 3; ++k)
        if (w[static_cast<std::size_t>(k)] != 0) ++nonzero, axis = k;
    if (nonzero > 1 || (dim == 2 && nonzero == 1 && axis != 2)) return std::nullopt;
    if (nonzero == 1) {
        const double radians = std::abs(w[static_cast<std::size_t>(axis)]);
        const std::optional<double> angle = exact_degrees(radians);
        if (!angle) return std::nullopt;
        Vec3 unit{};
        unit[static_cast<std::size_t>(axis)] = w[static_cast<std::size_t>(axis)] > 0 ? 1.0 : -1.0;
        j["rotate"] = {{"angle_deg", *angle}, {"axis", vector_json(unit, 3)}, {"center", vector_json(m.center, dim)}};
    } else if (m.center != Vec3{}) {
        return std::nullopt;  // a centre without a rotation: only a node file keeps it
    }
    j["translate"] = vector_json(m.translation, dim);
    return j;
}

/// The file name for a marker's table: the motion file's stem, the marker's
/// name with only letters, digits, '-' and '_' kept, and ".csv".
std::string table_name(const std::filesystem::path& json_path, const std::string& marker, std::size_t frame,
                       std::size_t frames) {
    std::string safe;
    for (char ch : marker) safe += std::isalnum(static_cast<unsigned char>(ch)) || ch == '-' || ch == '_' ? ch : '_';
    return json_path.stem().string() + (frames > 1 ? "_" + std::to_string(frame) : "") + "_" + safe + ".csv";
}

void write_displacements(const std::filesystem::path& path, const NodeTable<Vec3>& table, int dim) {
    write_file_atomically(path, [&](std::ostream& out) {
        out << (dim == 2 ? "node,dx,dy\n" : "node,dx,dy,dz\n");
        for (std::size_t i = 0; i < table.nodes.size(); ++i) {
            write_number(out, static_cast<long long>(table.nodes[i]));
            for (int d = 0; d < dim; ++d) {
                out.put(',');
                write_number(out, table.values[i][static_cast<std::size_t>(d)]);
            }
            out.put('\n');
        }
    });
}

void write_node_motions(const std::filesystem::path& path, const std::vector<NodeId>& nodes,
                        const std::vector<NodeMotion>& motions, int dim) {
    write_file_atomically(path, [&](std::ostream& out) {
        out << (dim == 2 ? "node,tx,ty,wz,cx,cy\n" : "node,tx,ty,tz,wx,wy,wz,cx,cy,cz\n");
        for (std::size_t i = 0; i < nodes.size(); ++i) {
            const NodeMotion& m = motions[i];
            write_number(out, static_cast<long long>(nodes[i]));
            auto field = [&](double v) {
                out.put(',');
                write_number(out, v);
            };
            if (dim == 2) {
                for (double v : {m.translation[0], m.translation[1], m.rotation[2], m.center[0], m.center[1]}) field(v);
            } else {
                for (const Vec3* v : {&m.translation, &m.rotation, &m.center})
                    for (double c : *v) field(c);
            }
            out.put('\n');
        }
    });
}

/// One marker's motion as JSON, writing its table beside `json_path` when it has one.
Json marker_json(const MarkerMotion& motion, const std::string& marker, const Mesh& mesh,
                 const std::filesystem::path& json_path, std::size_t frame, std::size_t frames) {
    const std::string csv = table_name(json_path, marker, frame, frames);
    const std::filesystem::path csv_path = json_path.parent_path() / csv;
    if (std::holds_alternative<FixedMotion>(motion)) return "fixed";
    if (const auto* r = std::get_if<RigidMotion>(&motion)) {
        if (std::optional<Json> j = rigid_json(r->motion, mesh.dim)) return *j;
        // Another rotation has no exact form in degrees: the same motion for every node of the marker.
        const std::vector<NodeId> nodes = marker_nodes(find_marker(mesh, marker));
        write_node_motions(csv_path, nodes, std::vector<NodeMotion>(nodes.size(), r->motion), mesh.dim);
        return {{"node_motion_file", csv}};
    }
    if (const auto* d = std::get_if<PrescribedDisplacements>(&motion)) {
        write_displacements(csv_path, d->displacements, mesh.dim);
        return {{"displacement_file", csv}};
    }
    if (const auto* n = std::get_if<PrescribedNodeMotions>(&motion)) {
        write_node_motions(csv_path, n->motions.nodes, n->motions.values, mesh.dim);
        return {{"node_motion_file", csv}};
    }
    throw Error("cannot write the motion of marker '" + marker + "' as a motion file: " +
                (std::holds_alternative<PeriodicMotion>(motion) ? "a periodic motion" : "new positions per node") +
                " (dgwarp writes rigid motions, displacements and motions per node)");
}

Json frame_json(const MotionFrame& frame, const Mesh& mesh, const std::filesystem::path& json_path, std::size_t k,
                std::size_t frames) {
    Json markers = Json::object();
    for (const auto& [name, motion] : frame.markers) markers[name] = marker_json(motion, name, mesh, json_path, k, frames);
    return markers;
}

}  // namespace

void write_motion_file(const std::filesystem::path& path, const MotionSpec& spec, const Mesh& mesh) {
    if (spec.time) throw Error("cannot write a periodic motion as a motion file");
    if (spec.frames.empty()) throw Error("cannot write a motion without frames");
    Json root = Json::object();
    const std::size_t frames = spec.frames.size();
    if (frames == 1) {
        root["markers"] = frame_json(spec.frames[0], mesh, path, 0, 1);
    } else {
        root["frames"] = Json::array();
        for (std::size_t k = 0; k < frames; ++k)
            root["frames"].push_back({{"markers", frame_json(spec.frames[k], mesh, path, k, frames)}});
    }
    if (!std::holds_alternative<FixedMotion>(spec.default_motion))
        root["default"] = marker_json(spec.default_motion, "default", mesh, path, 0, 1);
    if (spec.shared_nodes == SharedNodeRule::static_wins) root["shared_nodes"] = "static_wins";
    if (spec.shared_tolerance > 0) root["shared_tolerance"] = spec.shared_tolerance;
    const std::string text = root.dump(2) + "\n";
    write_file_atomically(path, [&](std::ostream& out) { out << text; });
}

}  // namespace dgwarp
