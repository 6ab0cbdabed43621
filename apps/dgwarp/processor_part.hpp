#pragma once
// Under mpirun on a decomposed OpenFOAM case (deform_processors.hpp): what a
// process holds of the case besides its part of the mesh, and what the
// processes share about their parts. Collective: every process calls them.
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "deform_setup.hpp"
#include "dgwarp/io/openfoam/openfoam.hpp"
#include "report.hpp"

namespace dgwarp::cli {

/// What this process holds of the case, beyond its part of the mesh.
struct ProcessorPart {
    std::filesystem::path poly_mesh;      // CASE/processor<r>/constant/polyMesh
    std::vector<std::int64_t> point_ids;  // pointProcAddressing
    std::vector<std::int64_t> cell_ids;   // cellProcAddressing
    foam::Format points_format = foam::Format::ascii;
    std::vector<std::uint8_t> owned;      // per point: this process is the lowest rank holding it (mpi::share_interface_markers)
    std::vector<std::int64_t> marker_elements;  // per marker: its faces here (before shared nodes were added)
};

/// The whole case's counts (describe_mesh, mesh_json), from every process's part.
MeshCounts case_counts(const Mesh& mesh, const ProcessorPart& part);

/// The boundary nodes this process owns that are on a moving and on a static marker.
std::int64_t owned_moving_and_static(const Mesh& mesh, const ResolvedBoundary& b, const std::vector<std::uint8_t>& owned);

/// Writes this process's points of frame `time` into its processor folder of
/// `out` (OUT/processor<r>/<time>/polyMesh/points; first, unless
/// `base_written`, a copy of its constant/polyMesh when OUT is not the input):
/// to a temporary file beside the points file, renamed into place only when
/// every process wrote its own, so that an error on one leaves no process's
/// new points (every process throws it). Returns the points file.
std::filesystem::path write_processor_points(const std::filesystem::path& out, const std::string& time,
                                             const ProcessorPart& part, std::span<const double> points,
                                             bool& base_written);

}  // namespace dgwarp::cli
