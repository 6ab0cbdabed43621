// processor_job.hpp: each process reads, deforms, measures and writes its own
// processor folder of a decomposed OpenFOAM case.
#include "dgwarp/mpi_job/processor_job.hpp"

#include <algorithm>
#include <variant>

#include "dgwarp/core/error.hpp"
#include "dgwarp/core/stopwatch.hpp"
#include "dgwarp/io/marker_types.hpp"
#include "dgwarp/io/mesh_io.hpp"
#include "dgwarp/io/motion_file.hpp"
#include "dgwarp/io/openfoam/openfoam_frames.hpp"
#include "dgwarp/mpi/agreement.hpp"
#include "dgwarp/mpi/part_reductions.hpp"
#include "dgwarp/mpi/part_setup.hpp"
#include "dgwarp/mpi/reductions.hpp"

namespace dgwarp::mpi {

namespace fs = std::filesystem;

namespace {

/// True when a marker of `spec` moves by a per-node table (node ids of the whole case).
bool has_node_tables(const MotionSpec& spec) {
    const auto tabled = [](const MarkerMotion& m) {
        return std::holds_alternative<PrescribedDisplacements>(m) || std::holds_alternative<PrescribedPositions>(m) ||
               std::holds_alternative<PrescribedNodeMotions>(m);
    };
    if (tabled(spec.default_motion)) return true;
    for (const MotionFrame& frame : spec.frames)
        for (const auto& [name, motion] : frame.markers)
            if (tabled(motion)) return true;
    return false;
}

/// The whole case's counts from every process's part: each node and cell once.
MeshCounts case_counts(MPI_Comm comm, const Mesh& mesh, const ProcessorPart& part) {
    MeshCounts c = mesh_counts(mesh);
    std::int64_t largest = -1;
    for (std::int64_t id : part.point_ids) largest = std::max(largest, id);
    c.nodes = mpi::max(comm, largest) + 1;
    c.cells = mpi::sum(comm, c.cells);
    c.cell_types = mpi::sum(comm, c.cell_types);
    std::vector<std::int64_t> nodes;
    for (const Marker& m : mesh.markers) {
        std::int64_t owned = 0;
        for (NodeId n : marker_nodes(m)) owned += part.owned[static_cast<std::size_t>(n)];
        nodes.push_back(owned);
    }
    const std::vector<std::int64_t> elements = mpi::sum(comm, part.marker_elements);
    nodes = mpi::sum(comm, nodes);
    for (std::size_t m = 0; m < c.markers.size(); ++m) c.markers[m] = {mesh.markers[m].name, elements[m], nodes[m]};
    return c;
}

/// The boundary nodes this process owns that are on a moving and on a static marker.
std::int64_t owned_moving_and_static(const Mesh& mesh, const ResolvedBoundary& b, const std::vector<std::uint8_t>& owned) {
    std::vector<std::uint8_t> on(mesh.num_points(), 0);  // bit 1: a moving marker, bit 2: a static one
    for (const Marker& m : mesh.markers) {
        const bool moving = std::find(b.moving_markers.begin(), b.moving_markers.end(), m.name) != b.moving_markers.end();
        for (NodeId n : marker_nodes(m)) on[static_cast<std::size_t>(n)] |= moving ? 1 : 2;
    }
    std::int64_t count = 0;
    for (std::size_t n = 0; n < on.size(); ++n) count += on[n] == 3 && owned[n];
    return count;
}

}  // namespace

std::string processor_job_refusal(const fs::path& case_path, const fs::path& motion, int processes) {
    try {
        const std::vector<fs::path> processors = openfoam_processor_meshes(case_path);
        if (processors.size() != static_cast<std::size_t>(processes))
            return case_path.string() + " has " + std::to_string(processors.size()) + " processor folders, for " +
                   std::to_string(processes) + " processes";
        MotionSpec spec = read_motion_file(motion);
        if (has_node_tables(spec)) return "a marker moves by a table of node ids (the whole case's)";
        const std::vector<OpenFoamPatchType> patches = openfoam_patch_types(processors.front());
        for (const OpenFoamPatchType& p : patches)
            if (is_cyclic_type(p.type) || p.type == "processorCyclic")
                return "patch '" + p.name + "' is " + p.type + " (a node's image may be on another processor)";
        std::vector<std::string> typed;
        for (const OpenFoamPatchType& p : patches)
            if (slides_by_type(p.type)) typed.push_back(p.name);
        slide_unless_named(spec, typed);
        for (const OpenFoamPatchType& p : patches)
            for (const MotionFrame& f : spec.frames)
                if (std::holds_alternative<SlideMotion>(marker_motion(spec, f, p.name)))
                    return "marker '" + p.name + "' slides (its first pass needs every boundary node)";
        return "";
    } catch (const Error& e) {
        return e.what();
    }
}

ProcessorCase read_processor_job(MPI_Comm comm, const ProcessorJobFiles& files, JobInputs& in,
                                 const std::function<void(const std::string&)>& phase) {
    const int rank = rank_in(comm), processes = processes_in(comm);
    const auto say = [&](const std::string& what) {
        if (phase) phase(what);
    };
    ProcessorCase c;
    c.output = files.output;
    std::vector<NodeId> interface;
    Stopwatch sw;

    // Each process reads the motion and its own processor folder.
    collectively(comm, [&] {
        in.spec = read_motion_file(files.motion);
        c.time_names = files.time_names ? files.time_names(in.spec) : openfoam_frame_time_names(in.spec);
        if (c.time_names.size() != frame_count(in.spec))
            throw UsageError("read_processor_job: " + std::to_string(c.time_names.size()) + " time folder names for " +
                             std::to_string(frame_count(in.spec)) + " frames");
        if (rank == 0) {
            std::vector<fs::path> inputs = motion_named_files(in.spec);
            inputs.insert(inputs.end(), {files.case_path, files.motion});
            for (const auto& file : mesh_input_files(files.case_path)) inputs.push_back(file);
            check_openfoam_frame_outputs(files.output, c.time_names, files.case_path, inputs);
        }
        const std::vector<fs::path> processors = openfoam_processor_meshes(files.case_path);
        if (processors.size() != static_cast<std::size_t>(processes))
            throw FormatError(files.case_path.string() + ": " + std::to_string(processors.size()) +
                              " processor folders for " + std::to_string(processes) + " processes");
        const fs::path& mine = processors[static_cast<std::size_t>(rank)];
        say("reading " + mine.string());
        OpenFoamProcessorMesh read = read_openfoam_processor(mine);
        c.part.poly_mesh = mine;
        c.part.point_ids = std::move(read.point_ids);
        c.part.cell_ids = std::move(read.cell_ids);
        c.part.points_format = read.points_format;
        interface = std::move(read.interface_nodes);
        in.mesh = std::move(read.mesh);
        for (const Marker& m : in.mesh.markers)
            c.part.marker_elements.push_back(static_cast<std::int64_t>(m.elements.size()));
    });
    in.read_seconds = sw.lap();

    // The same patches, in the same order, on every process.
    std::string names;
    for (const Marker& m : in.mesh.markers) names += m.name + "\n";
    const std::string names0 = broadcast_text(comm, names);
    collectively(comm, [&] {
        if (names != names0)
            throw ParseError((c.part.poly_mesh / "boundary").string(), 0,
                             "the patches of processor 0, in the same order (decomposePar writes every patch to every "
                             "processor)",
                             "other patches");
    });

    // The boundary: each process's nodes on the markers every process has them on.
    say("classifying the boundary");
    c.part.owned = share_interface_markers(comm, in.mesh, interface, c.part.point_ids);
    // The tolerance one process takes: 1e-9 × the whole case's bounding-box diagonal.
    if (in.spec.shared_tolerance <= 0) in.spec.shared_tolerance = 1e-9 * bounding_box_diagonal_over_parts(comm, in.mesh);
    collectively(comm, [&] {
        in.boundary = resolve_boundary(in.mesh, in.spec);
        // Each process holds its processor's part only; the sliding nodes'
        // first pass needs every boundary node (run/slide_pass.hpp).
        if (!in.boundary.sliding_markers.empty())
            throw Error("marker '" + in.boundary.sliding_markers.front() +
                        "' slides: sliding markers are not supported when each process reads its own processor "
                        "folder; run on one process, or on the reconstructed case");
    });
    c.counts = case_counts(comm, in.mesh, c.part);
    for (std::size_t b = 0; b < in.boundary.boundary.nodes.size(); ++b)
        if (c.part.owned[static_cast<std::size_t>(in.boundary.boundary.nodes[b])]) {
            ++c.boundary_nodes;
            c.moving_nodes += in.boundary.boundary.moving[b];
        }
    c.boundary_nodes = sum(comm, c.boundary_nodes);
    c.moving_nodes = sum(comm, c.moving_nodes);
    in.resolve_seconds = sw.lap();

    // The original quality, judged by the whole case's majority orientation per cell type.
    say("measuring the original mesh's quality");
    std::vector<std::int8_t> own = cell_orientations(in.mesh);
    std::vector<std::int8_t> orientation = dominant_orientations_over_parts(comm, in.mesh, own);
    in.original = measure_original(in.mesh, std::move(own), std::move(orientation));
    in.original.summary = quality_over_parts(comm, in.original.quality, c.part.cell_ids);
    warn_already_inverted(in);
    in.boundary.warnings =
        warnings_over_parts(comm, in.boundary.warnings,
                            sum(comm, owned_moving_and_static(in.mesh, in.boundary, c.part.owned)),
                            in.spec.shared_nodes);
    in.quality_seconds = sw.lap();
    return c;
}

RunReport run_processor_job(MPI_Comm comm, const JobInputs& in, const ProcessorCase& c, const PartPlan& plan,
                            const ProcessorRunOptions& options, const ProcessorRunCallbacks& callbacks) {
    bool base_written = false;
    const PartRunContext ctx{comm, in.mesh, in.spec, in.boundary, in.original, plan, c.part.cell_ids, c.part.point_ids};
    PartRunCallbacks on;
    on.frame_started = callbacks.frame_started;
    on.frame_done = [&](const PartFrameView& view) {
        const FrameReport& r = view.report;
        ProcessorFrame frame{view, {}, 0};
        if (r.valid() || options.write_invalid) {
            Stopwatch sw;
            frame.written = write_processor_points(comm, c.output, c.time_names[view.frame], c.part,
                                                   view.points, base_written);
            frame.write_seconds = sw.lap();
        }
        return callbacks.frame_done ? callbacks.frame_done(frame) : true;
    };
    RunOptions run_options;
    run_options.frame.repair = options.last_resort ? Repair::method_default : Repair::none;
    run_options.stop_at_invalid = false;  // frame_done decides
    return run_frames_on_parts(ctx, run_options, on);
}

fs::path write_processor_points(MPI_Comm comm, const fs::path& out, const std::string& time, const ProcessorPart& part,
                                std::span<const double> points, bool& base_written) {
    const fs::path folder = out / ("processor" + std::to_string(rank_in(comm)));
    const OpenFoamPointsFile file = openfoam_points_file(folder, time);
    const fs::path tmp = file.file.string() + ".dgwarp-part";
    collectively(comm, [&] {
        try {
            if (!base_written) {
                const fs::path base = openfoam_output_poly_mesh(folder);
                std::error_code ec;
                if (!fs::equivalent(base, part.poly_mesh, ec)) {
                    const bool points_here = file.file.parent_path() == base;
                    copy_poly_mesh(part.poly_mesh, base,
                                   points_here ? std::vector<std::string>{"points", "points.gz"} : std::vector<std::string>{});
                }
                base_written = true;
            }
            write_openfoam_points(tmp, points, part.points_format, file.location);
        } catch (...) {
            std::error_code ec;
            fs::remove(tmp, ec);
            throw;
        }
    });
    // Every process has its new points beside the old: each renames its own
    // (an error in a rename leaves the other processes' files renamed).
    collectively(comm, [&] {
        std::error_code ec;
        fs::rename(tmp, file.file, ec);
        if (ec) {
            fs::remove(tmp, ec);
            throw IoError(file.file.string(), "cannot rename " + tmp.string() + " to it: " + ec.message());
        }
    });
    return file.file;
}

}  // namespace dgwarp::mpi
