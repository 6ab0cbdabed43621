#include "dgwarp/mpi/morton_partition.hpp"

#include <numeric>

#include "dgwarp/graph/morton_order.hpp"

namespace dgwarp::mpi {

std::vector<std::int32_t> morton_cell_parts(const Mesh& mesh, int parts) {
    const std::size_t cells = mesh.cells.types.size();
    const int dim = mesh.dim;
    std::vector<double> centroids(cells * dim, 0.0);
    for (std::size_t c = 0; c < cells; ++c) {
        const std::int64_t begin = mesh.cells.offsets[c], end = mesh.cells.offsets[c + 1];
        for (std::int64_t k = begin; k < end; ++k)
            for (int d = 0; d < dim; ++d)
                centroids[c * dim + d] += mesh.points[static_cast<std::size_t>(mesh.cells.nodes[k]) * dim + d];
        for (int d = 0; d < dim; ++d) centroids[c * dim + d] /= static_cast<double>(end - begin);
    }
    std::vector<NodeId> ids(cells);
    std::iota(ids.begin(), ids.end(), 0);
    const std::vector<std::uint32_t> order = morton_order(dim, centroids, ids);
    std::vector<std::int32_t> part(cells, 0);
    for (std::size_t k = 0; k < cells; ++k)
        part[order[k]] = static_cast<std::int32_t>(k * static_cast<std::size_t>(parts) / cells);
    return part;
}

}  // namespace dgwarp::mpi
