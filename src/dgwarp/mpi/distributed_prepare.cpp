// prepare_distributed: gather the boundary, (DG-harmonic) select the coarse
// points over the processes, prepare the method on the working nodes, and
// (DG-IDW) agree on which motions go where each step.
#include <algorithm>
#include <cmath>
#include <exception>
#include <iterator>
#include <limits>
#include <numeric>
#include <string>

#include "dgwarp/core/error.hpp"
#include "dgwarp/core/hash.hpp"
#include "dgwarp/core/stopwatch.hpp"
#include "dgwarp/methods/dg_harmonic_on_coarse.hpp"
#include "dgwarp/methods/dg_idw_subset.hpp"
#include "dgwarp/methods/mesh_fingerprint.hpp"
#include "dgwarp/methods/method_inputs.hpp"
#include "dgwarp/methods/option_table.hpp"
#include "dgwarp/mpi/collective_checks.hpp"
#include "dgwarp/mpi/distributed_coarse_points.hpp"
#include "dgwarp/mpi/distributed_plan.hpp"
#include "dgwarp/mpi/distributed_plan_file.hpp"
#include "dgwarp/mpi/gather_boundary.hpp"

namespace dgwarp::mpi {

namespace {

// This process's input problems ("" when fine).
std::string check_local_input(int dim, std::span<const double> points, std::span<const std::int64_t> global_ids,
                              const BoundarySet& boundary) {
    if (dim != 2 && dim != 3) return "dim must be 2 or 3, got " + std::to_string(dim);
    if (points.size() != global_ids.size() * static_cast<std::size_t>(dim))
        return "the point array holds " + std::to_string(points.size()) + " values for " +
               std::to_string(global_ids.size()) + " global ids (dim " + std::to_string(dim) + ")";
    for (std::size_t i = 0; i < global_ids.size(); ++i) {
        if (global_ids[i] < 0 || global_ids[i] > std::numeric_limits<NodeId>::max())
            return "local node " + std::to_string(i) + " has global id " + std::to_string(global_ids[i]) +
                   ", outside 0.." + std::to_string(std::numeric_limits<NodeId>::max());
        for (int d = 0; d < dim; ++d)
            if (!std::isfinite(points[i * static_cast<std::size_t>(dim) + static_cast<std::size_t>(d)]))
                return "local node " + std::to_string(i) + " (global id " + std::to_string(global_ids[i]) +
                       ") has a coordinate that is not finite";
    }
    // Two local nodes with one global id are two copies of one node: at the same coordinates.
    std::vector<std::pair<std::int64_t, std::size_t>> ids(global_ids.size());
    for (std::size_t i = 0; i < ids.size(); ++i) ids[i] = {global_ids[i], i};
    std::sort(ids.begin(), ids.end());
    const auto d = static_cast<std::size_t>(dim);
    for (std::size_t k = 1; k < ids.size(); ++k)
        if (ids[k].first == ids[k - 1].first &&
            !std::equal(points.begin() + static_cast<std::ptrdiff_t>(ids[k].second * d),
                        points.begin() + static_cast<std::ptrdiff_t>(ids[k].second * d + d),
                        points.begin() + static_cast<std::ptrdiff_t>(ids[k - 1].second * d)))
            return "local nodes " + std::to_string(ids[k - 1].second) + " and " + std::to_string(ids[k].second) +
                   " have the same global id " + std::to_string(ids[k].first) + " but other coordinates";
    try {
        // The empty boundary of a process holding volume nodes only is fine.
        if (!boundary.nodes.empty() || !boundary.moving.empty())
            check_points_and_boundary("distributed prepare", dim, points, boundary);
    } catch (const Error& e) {
        return e.what();
    }
    return {};
}

// What every process must give alike: the method, the dimension and every
// option, as one hash (each field listed: the structs have padding).
std::uint64_t setup_fingerprint(Method method, int dim, const MethodOptions& o) {
    // Every option, tuning ones too, exactly (methods/option_table.hpp).
    const std::string text = std::to_string(static_cast<int>(method)) + " " + std::to_string(dim) + "\n" +
                             method_options_text(o);
    return hash64_of(std::as_bytes(std::span<const char>(text)));
}

// "" when this process's method, dimension and options are process 0's; else what differs.
std::string check_same_setup(MPI_Comm comm, Method method, int dim, const MethodOptions& options) {
    const std::uint64_t mine = setup_fingerprint(method, dim, options);
    std::uint64_t first[3] = {mine, static_cast<std::uint64_t>(method), static_cast<std::uint64_t>(dim)};
    MPI_Bcast(first, 3, MPI_UINT64_T, 0, comm);
    if (first[0] == mine) return {};
    const auto named = [](std::uint64_t m) {
        return m < std::size(all_methods) ? std::string(method_name(static_cast<Method>(m))) : std::to_string(m);
    };
    return "its method, dimension or options (" + std::string(method_name(method)) + ", " + std::to_string(dim) +
           "D) are not process 0's (" + named(first[1]) + ", " + std::to_string(first[2]) +
           "D): every process must prepare the same method with the same options";
}

// What `f` throws, as a message ("" when it returns): a local phase's
// failure, agreed on with the other processes before the next collective.
template <class F>
std::string local_failure(F&& f) {
    try {
        f();
    } catch (const std::exception& e) {
        return e.what();
    } catch (...) {
        return "an unknown exception";
    }
    return {};
}

// Ascending global id order of `nodes` (local indices).
void sort_by_global_id(std::vector<NodeId>& nodes, std::span<const std::int64_t> global_ids) {
    std::stable_sort(nodes.begin(), nodes.end(), [&](NodeId a, NodeId b) { return global_ids[a] < global_ids[b]; });
}

// DG-IDW: the working nodes cut down to the boundary nodes a step reads
// (`keep`, by boundary index) and the process's volume nodes, so that a step
// costs nothing per boundary node of the whole mesh (keep_dg_idw_boundary_nodes:
// the plan's bits unchanged); the distributed plan's own indices renumbered alike.
void keep_only_boundary_nodes_read(DistributedPlan& p, const std::vector<std::uint8_t>& keep) {
    const auto nb = static_cast<std::int32_t>(keep.size());
    const int dim = p.dim;
    std::vector<double> points;
    for (std::int32_t b = 0; b < nb; ++b)
        if (keep[b]) points.insert(points.end(), p.working_points.begin() + b * dim, p.working_points.begin() + (b + 1) * dim);
    const auto kept = static_cast<std::int32_t>(points.size() / static_cast<std::size_t>(dim));
    points.insert(points.end(), p.working_points.begin() + static_cast<std::ptrdiff_t>(nb) * dim, p.working_points.end());
    const std::vector<std::int32_t> renumber = keep_dg_idw_boundary_nodes(std::get<DgIdwPlan>(p.plan), keep, points);
    p.working_points = std::move(points);
    for (std::int32_t& w : p.local_to_working) w = w < nb ? renumber[w] : w - nb + kept;
    for (std::int32_t& b : p.local_boundary_index) b = renumber[b];
    for (std::int32_t& b : p.adopted_boundary) b = renumber[b];
    for (std::int32_t& b : p.recv_boundary) b = renumber[b];
    for (std::int32_t& b : p.counted_shared_members) b = renumber[b];
}

// DG-IDW: who sends which motions to whom every step.
void plan_motion_exchange(DistributedPlan& p, const detail::GatheredBoundary& g) {
    const auto& plan = std::get<DgIdwPlan>(p.plan);
    const auto nb = static_cast<std::size_t>(p.num_boundary_nodes);
    // Moving corners of the graph simplices holding this process's volume
    // nodes (static corners' motions are never read).
    std::vector<std::uint8_t> needed = dg_idw_motions_read(plan);
    // The shared graph vertices whose first boundary node this process owns:
    // it counts their conflicts, so it needs all their nodes' motions.
    for (std::span<const std::int32_t> group : dg_idw_shared_groups(plan)) {
        if (g.owner[group.front()] != p.rank) continue;
        for (std::int32_t b : group) {
            needed[b] = 1;
            p.counted_shared_members.push_back(b);
        }
        p.counted_shared_offsets.push_back(static_cast<std::int32_t>(p.counted_shared_members.size()));
    }
    // Boundary nodes held here without their motion (boundary elsewhere) move with the owner's.
    for (std::int32_t b : p.adopted_boundary)
        if (g.moving[b]) needed[b] = 1;
    // The boundary nodes this process's step reads or writes: its own, the adopted and the needed ones.
    std::vector<std::uint8_t> keep(needed);
    for (std::int32_t b : p.local_boundary_index) keep[b] = 1;
    for (std::int32_t b : p.adopted_boundary) keep[b] = 1;
    // A boundary node held by several processes moves with its owner's motion
    // (as the other methods' gather does): every copy ends at the same place,
    // whatever motion another process gives its copy. Only the owned ones are held here.
    for (std::int32_t b : p.local_boundary_index)
        needed[b] = g.owner[b] == p.rank ? 0 : g.moving[b];

    // Requests by owner (ascending boundary index within each).
    std::vector<std::vector<std::int32_t>> requests(p.size);
    for (std::size_t b = 0; b < nb; ++b)
        if (needed[b]) requests[g.owner[b]].push_back(static_cast<std::int32_t>(b));
    p.recv_counts.assign(p.size, 0);
    for (int r = 0; r < p.size; ++r) {
        p.recv_counts[r] = static_cast<int>(requests[r].size());
        p.recv_boundary.insert(p.recv_boundary.end(), requests[r].begin(), requests[r].end());
    }
    p.send_counts.assign(p.size, 0);
    MPI_Alltoall(p.recv_counts.data(), 1, MPI_INT, p.send_counts.data(), 1, MPI_INT, p.comm);
    std::vector<int> sdispl(p.size, 0), rdispl(p.size, 0);
    for (int r = 1; r < p.size; ++r) {
        sdispl[r] = sdispl[r - 1] + p.recv_counts[r - 1];
        rdispl[r] = rdispl[r - 1] + p.send_counts[r - 1];
    }
    std::vector<std::int32_t> asked(static_cast<std::size_t>(rdispl[p.size - 1] + p.send_counts[p.size - 1]));
    MPI_Alltoallv(p.recv_boundary.data(), p.recv_counts.data(), sdispl.data(), MPI_INT32_T, asked.data(),
                  p.send_counts.data(), rdispl.data(), MPI_INT32_T, p.comm);
    // Boundary index -> local boundary index, for the ones asked of this process (it owns them).
    std::vector<std::pair<std::int32_t, std::int32_t>> held;
    for (std::size_t j = 0; j < p.local_boundary_index.size(); ++j)
        held.emplace_back(p.local_boundary_index[j], static_cast<std::int32_t>(j));
    std::sort(held.begin(), held.end());
    p.send_local.resize(asked.size());
    for (std::size_t k = 0; k < asked.size(); ++k)
        p.send_local[k] = std::lower_bound(held.begin(), held.end(), std::pair{asked[k], std::int32_t{-1}})->second;
    keep_only_boundary_nodes_read(p, keep);
}

}  // namespace

bool gathers_all_motions(Method method) { return method != Method::dg_idw; }

DistributedPlan prepare_distributed(MPI_Comm comm, Method method, int dim, std::span<const double> points,
                                    std::span<const std::int64_t> global_ids, const BoundarySet& boundary,
                                    const MethodOptions& options) {
    DistributedPlan p;
    p.comm = comm;
    p.input_hash = distributed_inputs_hash(points, global_ids, boundary);
    MPI_Comm_rank(comm, &p.rank);
    MPI_Comm_size(comm, &p.size);
    p.method = method;
    p.dim = dim;
    p.options = options;
    p.gather_all = gathers_all_motions(method);
    p.num_local_points = static_cast<std::int64_t>(global_ids.size());
    // Before any other collective: the same method, dimension and options everywhere
    // (another would enter other collectives, and wait forever or fail in MPI).
    detail::throw_if_any_failed(comm, check_same_setup(comm, method, dim, options), "its method or options");
    // laplacian solves on the whole mesh's cells, which no process holds here.
    detail::throw_if_any_failed(
        comm,
        method == Method::laplacian ? std::string("the laplacian reference method runs on one process (it solves on "
                                                  "the whole mesh's cells); use another method with MPI")
                                    : check_local_input(dim, points, global_ids, boundary),
        "its mesh part");

    auto t0 = Clock::now();
    const detail::GatheredBoundary g = detail::gather_boundary(comm, dim, points, global_ids, boundary);
    p.num_boundary_nodes = static_cast<std::int64_t>(g.global_ids.size());
    p.local_boundary_index = g.local_index;
    const auto nb = static_cast<NodeId>(g.global_ids.size());

    // This process's volume nodes, ascending in global id. A local node that
    // another process holds as a boundary node (a partition interface node
    // whose boundary faces are all on the other side) is that boundary node
    // here too: its motion comes from its owner.
    std::vector<std::uint8_t> is_boundary(global_ids.size(), 0);
    for (NodeId n : boundary.nodes) is_boundary[n] = 1;
    std::vector<NodeId> volume;
    std::vector<std::pair<NodeId, std::int32_t>> adopted;  // (local node, boundary index)
    std::string error;
    for (std::size_t i = 0; i < global_ids.size(); ++i) {
        if (is_boundary[i]) continue;
        const auto at = std::lower_bound(g.global_ids.begin(), g.global_ids.end(), global_ids[i]);
        if (at != g.global_ids.end() && *at == global_ids[i]) {
            const auto b = static_cast<std::int32_t>(at - g.global_ids.begin());
            for (int d = 0; d < dim; ++d)
                if (g.points[static_cast<std::size_t>(b) * dim + d] != points[i * dim + d] && error.empty())
                    error = "local node " + std::to_string(i) + " (global id " + std::to_string(global_ids[i]) +
                            ") is not where process " + std::to_string(g.owner[b]) + " has that boundary node";
            adopted.emplace_back(static_cast<NodeId>(i), b);
            continue;
        }
        volume.push_back(static_cast<NodeId>(i));
    }
    sort_by_global_id(volume, global_ids);
    p.times.gather_seconds = seconds_since(t0);
    detail::throw_if_any_failed(comm, error, "its boundary nodes");

    // Working nodes: the boundary (boundary index order), [coarse points], own volume nodes.
    p.working_points = g.points;
    p.local_to_working.assign(global_ids.size(), -1);
    for (std::size_t j = 0; j < boundary.nodes.size(); ++j) p.local_to_working[boundary.nodes[j]] = g.local_index[j];
    for (const auto& [n, b] : adopted) {
        p.local_to_working[n] = b;
        p.adopted_boundary.push_back(b);
    }
    std::vector<NodeId> coarse;
    std::vector<std::int64_t> coarse_ids;
    if (method == Method::dg_harmonic) {
        t0 = Clock::now();
        std::vector<double> first(g.points);  // boundary, then own volume nodes
        std::vector<NodeId> boundary_ids(static_cast<std::size_t>(nb)), volume_ids(volume.size());
        std::vector<std::int64_t> volume_global(volume.size());
        std::iota(boundary_ids.begin(), boundary_ids.end(), 0);
        for (std::size_t i = 0; i < volume.size(); ++i) {
            volume_ids[i] = nb + static_cast<NodeId>(i);
            volume_global[i] = global_ids[volume[i]];
            for (int d = 0; d < dim; ++d) first.push_back(points[static_cast<std::size_t>(volume[i]) * dim + d]);
        }
        const detail::CoarsePoints c = detail::select_coarse_points_distributed(
            comm, dim, first, boundary_ids, volume_ids, volume_global,
            {options.dg_harmonic.wall_spacing, options.dg_harmonic.growth});
        coarse_ids = c.global_ids;
        for (std::size_t k = 0; k < coarse_ids.size(); ++k) coarse.push_back(nb + static_cast<NodeId>(k));
        p.working_points.insert(p.working_points.end(), c.points.begin(), c.points.end());
        p.num_coarse_points = static_cast<std::int64_t>(coarse_ids.size());
        p.times.coarse_seconds = seconds_since(t0);
    }
    for (NodeId n : volume) {
        const auto c = std::lower_bound(coarse_ids.begin(), coarse_ids.end(), global_ids[n]);
        if (c != coarse_ids.end() && *c == global_ids[n]) {
            p.local_to_working[n] = nb + static_cast<NodeId>(c - coarse_ids.begin());
            continue;
        }
        p.local_to_working[n] = static_cast<std::int32_t>(p.working_points.size() / dim);
        for (int d = 0; d < dim; ++d) p.working_points.push_back(points[static_cast<std::size_t>(n) * dim + d]);
    }

    BoundarySet working_boundary;
    working_boundary.nodes.resize(static_cast<std::size_t>(nb));
    std::iota(working_boundary.nodes.begin(), working_boundary.nodes.end(), 0);
    working_boundary.moving = g.moving;
    t0 = Clock::now();
    // The method's prepare is local (its own volume nodes): a failure on one process
    // (an option it refuses, degenerate geometry, memory) is raised on every one.
    detail::throw_if_any_failed(comm, local_failure([&] {
        p.plan = method == Method::dg_harmonic
                     ? Plan(prepare_dg_harmonic_on_coarse(dim, p.working_points, working_boundary, coarse,
                                                          options.dg_harmonic))
                     : prepare(method, dim, p.working_points, working_boundary, options);
    }), "its method's prepare");
    p.times.method_seconds = seconds_since(t0);

    t0 = Clock::now();
    if (p.gather_all) {
        p.owned_counts.assign(p.size, 0);
        std::vector<std::vector<std::int32_t>> by_rank(p.size);
        // Moving nodes only: a static node's motion is zero (never sent).
        for (std::size_t b = 0; b < g.owner.size(); ++b)
            if (g.moving[b]) by_rank[g.owner[b]].push_back(static_cast<std::int32_t>(b));
        for (int r = 0; r < p.size; ++r) {
            p.owned_counts[r] = static_cast<int>(by_rank[r].size());
            p.owned_boundary.insert(p.owned_boundary.end(), by_rank[r].begin(), by_rank[r].end());
        }
        // This process's owned nodes in ascending boundary index, as local boundary indices.
        std::vector<std::pair<std::int32_t, std::int32_t>> held;
        for (std::size_t j = 0; j < g.local_index.size(); ++j)
            if (g.owner[g.local_index[j]] == p.rank && g.moving[g.local_index[j]]) held.emplace_back(g.local_index[j], static_cast<std::int32_t>(j));
        std::sort(held.begin(), held.end());
        held.erase(std::unique(held.begin(), held.end(),
                               [](const auto& a, const auto& b) { return a.first == b.first; }),
                   held.end());
        for (const auto& h : held) p.my_owned_local.push_back(h.second);
    } else {
        plan_motion_exchange(p, g);
    }
    p.times.exchange_seconds = seconds_since(t0);
    return p;
}

std::size_t distributed_plan_bytes(const DistributedPlan& p) {
    return sizeof(DistributedPlan) + plan_memory_bytes(p.plan) + bytes_of(p.working_points) +
           bytes_of(p.local_to_working) + bytes_of(p.local_boundary_index) + bytes_of(p.adopted_boundary) +
           bytes_of(p.owned_counts) +
           bytes_of(p.owned_boundary) + bytes_of(p.my_owned_local) + bytes_of(p.send_counts) +
           bytes_of(p.recv_counts) + bytes_of(p.send_local) + bytes_of(p.recv_boundary) +
           bytes_of(p.counted_shared_offsets) + bytes_of(p.counted_shared_members);
}

}  // namespace dgwarp::mpi
