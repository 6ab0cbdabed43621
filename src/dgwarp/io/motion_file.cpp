#include "dgwarp/io/motion_file.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <utility>
#include <variant>

#include "dgwarp/core/error.hpp"
#include "dgwarp/io/json_fields.hpp"
#include "dgwarp/io/node_table_read.hpp"
#include "dgwarp/io/text_reader.hpp"

namespace dgwarp {

namespace {

constexpr double degree = std::numbers::pi / 180.0;

/// Reads the JSON tree into a MotionSpec; remembers the files it has read so
/// a file named by several markers is read once.
class MotionParser {
public:
    MotionParser(std::string file, std::filesystem::path base_dir)
        : file_(std::move(file)), base_dir_(std::move(base_dir)) {}

    MotionSpec parse(const Json& root);

private:
    MotionFrame parse_markers(const Json& markers, const JsonPlace& at, bool in_frames);
    MarkerMotion parse_marker_motion(const Json& value, const JsonPlace& at, bool in_frames);
    RigidMotion parse_rigid(const Json& value, const JsonPlace& at);
    PeriodicMotion parse_periodic(const Json& value, const JsonPlace& at);
    TimeSteps parse_time(const Json& value, const JsonPlace& at);
    std::filesystem::path file_path(const Json& value, const JsonPlace& at);
    template <class Table, class Read>
    Table read_cached(std::map<std::string, Table>& cache, const Json& value, const JsonPlace& at, Read read);

