#pragma once
// The MPI test programs' partitions of a mesh read whole by every process:
// each process keeps the nodes of the cells given to it (mpi_same_bits.cpp,
// mpi_failures.cpp); and the rect-box's boundary they move.
#include <algorithm>
#include <cstdint>
#include <vector>

#include "dgwarp/mesh/mesh.hpp"
#include "dgwarp/motion/node_motion.hpp"
#include "dgwarp/motion/resolve_motion.hpp"

namespace dgwarp::test {

struct Part {
    std::vector<double> points;
    std::vector<std::int64_t> global_ids;
    BoundarySet boundary;
    std::vector<std::int32_t> boundary_slot;  // per local boundary node: its index in the whole BoundarySet
};

enum class Partition { block, round_robin, round_robin_lowest_lists };

inline const char* partition_name(Partition p) {
    return p == Partition::block ? "block" : p == Partition::round_robin ? "round-robin" : "round-robin, boundary listed once";
}

// The nodes of the cells `owner` gives this rank, in first-use order. With
// round_robin_lowest_lists, a boundary node is listed as one only by the
// lowest rank holding it (the others hold it as a plain node, as a solver's
// partition may hold an interface node whose boundary faces are elsewhere).
inline Part make_part(const Mesh& mesh, const BoundarySet& whole, int rank, int size, Partition partition) {
    const std::size_t cells = mesh.cells.types.size();
    const bool round_robin = partition != Partition::block;
    std::vector<std::int32_t> local(mesh.num_points(), -1), lowest(mesh.num_points(), size);
    for (std::size_t c = 0; c < cells; ++c)
        for (std::int64_t k = mesh.cells.offsets[c]; k < mesh.cells.offsets[c + 1]; ++k)
            lowest[mesh.cells.nodes[k]] = std::min(lowest[mesh.cells.nodes[k]], static_cast<std::int32_t>(c % size));
    Part p;
    for (std::size_t c = 0; c < cells; ++c) {
        const int owner = round_robin ? static_cast<int>(c % size) : static_cast<int>(c * size / cells);
        if (owner != rank) continue;
        for (std::int64_t k = mesh.cells.offsets[c]; k < mesh.cells.offsets[c + 1]; ++k) {
            const NodeId n = mesh.cells.nodes[k];
            if (local[n] >= 0) continue;
            local[n] = static_cast<std::int32_t>(p.global_ids.size());
            p.global_ids.push_back(n);
            for (int d = 0; d < mesh.dim; ++d) p.points.push_back(mesh.points[static_cast<std::size_t>(n) * mesh.dim + d]);
        }
    }
    for (std::size_t b = 0; b < whole.nodes.size(); ++b) {
        const std::int32_t l = local[whole.nodes[b]];
        if (l < 0) continue;
        if (partition == Partition::round_robin_lowest_lists && lowest[whole.nodes[b]] != rank) continue;
        p.boundary.nodes.push_back(l);
        p.boundary.moving.push_back(whole.moving[b]);
        p.boundary_slot.push_back(static_cast<std::int32_t>(b));
    }
    // BoundarySet order: ascending local index.
    std::vector<std::size_t> order(p.boundary.nodes.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return p.boundary.nodes[a] < p.boundary.nodes[b]; });
    Part sorted = p;
    for (std::size_t i = 0; i < order.size(); ++i) {
        sorted.boundary.nodes[i] = p.boundary.nodes[order[i]];
        sorted.boundary.moving[i] = p.boundary.moving[order[i]];
        sorted.boundary_slot[i] = p.boundary_slot[order[i]];
    }
    return sorted;
}

// The rect-box's boundary: the rectangle moving, the far field static (as a motion file moving the rectangle says).
inline BoundarySet rect_box_boundary(const Mesh& mesh) {
    MotionSpec spec;
    spec.frames.resize(1);
    spec.frames[0].markers["rectangle"] = RigidMotion{};
    return resolve_boundary(mesh, spec).boundary;
}

}  // namespace dgwarp::test
