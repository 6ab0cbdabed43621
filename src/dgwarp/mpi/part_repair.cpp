// part_repair.hpp: the last resort over the parts, on a patch every process builds alike.
#include "dgwarp/mpi/part_repair.hpp"

#include <algorithm>
#include <iterator>
#include <vector>

#include "dgwarp/core/error.hpp"
#include "dgwarp/mpi/agreement.hpp"
#include "dgwarp/mpi/large_transfers.hpp"
#include "dgwarp/mpi/reductions.hpp"
#include "dgwarp/repair/last_resort.hpp"
#include "dgwarp/repair/unrepairable_cells.hpp"

namespace dgwarp::mpi {

namespace {

std::vector<std::int64_t> sorted_unique(std::vector<std::int64_t> v) {
    std::sort(v.begin(), v.end());
    v.erase(std::unique(v.begin(), v.end()), v.end());
    return v;
}

bool holds(const std::vector<std::int64_t>& sorted, std::int64_t id) {
    return std::binary_search(sorted.begin(), sorted.end(), id);
}

std::size_t index_of(const std::vector<std::int64_t>& sorted, std::int64_t id) {
    return static_cast<std::size_t>(std::lower_bound(sorted.begin(), sorted.end(), id) - sorted.begin());
}

/// The patch every process builds from what all of them gathered.
struct Patch {
    std::vector<std::int64_t> nodes;  // whole-mesh ids, sorted: node i of the patch
    Mesh mesh;
    std::vector<std::int8_t> orientation;
    std::vector<NodeId> fixed;
    std::vector<std::int64_t> folded;  // patch cells
};

/// This process's cells touching `inner`, as records: cell id, type,
/// orientation, node count, the nodes' whole-mesh ids, face count, then each
/// face's size and nodes (a polyhedron's).
std::vector<std::int64_t> cell_records(const Mesh& mesh, std::span<const std::int8_t> orientation,
                                       std::span<const std::int64_t> node_ids, std::span<const std::int64_t> cell_ids,
                                       const std::vector<std::int64_t>& inner) {
    std::vector<std::int64_t> r;
    const ElementList& cells = mesh.cells;
    for (std::size_t c = 0; c < cells.size(); ++c) {
        const auto nodes = cells.nodes_of(c);
        if (std::none_of(nodes.begin(), nodes.end(), [&](NodeId n) { return holds(inner, node_ids[n]); })) continue;
        r.insert(r.end(), {cell_ids[c], static_cast<std::int64_t>(cells.types[c]), orientation[c],
                           static_cast<std::int64_t>(nodes.size())});
        for (NodeId n : nodes) r.push_back(node_ids[n]);
        const auto [first, last] = cells.faces_of(c);
        r.push_back(last - first);
        for (std::int64_t f = first; f < last; ++f) {
            const auto ring = cells.face_nodes_of(f);
            r.push_back(static_cast<std::int64_t>(ring.size()));
            for (NodeId n : ring) r.push_back(node_ids[n]);
        }
    }
    return r;
}

/// The patch's cells from every process's records, in whole-mesh cell order
/// (a cell several processes hold, once); returns their whole-mesh ids.
std::vector<std::int64_t> add_cells(Patch& p, const std::vector<std::int64_t>& records) {
    struct Cell {
        std::int64_t id;
        std::size_t at;  // its record
    };
    std::vector<Cell> cells;
    for (std::size_t at = 0; at < records.size();) {
        cells.push_back({records[at], at});
        std::size_t next = at + 4 + static_cast<std::size_t>(records[at + 3]);
        const auto faces = records[next++];
        for (std::int64_t f = 0; f < faces; ++f) next += 1 + static_cast<std::size_t>(records[next]);
        at = next;
    }
    std::stable_sort(cells.begin(), cells.end(), [](const Cell& a, const Cell& b) { return a.id < b.id; });
    cells.erase(std::unique(cells.begin(), cells.end(), [](const Cell& a, const Cell& b) { return a.id == b.id; }),
                cells.end());
    std::vector<NodeId> nodes, rings;
    std::vector<int> sizes;
    for (const Cell& cell : cells) {
        const std::int64_t* r = records.data() + cell.at;
        const auto type = static_cast<CellType>(r[1]);
        p.orientation.push_back(static_cast<std::int8_t>(r[2]));
        const std::int64_t* f = r + 4 + r[3];
        const std::int64_t faces = *f++;
        if (type != CellType::polyhedron) {
            nodes.clear();
            for (std::int64_t k = 0; k < r[3]; ++k) nodes.push_back(static_cast<NodeId>(index_of(p.nodes, r[4 + k])));
            p.mesh.cells.push_back(type, nodes);
            continue;
        }
        rings.clear();
        sizes.clear();
        for (std::int64_t k = 0; k < faces; ++k) {
            const std::int64_t n = *f++;
            sizes.push_back(static_cast<int>(n));
            for (std::int64_t j = 0; j < n; ++j) rings.push_back(static_cast<NodeId>(index_of(p.nodes, *f++)));
        }
        p.mesh.cells.push_polyhedron(rings, sizes);
    }
    std::vector<std::int64_t> ids;
    for (const Cell& cell : cells) ids.push_back(cell.id);
    return ids;
}

}  // namespace

std::optional<UntangleReport> last_resort_over_parts(MPI_Comm comm, const Mesh& mesh,
                                                     std::span<const std::int8_t> own_orientation,
                                                     std::span<const std::int64_t> node_ids,
                                                     std::span<const std::int64_t> cell_ids,
                                                     std::span<const NodeId> fixed,
                                                     std::span<const std::int64_t> folded, std::span<double> points) {
    collectively(comm, [&] {
        if (node_ids.size() != mesh.num_points() || cell_ids.size() != mesh.cells.size() ||
            own_orientation.size() != mesh.cells.size() || points.size() != mesh.points.size())
            throw MeshError("last_resort_over_parts: " + std::to_string(node_ids.size()) + " node ids, " +
                            std::to_string(cell_ids.size()) + " cell ids, " + std::to_string(own_orientation.size()) +
                            " orientations and " + std::to_string(points.size()) + " coordinates for " +
                            std::to_string(mesh.num_points()) + " nodes and " + std::to_string(mesh.cells.size()) +
                            " cells");
    });
    const ElementList& cells = mesh.cells;
    if (sum(comm, static_cast<std::int64_t>(folded.size())) == 0) return std::nullopt;
    // As run_last_resort: nothing runs where the boundary motion itself folds
    // a cell (every node of it fixed: no repair of the volume can help).
    std::int64_t pinned = 0;
    collectively(comm, [&] { pinned = static_cast<std::int64_t>(cells_with_only_fixed_nodes(cells, fixed, folded).size()); });
    if (sum(comm, pinned) > 0) return std::nullopt;
    std::vector<std::int64_t> folded_ids;
    for (std::int64_t c : folded) folded_ids.push_back(cell_ids[static_cast<std::size_t>(c)]);
    const std::vector<std::int64_t> all_folded = sorted_unique(all_gather(comm, folded_ids));

    // Level 0: the nodes of the cells the repair sets out to mend on every
    // process (the folded ones with a free node); level l + 1: the other
    // nodes of the cells touching level l.
    std::vector<std::int64_t> seeds, mine;
    UntangleReport census;  // this process's cells at or below zero quality, counted as one process counts them
    collectively(comm, [&] {
        seeds = cells_to_untangle(mesh.dim, cells, own_orientation, fixed, points, last_resort_untangle_options(folded),
                                  &census);
    });
    // Over every process (each cell held by one): the report's counts of the whole mesh.
    const std::int64_t inverted = sum(comm, census.inverted_before), below = sum(comm, census.below_target_before);
    for (std::int64_t c : seeds)
        for (NodeId n : cells.nodes_of(static_cast<std::size_t>(c))) mine.push_back(node_ids[n]);
    std::vector<std::vector<std::int64_t>> levels{sorted_unique(all_gather(comm, mine))};
    std::vector<std::int64_t> reached = levels[0];  // every level so far
    const auto grow = [&](int rings) {
        while (static_cast<int>(levels.size()) <= rings) {
            mine.clear();
            for (std::size_t c = 0; c < cells.size(); ++c) {
                const auto nodes = cells.nodes_of(c);
                if (std::none_of(nodes.begin(), nodes.end(), [&](NodeId n) { return holds(levels.back(), node_ids[n]); }))
                    continue;
                for (NodeId n : nodes)
                    if (!holds(reached, node_ids[n])) mine.push_back(node_ids[n]);
            }
            levels.push_back(sorted_unique(all_gather(comm, mine)));
            std::vector<std::int64_t> all = reached;
            all.insert(all.end(), levels.back().begin(), levels.back().end());
            reached = sorted_unique(std::move(all));
        }
    };

    const int dim = mesh.dim;
    const auto d_ = static_cast<std::size_t>(dim);
    for (int rings = part_repair_rings;;) {
        grow(rings);
        // The patch: the nodes up to level `rings` (every level grown so far),
        // the cells touching the levels below it (`inner`).
        Patch p;
        p.nodes = reached;
        std::vector<std::int64_t> inner;
        const std::vector<std::int64_t>& edge = levels[static_cast<std::size_t>(rings)];
        std::set_difference(reached.begin(), reached.end(), edge.begin(), edge.end(), std::back_inserter(inner));
        // Every process's cells touching the inner levels, the coordinates of
        // its nodes in the patch, its boundary nodes there.
        std::vector<std::int64_t> held_ids, boundary_ids;
        std::vector<double> held_points;
        for (std::size_t n = 0; n < mesh.num_points(); ++n) {
            if (!holds(p.nodes, node_ids[n])) continue;
            held_ids.push_back(node_ids[n]);
            for (std::size_t d = 0; d < d_; ++d) held_points.push_back(points[n * d_ + d]);
        }
        for (NodeId n : fixed)
            if (holds(p.nodes, node_ids[n])) boundary_ids.push_back(node_ids[n]);
        const std::vector<std::int64_t> records =
            all_gather(comm, cell_records(mesh, own_orientation, node_ids, cell_ids, inner));
        const std::vector<std::int64_t> all_held = all_gather(comm, held_ids);
        const std::vector<double> all_points = detail::allgather_records<double>(comm, held_points);
        const std::vector<std::int64_t> all_boundary = sorted_unique(all_gather(comm, boundary_ids));

        // Every process repairs the same patch, and so decides alike.
        std::optional<UntangleReport> report;
        int moved_level = -1;  // the farthest level a node moved at
        collectively(comm, [&] {
            p.mesh.dim = dim;
            p.mesh.points.assign(p.nodes.size() * d_, 0.0);
            for (std::size_t k = 0; k < all_held.size(); ++k)
                std::copy_n(all_points.begin() + static_cast<std::ptrdiff_t>(k * d_), dim,
                            p.mesh.points.begin() + static_cast<std::ptrdiff_t>(index_of(p.nodes, all_held[k]) * d_));
            const std::vector<std::int64_t> patch_cell_ids = add_cells(p, records);
            // Held: the boundary's nodes, and those of the last level (some of their cells are not in the patch).
            for (std::size_t i = 0; i < p.nodes.size(); ++i)
                if (holds(all_boundary, p.nodes[i]) || !holds(inner, p.nodes[i])) p.fixed.push_back(static_cast<NodeId>(i));
            for (std::int64_t id : all_folded) {
                if (!holds(patch_cell_ids, id))
                    throw Error("last_resort_over_parts: folded cell " + std::to_string(id) + " is not in the patch");
                p.folded.push_back(static_cast<std::int64_t>(index_of(patch_cell_ids, id)));
            }
            const std::vector<double> before = p.mesh.points;
            report = run_last_resort(dim, p.mesh.cells, p.orientation, p.fixed, p.folded, p.mesh.points);
            for (int l = 0; l <= rings; ++l)
                for (std::int64_t id : levels[static_cast<std::size_t>(l)]) {
                    const std::size_t i = index_of(p.nodes, id);
                    if (!std::equal(before.begin() + static_cast<std::ptrdiff_t>(i * d_),
                                    before.begin() + static_cast<std::ptrdiff_t>((i + 1) * d_),
                                    p.mesh.points.begin() + static_cast<std::ptrdiff_t>(i * d_)))
                        moved_level = std::max(moved_level, l);
                }
        });
        // The repair reads and moves nodes within a few rings of the cells it
        // mends, and mends the cells around the nodes it moved: beyond
        // level moved_level + 1 + its rounds + 2, nothing. When that reaches
        // the held edge, the patch is grown and the repair run again.
        const int needed = std::max(part_repair_rings, moved_level + 1 + last_resort_max_rounds + 2);
        if (!report || needed <= rings || rings >= part_repair_max_rings) {
            if (report) {
                // The cells outside the patch do not change: counted before and after.
                report->inverted_after += inverted - report->inverted_before;
                report->inverted_before = inverted;
                report->below_target_after += below - report->below_target_before;
                report->below_target_before = below;
                // This process's nodes where the repair put them.
                for (std::size_t n = 0; n < mesh.num_points(); ++n) {
                    if (!holds(p.nodes, node_ids[n])) continue;
                    const std::size_t i = index_of(p.nodes, node_ids[n]);
                    std::copy_n(p.mesh.points.begin() + static_cast<std::ptrdiff_t>(i * d_), dim,
                                points.begin() + static_cast<std::ptrdiff_t>(n * d_));
                }
            }
            return report;
        }
        rings = std::min(needed, part_repair_max_rings);
    }
}

}  // namespace dgwarp::mpi