    std::string file_;
    std::filesystem::path base_dir_;
    std::map<std::string, NodeTable<Vec3>> displacement_files_, surface_files_;
    std::map<std::string, NodeTable<NodeMotion>> node_motion_files_;
    bool has_periodic_ = false;
};

MotionSpec MotionParser::parse(const Json& root) {
    const JsonPlace top{file_, ""};
    check_object(root, top, {"markers", "frames", "default", "time", "shared_nodes", "shared_tolerance"});
    const bool has_markers = root.contains("markers"), has_frames = root.contains("frames");
    if (has_markers == has_frames)
        throw ParseError(file_, 0, "exactly one of the keys markers (one motion) or frames (a list of frames) at the top level",
                         has_markers ? "both" : "neither");

    MotionSpec spec;
    spec.source = file_;
    if (has_markers) {
        spec.frames.push_back(parse_markers(root["markers"], top.key("markers"), false));
    } else {
        const Json& frames = root["frames"];
        const JsonPlace at = top.key("frames");
        if (!frames.is_array() || frames.empty()) json_fail(at, "a non-empty array of frames", frames);
        for (std::size_t i = 0; i < frames.size(); ++i) {
            const JsonPlace frame_at = at.index(i);
            check_object(frames[i], frame_at, {"markers"});
            spec.frames.push_back(parse_markers(require_field(frames[i], frame_at, "markers", "the markers' motions"),
                                                frame_at.key("markers"), true));
        }
    }
    if (root.contains("default")) {
        spec.default_motion = parse_marker_motion(root["default"], top.key("default"), has_frames);
        spec.default_given = true;
    }

    if (root.contains("time")) {
        spec.time = parse_time(root["time"], top.key("time"));
        if (!has_periodic_)
            throw ParseError(file_, 0, "time only with a periodic motion (frames are the steps otherwise)", "time without one");
    } else if (has_periodic_) {
        throw ParseError(file_, 0, "the field time ({\"time_step\": ..., \"steps\": ...}) for the periodic motion", "");
    }

    if (root.contains("shared_nodes")) {
        const JsonPlace at = top.key("shared_nodes");
        const std::string rule = string_value(root["shared_nodes"], at);
        if (rule == "moving_wins") spec.shared_nodes = SharedNodeRule::moving_wins;
        else if (rule == "static_wins") spec.shared_nodes = SharedNodeRule::static_wins;
        else json_fail(at, "\"moving_wins\" or \"static_wins\"", root["shared_nodes"]);
    }
    if (root.contains("shared_tolerance")) {
        const JsonPlace at = top.key("shared_tolerance");
        spec.shared_tolerance = finite_number(root["shared_tolerance"], at);
        if (spec.shared_tolerance <= 0) json_fail(at, "a length > 0", root["shared_tolerance"]);
    }
    return spec;
}

MotionFrame MotionParser::parse_markers(const Json& markers, const JsonPlace& at, bool in_frames) {
    if (!markers.is_object()) json_fail(at, "an object {\"<marker name>\": <motion>, ...}", markers);
    MotionFrame frame;
    for (const auto& [name, value] : markers.items()) {
        if (name.empty()) json_fail(at, "non-empty marker names", markers);
        frame.markers.emplace(name, parse_marker_motion(value, at.key(name), in_frames));
    }
    return frame;
}

MarkerMotion MotionParser::parse_marker_motion(const Json& value, const JsonPlace& at, bool in_frames) {
    constexpr const char* kinds =
        "\"fixed\", \"slide\" or one motion object: {\"rotate\": ..., \"translate\": ...}, "
        "{\"displacement_file\": ...}, {\"surface_file\": ...}, {\"node_motion_file\": ...}, {\"periodic\": ...} or "
        "{\"cyclic\": \"<partner marker>\"}";
    if (value.is_string()) {
        if (value.get<std::string>() == "fixed") return FixedMotion{};
        if (value.get<std::string>() == "slide") return SlideMotion{};
        json_fail(at, kinds, value);
    }
    check_object(value, at,
                 {"rotate", "translate", "displacement_file", "surface_file", "node_motion_file", "periodic", "cyclic"});
    if (value.contains("cyclic")) {
        if (value.size() != 1) json_fail(at, kinds, value);
        const Json& partner = value["cyclic"];
        if (!partner.is_string() || partner.get<std::string>().empty())
            json_fail(at.key("cyclic"), "the name of the partner marker (the other half of the periodic boundary)",
                      partner);
        return CyclicMotion{partner.get<std::string>()};
    }
    const bool rigid = value.contains("rotate") || value.contains("translate");
    const int others = int(value.contains("displacement_file")) + int(value.contains("surface_file")) +
                       int(value.contains("node_motion_file")) + int(value.contains("periodic"));
    if (others + int(rigid) != 1) json_fail(at, kinds, value);

    if (rigid) return parse_rigid(value, at);
    if (value.contains("periodic")) {
        if (in_frames)
            json_fail(at.key("periodic"), "no periodic motion in a list of frames (give it in the top-level markers, with time)",
                      value["periodic"]);
        has_periodic_ = true;
        return parse_periodic(value["periodic"], at.key("periodic"));
    }
    if (value.contains("displacement_file"))
        return PrescribedDisplacements{read_cached(displacement_files_, value["displacement_file"],
                                                   at.key("displacement_file"), read_displacement_csv)};
    if (value.contains("surface_file"))
        return PrescribedPositions{
            read_cached(surface_files_, value["surface_file"], at.key("surface_file"), read_su2_surface_file)};
    return PrescribedNodeMotions{
        read_cached(node_motion_files_, value["node_motion_file"], at.key("node_motion_file"), read_node_motion_csv)};
}

RigidMotion MotionParser::parse_rigid(const Json& value, const JsonPlace& at) {
    RigidMotion rigid;
    if (value.contains("rotate")) {
        const Json& r = value["rotate"];
        const JsonPlace rat = at.key("rotate");
        check_object(r, rat, {"angle_deg", "axis", "center"});
        const double angle = finite_number(require_field(r, rat, "angle_deg", "the angle in degrees"), rat.key("angle_deg"));
        Vec3 axis{0, 0, 1};
        if (r.contains("axis")) {
            axis = vector_value(r["axis"], rat.key("axis"), true);
            if (axis == Vec3{0, 0, 0}) json_fail(rat.key("axis"), "a non-zero axis", r["axis"]);
        }
        rigid.motion.rotation = rotation_vector(angle * degree, axis);
        rigid.motion.center =
            vector_value(require_field(r, rat, "center", "the centre of rotation, [x, y(, z)]"), rat.key("center"));
    }
    if (value.contains("translate")) rigid.motion.translation = vector_value(value["translate"], at.key("translate"));
    return rigid;
}

PeriodicMotion MotionParser::parse_periodic(const Json& value, const JsonPlace& at) {
    check_object(value, at, {"pitch", "plunge"});
    if (!value.contains("pitch") && !value.contains("plunge"))
        json_fail(at, "a pitch, a plunge or both", value);
    auto frequency = [](const Json& obj, const JsonPlace& a) {
        const double f = finite_number(require_field(obj, a, "frequency", "in Hz"), a.key("frequency"));
        if (f < 0) json_fail(a.key("frequency"), "a frequency >= 0 (Hz)", obj["frequency"]);
        return f;
    };
    PeriodicMotion motion;
    if (value.contains("pitch")) {
        const Json& p = value["pitch"];
        const JsonPlace pat = at.key("pitch");
        check_object(p, pat, {"amplitude_deg", "mean_deg", "frequency", "phase_deg", "axis", "center"});
        Pitch pitch;
        pitch.amplitude =
            degree * finite_number(require_field(p, pat, "amplitude_deg", "in degrees"), pat.key("amplitude_deg"));
        if (p.contains("mean_deg")) pitch.mean = degree * finite_number(p["mean_deg"], pat.key("mean_deg"));
        pitch.frequency = frequency(p, pat);
        if (p.contains("phase_deg")) pitch.phase = degree * finite_number(p["phase_deg"], pat.key("phase_deg"));
        if (p.contains("axis")) {
            const Vec3 axis = vector_value(p["axis"], pat.key("axis"), true);
            if (axis == Vec3{0, 0, 0}) json_fail(pat.key("axis"), "a non-zero axis", p["axis"]);
            pitch.axis = rotation_vector(1.0, axis);  // unit length
        }
        pitch.center = vector_value(require_field(p, pat, "center", "the pitch axis' point, [x, y(, z)]"), pat.key("center"));
        motion.pitch = pitch;
    }
    if (value.contains("plunge")) {
        const Json& p = value["plunge"];
        const JsonPlace pat = at.key("plunge");
        check_object(p, pat, {"amplitude", "frequency", "phase_deg"});
        Plunge plunge;
        plunge.amplitude =
            vector_value(require_field(p, pat, "amplitude", "a vector [x, y(, z)]"), pat.key("amplitude"));
        plunge.frequency = frequency(p, pat);
        if (p.contains("phase_deg")) plunge.phase = degree * finite_number(p["phase_deg"], pat.key("phase_deg"));
        motion.plunge = plunge;
    }
    return motion;
}

TimeSteps MotionParser::parse_time(const Json& value, const JsonPlace& at) {
    check_object(value, at, {"time_step", "steps"});
    TimeSteps time;
    time.time_step = finite_number(require_field(value, at, "time_step", "in seconds, > 0"), at.key("time_step"));
    if (time.time_step <= 0) json_fail(at.key("time_step"), "a time step > 0", value["time_step"]);
    time.steps = integer(require_field(value, at, "steps", "the number of frames, >= 1"), at.key("steps"));
    if (time.steps < 1 || time.steps > max_time_steps)
        json_fail(at.key("steps"), "a number of steps from 1 to " + std::to_string(max_time_steps), value["steps"]);
    return time;
}

std::filesystem::path MotionParser::file_path(const Json& value, const JsonPlace& at) {
    const std::string name = string_value(value, at);
    if (name.empty()) json_fail(at, "a file name", value);
    const std::filesystem::path p(name);
    return p.is_absolute() ? p : base_dir_ / p;
}

template <class Table, class Read>
Table MotionParser::read_cached(std::map<std::string, Table>& cache, const Json& value, const JsonPlace& at,
                                Read read) {
    const std::filesystem::path path = file_path(value, at);
    const std::string key = path.lexically_normal().string();
    if (const auto it = cache.find(key); it != cache.end()) return it->second;
    try {
        return cache.emplace(key, read(path)).first->second;
    } catch (const IoError& e) {
        // Keep the reason ("No such file or directory", "is not a regular file").
        std::string reason = e.what();
        if (const std::string prefix = e.file() + ": "; reason.starts_with(prefix)) reason.erase(0, prefix.size());
        throw IoError(e.file(), "cannot read the file named at " + at.path + " in " + file_ + ": " + reason,
                      e.error_number());
    }
}

}  // namespace

MotionSpec parse_motion_file(const std::string& text, const std::string& file_name,
                             const std::filesystem::path& base_dir) {
    return MotionParser(file_name, base_dir).parse(parse_json_text(text, file_name));
}

MotionSpec read_motion_file(const std::filesystem::path& path) {
    return parse_motion_file(read_file_text(path), path.string(), path.parent_path());
}

namespace {

void add_table_source(std::vector<std::filesystem::path>& files, const std::string& source) {
    if (!source.empty() && std::find(files.begin(), files.end(), source) == files.end()) files.emplace_back(source);
}

void add_marker_files(std::vector<std::filesystem::path>& files, const MarkerMotion& motion) {
    if (const auto* d = std::get_if<PrescribedDisplacements>(&motion)) add_table_source(files, d->displacements.source);
    if (const auto* p = std::get_if<PrescribedPositions>(&motion)) add_table_source(files, p->positions.source);
    if (const auto* n = std::get_if<PrescribedNodeMotions>(&motion)) add_table_source(files, n->motions.source);
}

}  // namespace

std::vector<std::filesystem::path> motion_named_files(const MotionSpec& spec) {
    std::vector<std::filesystem::path> files;
    add_marker_files(files, spec.default_motion);
    for (const MotionFrame& frame : spec.frames)
        for (const auto& [marker, motion] : frame.markers) add_marker_files(files, motion);
    return files;
}

}  // namespace dgwarp
