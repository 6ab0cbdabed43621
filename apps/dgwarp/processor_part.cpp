// processor_part.hpp: what the processes share about their parts of a decomposed case.
#include "processor_part.hpp"

#include <mpi.h>

#include <algorithm>

#include "dgwarp/core/atomic_write.hpp"
#include "dgwarp/core/error.hpp"
#include "dgwarp/mpi/agreement.hpp"
#include "dgwarp/mpi/reductions.hpp"
#include "mpi_session.hpp"

namespace dgwarp::cli {

namespace fs = std::filesystem;


MeshCounts case_counts(const Mesh& mesh, const ProcessorPart& part) {
    MeshCounts c = mesh_counts(mesh);
    std::int64_t largest = -1;
    for (std::int64_t id : part.point_ids) largest = std::max(largest, id);
    c.nodes = mpi::max(MPI_COMM_WORLD, largest) + 1;
    c.cells = mpi::sum(MPI_COMM_WORLD, c.cells);
    c.cell_types = mpi::sum(MPI_COMM_WORLD, c.cell_types);
    std::vector<std::int64_t> elements(part.marker_elements), nodes;
    for (const Marker& m : mesh.markers) {
        std::int64_t owned = 0;
        for (NodeId n : marker_nodes(m)) owned += part.owned[static_cast<std::size_t>(n)];
        nodes.push_back(owned);
    }
    elements = mpi::sum(MPI_COMM_WORLD, elements);
    nodes = mpi::sum(MPI_COMM_WORLD, nodes);
    for (std::size_t m = 0; m < c.markers.size(); ++m) c.markers[m] = {mesh.markers[m].name, elements[m], nodes[m]};
    return c;
}

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

fs::path write_processor_points(const fs::path& out, const std::string& time, const ProcessorPart& part,
                                std::span<const double> points, bool& base_written) {
    const fs::path folder = out / ("processor" + std::to_string(mpi_rank()));
    const OpenFoamPointsFile file = openfoam_points_file(folder, time);
    const fs::path tmp = file.file.string() + ".dgwarp-part";
    mpi::collectively(MPI_COMM_WORLD, [&] {
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
    mpi::collectively(MPI_COMM_WORLD, [&] {
        std::error_code ec;
        fs::rename(tmp, file.file, ec);
        if (ec) {
            fs::remove(tmp, ec);
            throw IoError(file.file.string(), "cannot rename " + tmp.string() + " to it: " + ec.message());
        }
    });
    return file.file;
}

}  // namespace dgwarp::cli
