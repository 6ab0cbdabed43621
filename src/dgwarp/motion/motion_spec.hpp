#pragma once
// A motion file, parsed: plain data saying how each boundary marker moves, in
// one frame or in a time series. It knows nothing of a mesh; resolve_motion
// turns it into one NodeMotion per boundary node (see docs/MOTION.md for the
// JSON form and the rules).
//
// Units: lengths in mesh units, angles in radians (the JSON file gives
// degrees), frequencies in Hz, times in seconds. Node ids are 0-based mesh
// node ids.
#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <variant>
#include <utility>
#include <vector>

#include "dgwarp/mesh/mesh.hpp"
#include "dgwarp/motion/node_motion.hpp"

namespace dgwarp {

/// Per-node values read from a file (or built in code): entry i gives node
/// nodes[i] the value values[i]. Node ids are unique.
template <class Value>
struct NodeTable {
    std::vector<NodeId> nodes;        // 0-based mesh node ids
    std::vector<Value> values;        // same size as nodes
    int components = 3;               // 2 or 3: how many coordinates per vector the file gave
                                      // (2: the z components are 0)
    std::string source;               // the file the table came from; "" when built in code
    std::vector<std::size_t> lines;   // 1-based line of each entry in source; empty when built in code
};

/// The marker does not move (t = 0, w = 0).
struct FixedMotion {
    bool operator==(const FixedMotion&) const = default;
};

/// Every node of the marker gets the same motion: rotation about motion.center
/// by motion.rotation (axis × angle), then translation by motion.translation.
struct RigidMotion {
    NodeMotion motion;
    bool operator==(const RigidMotion&) const = default;
};

/// Pitching: the rotation angle at time t is mean + amplitude·sin(2π·frequency·t + phase)
/// about the unit `axis` through `center`.
struct Pitch {
    double amplitude = 0;  // radians
    double mean = 0;       // radians
    double frequency = 0;  // Hz
    double phase = 0;      // radians
    Vec3 axis{0, 0, 1};    // unit vector
    Vec3 center{};
    bool operator==(const Pitch&) const = default;
};

/// Plunging: the translation at time t is amplitude·sin(2π·frequency·t + phase).
struct Plunge {
    Vec3 amplitude{};
    double frequency = 0;  // Hz
    double phase = 0;      // radians
    bool operator==(const Plunge&) const = default;
};

/// A periodic rigid motion (pitch, plunge, or both; at least one). At time t
/// every node gets t = plunge(t), w = pitch angle(t) × axis, c = pitch center.
struct PeriodicMotion {
    std::optional<Pitch> pitch;
    std::optional<Plunge> plunge;
    bool operator==(const PeriodicMotion&) const = default;
};

/// A displacement per node: t_i = d_i, w_i = 0.
struct PrescribedDisplacements {
    NodeTable<Vec3> displacements;
};

/// A new position per node (SU2 surface file): t_i = p_i - x_i, w_i = 0.
struct PrescribedPositions {
    NodeTable<Vec3> positions;
};

/// A full motion (t_i, w_i, c_i) per node, e.g. a twist.
struct PrescribedNodeMotions {
    NodeTable<NodeMotion> motions;
};

/// How one marker moves.
/// The marker's nodes slide in the planes of its faces (a symmetry plane,
/// OpenFOAM's empty and wedge patches): they are not boundary nodes for the
/// methods, which move them as volume nodes, and their motion out of those
/// planes is removed (motion/slide_planes.hpp). A sliding marker slides in
/// every frame.
struct SlideMotion {
    bool operator==(const SlideMotion&) const = default;
};

/// The marker is one half of a periodic boundary whose other half is marker
/// `partner` (which must name this one back): an OpenFOAM cyclic patch. Its
/// nodes are not boundary nodes for the methods, which move them as volume
/// nodes, and each node and its image on the partner move alike, through the
/// rigid motion that maps one half onto the other (motion/cyclic_pairs.hpp).
/// A cyclic marker is cyclic in every frame, with the same partner.
struct CyclicMotion {
    std::string partner;
    bool operator==(const CyclicMotion&) const = default;
};

using MarkerMotion = std::variant<FixedMotion, RigidMotion, PeriodicMotion, PrescribedDisplacements,
                                  PrescribedPositions, PrescribedNodeMotions, SlideMotion, CyclicMotion>;

/// One frame of a motion: the motion of each named marker.
struct MotionFrame {
    std::map<std::string, MarkerMotion> markers;
};

/// The time steps of a periodic motion: frame k is at time k·time_step,
/// k = 0 … steps-1.
struct TimeSteps {
    double time_step = 0;    // > 0
    std::int64_t steps = 1;  // 1 ... max_time_steps
};

/// The most time steps a motion file may ask for. Each step is a deformation
/// and an output file, so more is a mistake (a time_step given as steps, a
/// damaged file), not a run to start: 10^12 steps would loop for ever and
/// grow the per-frame report without bound.
inline constexpr std::int64_t max_time_steps = 1'000'000;

/// What a boundary node on markers with different motions does (docs/MOTION.md).
enum class SharedNodeRule {
    /// METHODS.md's default: the node follows the moving markers it is on when
    /// they all agree (same NodeMotion, or the same new position within the
    /// tolerance), whatever static markers it is also on; otherwise an error.
    moving_wins,
    /// A node on any static marker stays fixed; nodes on moving markers only
    /// must agree as above.
    static_wins,
};

/// A parsed motion file.
struct MotionSpec {
    /// One frame for a single motion (or for periodic motions, which `time`
    /// expands into steps); several for a time series given frame by frame.
    std::vector<MotionFrame> frames;
    /// The motion of markers a frame does not name.
    MarkerMotion default_motion = FixedMotion{};
    /// The file gave `default` (even "fixed"): it then says what every marker
    /// it does not name does, those of a sliding type too (slide_unless_named).
    bool default_given = false;
    /// Set when a marker has a PeriodicMotion (then frames.size() == 1).
    std::optional<TimeSteps> time;
    SharedNodeRule shared_nodes = SharedNodeRule::moving_wins;
    /// Largest distance between two new positions of a shared node that still
    /// counts as agreeing; <= 0 means 1e-9 × the mesh's bounding-box diagonal.
    double shared_tolerance = 0;
    /// The motion file, for messages; "" when built in code.
    std::string source;
};

/// The rotation vector (axis × angle) of a rotation by `angle` radians about
/// `axis`; the axis need not be unit length but must not be zero (asserted).
Vec3 rotation_vector(double angle, const Vec3& axis);

/// The motion of a periodic motion at time t.
NodeMotion periodic_motion_at(const PeriodicMotion& motion, double t);

/// How many frames the spec describes: time->steps when set, else frames.size().
std::size_t frame_count(const MotionSpec& spec);

/// The time of frame k: k·time_step for periodic motions, else 0.
double frame_time(const MotionSpec& spec, std::size_t frame);

/// The MotionFrame that frame k reads: frames[0] for periodic motions, else frames[k].
const MotionFrame& frame_spec(const MotionSpec& spec, std::size_t frame);

/// The motion of marker `name` in `frame` (the default when the frame does not name it).
const MarkerMotion& marker_motion(const MotionSpec& spec, const MotionFrame& frame,
                                  const std::string& name);

/// Makes each of `markers` slide (SlideMotion) in every frame, unless a frame
/// of `spec` names it or the spec gives a default (default_given, or a
/// default_motion other than "fixed": it then says what every marker it does
/// not name does): what a mesh file's marker types ask
/// (io/marker_types.hpp). Returns the markers it made slide, in the order given.
std::vector<std::string> slide_unless_named(MotionSpec& spec, const std::vector<std::string>& markers);

/// The same for cyclic pairs (OpenFOAM's cyclic patches and their
/// neighbourPatch): both markers of a pair that no frame names, under the
/// same condition, become each other's CyclicMotion. Returns the pairs made
/// cyclic, in the order given.
std::vector<std::pair<std::string, std::string>> couple_unless_named(
    MotionSpec& spec, const std::vector<std::pair<std::string, std::string>>& pairs);

/// Renames marker `from` to `to` in every frame of `spec` (its key, and the
/// partner of the cyclic markers that name it): what a mesh whose marker was
/// renamed after the motion file was written needs.
void rename_marker(MotionSpec& spec, const std::string& from, const std::string& to);

/// A short name of the kind of motion ("fixed", "rigid", "periodic",
/// "displacement_file", "surface_file", "node_motion_file", "slide",
/// "cyclic"), for messages.
const char* motion_kind_name(const MarkerMotion& motion);

}  // namespace dgwarp
