#pragma once
// A deformation job on a decomposed OpenFOAM case under MPI, as a solver's
// decomposition holds it: process r reads only CASE/processor<r> (its
// polyMesh, pointProcAddressing and cellProcAddressing), classifies its
// boundary and judges its cells as one process does over the whole case,
// prepares and deforms with the distributed plans (mpi/part_run.hpp), and
// writes only OUT/processor<r>; no process holds the whole mesh. Collective:
// every process of `comm` (as many as processor folders) calls each function,
// in the same order; a failure on one is raised on every process
// (mpi/agreement.hpp). docs/MPI.md.
//
//   JobInputs in;
//   const ProcessorCase c = read_processor_job(comm, {case_path, motion, out}, in);
//   const PartPlan plan = prepare_part(comm, method, 3, in.mesh.points, c.part.point_ids, in.boundary.boundary, options);
//   run_processor_job(comm, in, c, plan, {}, {.frame_done = [&](const ProcessorFrame& f) { return report(f); }});
#include <mpi.h>

#include <cstdint>
#include <filesystem>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "dgwarp/io/openfoam/openfoam.hpp"
#include "dgwarp/job/job_inputs.hpp"
#include "dgwarp/mesh/mesh_counts.hpp"
#include "dgwarp/mpi/part_run.hpp"
#include "dgwarp/mpi/root_session.hpp"

namespace dgwarp::mpi {

/// Whether `case_path` can be deformed with each of `processes` processes on
/// its own processor folder under `spec`: "" when it can; else why not (the
/// whole case must then be read on one process): not a decomposed case of
/// that many processors, a marker moved by a per-node table (its node ids are
/// the whole case's), a cyclic patch (a node's image may be on another
/// processor), or a sliding marker, by the motion or by its patch type (its
/// first pass needs every boundary node). Reads the motion file and the first
/// processor's boundary file; errors become the reason. Not collective.
std::string processor_job_refusal(const std::filesystem::path& case_path, const std::filesystem::path& motion,
                                  int processes);

/// What this process holds of the case, beyond its part of the mesh.
struct ProcessorPart {
    std::filesystem::path poly_mesh;      // CASE/processor<r>/constant/polyMesh
    std::vector<std::int64_t> point_ids;  // pointProcAddressing
    std::vector<std::int64_t> cell_ids;   // cellProcAddressing
    foam::Format points_format = foam::Format::ascii;
    std::vector<std::uint8_t> owned;      // per point: this process is the lowest rank holding it (share_interface_markers)
    std::vector<std::int64_t> marker_elements;  // per marker: its faces here (before shared nodes were added)
};

/// What a job holds of the case besides its inputs (JobInputs over this
/// process's part), and what the processes agreed about the whole case.
struct ProcessorCase {
    ProcessorPart part;
    std::filesystem::path output;         // the case written (each process its processor folder)
    std::vector<std::string> time_names;  // per frame, its time folder
    MeshCounts counts;                    // the whole case's (each node and cell once)
    std::int64_t boundary_nodes = 0, moving_nodes = 0;  // the whole case's, each node once
};

struct ProcessorJobFiles {
    std::filesystem::path case_path;  // a decomposed case of as many processor folders as processes
    std::filesystem::path motion;     // a motion file (io/motion_file.hpp)
    std::filesystem::path output;     // the case written; may be case_path
    /// Each frame's time folder from the motion; default: openfoam_time_names of the frames' times.
    std::function<std::vector<std::string>(const MotionSpec&)> time_names{};
};

/// Every process reads the motion and its own processor folder (rank 0
/// first checks the outputs: check_openfoam_frame_outputs), checks that every
/// processor has the same patches in the same order, shares the markers of
/// the nodes several processors hold (share_interface_markers), resolves its
/// boundary with the whole case's shared-node tolerance, and measures its
/// original cells as judged over the whole case (dominant_orientations_over_parts),
/// with the boundary's warnings reduced to rank 0 (warnings_over_parts) and
/// the inputs' counts summed: `in` over this process's part (its mesh, the
/// motion, its boundary resolved, its original cells, the times of each
/// phase), and the rest returned. `phase`: each phase's name, as it starts.
ProcessorCase read_processor_job(MPI_Comm comm, const ProcessorJobFiles& files, JobInputs& in,
                                 const std::function<void(const std::string&)>& phase = {});

/// A frame as run_processor_job's callback sees it, on every process.
struct ProcessorFrame {
    const PartFrameView& view;
    std::filesystem::path written;  // this process's points file; empty when not written
    double write_seconds = 0;
};

struct ProcessorRunOptions {
    /// Write a frame with cells the motion inverted (else nothing of it is written).
    bool write_invalid = false;
    /// dg-harmonic's last resort: the cells its step inverts repaired over
    /// the processes (mpi/part_repair.hpp), as one process repairs them.
    bool last_resort = true;
};

struct ProcessorRunCallbacks {
    /// Before frame k's step, on every process.
    std::function<void(std::size_t frame)> frame_started{};
    /// Each frame, after its points are written, on every process; false on
    /// any process stops the run on all.
    std::function<bool(const ProcessorFrame&)> frame_done{};
};

/// Every frame of in.spec in order with `plan` (prepare_part over the
/// part): stepped, measured over the whole case, and written into each
/// process's processor folder of c.output (write_processor_points) unless
/// its cells are inverted (options.write_invalid), then given to
/// `on.frame_done`. Returns the run's report.
RunReport run_processor_job(MPI_Comm comm, const JobInputs& in, const ProcessorCase& c, const PartPlan& plan,
                            const ProcessorRunOptions& options, const ProcessorRunCallbacks& on = {});

/// Writes this process's points of frame `time` into its processor folder of
/// `out` (OUT/processor<r>/<time>/polyMesh/points; first, unless
/// `base_written`, a copy of its constant/polyMesh when OUT is not the input):
/// to a temporary file beside the points file, renamed into place only when
/// every process wrote its own, so that an error on one leaves no process's
/// new points (every process throws it). Returns the points file.
std::filesystem::path write_processor_points(MPI_Comm comm, const std::filesystem::path& out, const std::string& time,
                                             const ProcessorPart& part, std::span<const double> points,
                                             bool& base_written);

}  // namespace dgwarp::mpi
