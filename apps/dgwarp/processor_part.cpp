// processor_part.hpp: what the processes share about their parts of a decomposed case.
#include "processor_part.hpp"

#include <algorithm>
#include <unordered_map>

#include "dgwarp/core/atomic_write.hpp"
#include "dgwarp/core/error.hpp"
#include "mpi_session.hpp"

namespace dgwarp::cli {

namespace fs = std::filesystem;


void share_interface_markers(Mesh& mesh, const std::vector<NodeId>& interface, ProcessorPart& part) {
    const int rank = mpi_rank();
    std::vector<std::uint8_t> on_interface(mesh.num_points(), 0);
    for (NodeId n : interface) on_interface[static_cast<std::size_t>(n)] = 1;
    std::unordered_map<std::int64_t, NodeId> local_of;
    local_of.reserve(interface.size());
    std::vector<std::int64_t> ids;
    for (NodeId n : interface) {
        local_of.emplace(part.point_ids[static_cast<std::size_t>(n)], n);
        ids.push_back(part.point_ids[static_cast<std::size_t>(n)]);
    }
    // Owners: the lowest rank holding each interface point.
    std::vector<std::int64_t> counts;
    const std::vector<std::int64_t> all_ids = mpi_all_gather(ids, &counts);
    part.owned.assign(mesh.num_points(), 1);
    std::size_t at = 0;
    for (int r = 0; r < static_cast<int>(counts.size()); ++r)
        for (std::int64_t k = 0; k < counts[static_cast<std::size_t>(r)]; ++k, ++at)
            if (r < rank)
                if (const auto it = local_of.find(all_ids[at]); it != local_of.end())
                    part.owned[static_cast<std::size_t>(it->second)] = 0;
    // (point id, marker) of every interface point on a marker, from every process.
    std::vector<std::vector<NodeId>> nodes_of(mesh.markers.size());
    std::vector<std::int64_t> pairs;
    for (std::size_t m = 0; m < mesh.markers.size(); ++m) {
        nodes_of[m] = marker_nodes(mesh.markers[m]);
        for (NodeId n : nodes_of[m])
            if (on_interface[static_cast<std::size_t>(n)])
                pairs.insert(pairs.end(), {part.point_ids[static_cast<std::size_t>(n)], static_cast<std::int64_t>(m)});
    }
    const std::vector<std::int64_t> all_pairs = mpi_all_gather(pairs);
    std::vector<std::vector<NodeId>> extra(mesh.markers.size());
    for (std::size_t k = 0; k + 1 < all_pairs.size(); k += 2) {
        const auto it = local_of.find(all_pairs[k]);
        const auto m = static_cast<std::size_t>(all_pairs[k + 1]);
        if (it == local_of.end() || m >= mesh.markers.size()) continue;
        if (!std::binary_search(nodes_of[m].begin(), nodes_of[m].end(), it->second)) extra[m].push_back(it->second);
    }
    for (std::size_t m = 0; m < mesh.markers.size(); ++m) {
        std::sort(extra[m].begin(), extra[m].end());
        extra[m].erase(std::unique(extra[m].begin(), extra[m].end()), extra[m].end());
        for (NodeId n : extra[m]) mesh.markers[m].elements.push_back(CellType::vertex, {&n, 1});
    }
}

MeshCounts case_counts(const Mesh& mesh, const ProcessorPart& part) {
    MeshCounts c = mesh_counts(mesh);
    std::int64_t largest = -1;
    for (std::int64_t id : part.point_ids) largest = std::max(largest, id);
    c.nodes = mpi_max(largest) + 1;
    c.cells = mpi_sum(c.cells);
    c.cell_types = mpi_sum(c.cell_types);
    std::vector<std::int64_t> elements(part.marker_elements), nodes;
    for (const Marker& m : mesh.markers) {
        std::int64_t owned = 0;
        for (NodeId n : marker_nodes(m)) owned += part.owned[static_cast<std::size_t>(n)];
        nodes.push_back(owned);
    }
    elements = mpi_sum(elements);
    nodes = mpi_sum(nodes);
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
                                const std::vector<double>& points, bool& base_written) {
    const fs::path folder = out / ("processor" + std::to_string(mpi_rank()));
    const OpenFoamPointsFile file = openfoam_points_file(folder, time);
    const fs::path tmp = file.file.string() + ".dgwarp-part";
    mpi_collectively([&] {
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
    mpi_collectively([&] {
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
