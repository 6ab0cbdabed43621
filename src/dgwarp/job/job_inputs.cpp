#include "dgwarp/job/job_inputs.hpp"

#include "dgwarp/core/error.hpp"
#include "dgwarp/core/stopwatch.hpp"
#include "dgwarp/io/marker_types.hpp"
#include "dgwarp/io/su2/su2_config.hpp"
#include "dgwarp/motion/planar_motion.hpp"

namespace dgwarp {

void classify_inputs(JobInputs& in, const InputSettings& settings) {
    Stopwatch sw;
    // Names the output cannot hold (a CGNS BC "UserDefined 1" for an OpenFOAM
    // patch): made into names it can, in the motion too, and said below.
    if (!settings.writable_for.empty())
        in.renamed_for_output = make_marker_names_writable(in.mesh, settings.writable_for);
    for (const MarkerRename& r : in.renamed_for_output) rename_marker(in.spec, r.from, r.to);
    if (in.extras.cgns && !in.renamed_for_output.empty()) in.extras.cgns.reset();  // a renamed CGNS input is written whole
    // Markers that slide by their type; a 2D case deformed as its 2D mesh.
    std::vector<std::string> symmetry;
    if (!settings.su2_config.empty())
        for (const Su2ConfigMarker& m : su2_symmetry_markers(settings.su2_config)) {
            try {
                find_marker(in.mesh, m.name);
            } catch (const MeshError& e) {
                throw MeshError(settings.su2_config + ":" + std::to_string(m.line) + ": MARKER_SYM: " + e.what(),
                                m.name);
            }
            symmetry.push_back(m.name);
        }
    TypedMotion typed = apply_marker_types(in.mesh, in.extras, in.spec, symmetry);
    in.sliding_by_type = std::move(typed.sliding);
    in.coupled_by_type = std::move(typed.coupled);
    in.not_planar = std::move(typed.not_planar);
    if (typed.planar) {
        in.spec = planar_motion(*typed.planar, in.mesh, in.spec);
        in.file_mesh = std::move(in.mesh);
        in.mesh = typed.planar->mesh;
        in.planar = std::move(typed.planar);
    }
    in.boundary = resolve_boundary(in.mesh, in.spec);
    if (!typed.uncoupled.empty()) in.boundary.warnings.push_back(uncoupled_cyclic_warning(typed.uncoupled));
    for (const MarkerRename& r : in.renamed_for_output)
        in.boundary.warnings.push_back({WarningCode::other,
                                        settings.writable_for + " cannot hold the marker name '" + r.from +
                                            "': it is written as '" + r.to + "'" +
                                            (settings.rename_option.empty()
                                                 ? std::string()
                                                 : " (" + settings.rename_option + " '" + r.from +
                                                       "=NEW' names it otherwise)"),
                                        r.to});
    if (!in.not_planar.empty())
        in.boundary.warnings.push_back(
            {WarningCode::other, "the empty or wedge patches slide but do not make a 2D case (" + in.not_planar +
                                     "): the mesh is deformed in 3D, their nodes kept in their planes"});
    in.resolve_seconds = sw.lap();
}

void warn_already_inverted(JobInputs& in) {
    const std::int64_t bad = in.original.summary.inverted;
    if (bad == 0) return;
    Warning w{WarningCode::already_inverted,
              std::to_string(bad) + (bad == 1 ? " cell is" : " cells are") +
                  " already inverted or degenerate in the input mesh (quality <= 0, e.g. cell " +
                  std::to_string(in.original.summary.worst_cell) +
                  "): they are counted as inverted before and after, but not blamed on the motion, and do not "
                  "make a step invalid",
              "", bad};
    w.element = in.original.summary.worst_cell;
    in.boundary.warnings.push_back(std::move(w));
}

void measure_original_cells(JobInputs& in, const std::function<void()>& work) {
    in.original = measure_original_beside(in.mesh, work, &in.quality_seconds);
    warn_already_inverted(in);
}

const Mesh& output_mesh(const JobInputs& in) { return in.planar ? in.file_mesh : in.mesh; }

void write_output_mesh(JobInputs& in, const std::filesystem::path& path, std::vector<double>& points,
                       const MeshFields& fields, const WriteOptions& options) {
    Mesh& mesh = in.planar ? in.file_mesh : in.mesh;
    if (points.size() != mesh.points.size())
        throw MeshError(std::to_string(points.size()) + " coordinates for an output mesh of " +
                        std::to_string(mesh.points.size()));
    struct SwapBack {
        std::vector<double>& a;
        std::vector<double>& b;
        ~SwapBack() { a.swap(b); }
    } back{mesh.points, points};
    mesh.points.swap(points);
    write_mesh(path, mesh, fields, options);
}

std::span<const double> output_points(const JobInputs& in, std::span<const double> points,
                                      std::vector<double>& buffer) {
    if (!in.planar) return points;
    buffer.resize(in.file_mesh.points.size());
    lift_points(*in.planar, in.file_mesh.points, points, buffer);
    return buffer;
}

std::vector<double>& output_points(const JobInputs& in, std::vector<double>& points, std::vector<double>& buffer) {
    if (!in.planar) return points;
    output_points(in, std::span<const double>(points), buffer);
    return buffer;
}

}  // namespace dgwarp
