// The MPI failure test (registered with ctest, run with mpirun -np 3): a
// failure or a disagreement on one process fails every process together,
// within seconds, instead of leaving the others waiting in a collective
// (issue #31); and a boundary node held by several processes moves with its
// owner's motion whatever the others give it.
//
//   mpirun -np P mpi_failures SCENARIO
//
// Every process builds the rect-box (2,340 nodes) and keeps the nodes of its
// round-robin share of the cells. SCENARIO, on process 1:
//   bad-option     DG-IDW with a_translation = -1 (its prepare refuses it)
//   other-method   DG-harmonic where the others prepare DG-IDW
//   other-option   DG-harmonic with another wall spacing
//   nan-point      a volume node's coordinate NaN (DG-harmonic)
//   duplicate-id   two local nodes with one global id (DG-IDW)
//   small-chunks   (every process) a gather of records in rounds of 3 records and a
//                  vector sent in pieces of 5 bytes equal the one-round transfers
//   ghost-motion   twice the motion for the boundary nodes it holds but does not own
//                  (DG-IDW, then DG-harmonic): every process's coordinates are the
//                  single-process run's with the owners' motion, bit for bit
// Rank 0 prints "failed on K of P processes" (the failure scenarios) or
// "ghosts: same bits" / "ghosts: DIFFERENT"; every process prints its error.
#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <exception>
#include <limits>
#include <string>
#include <vector>

#include "dgwarp/cases/rect_box.hpp"
#include "dgwarp/motion/resolve_motion.hpp"
#include "dgwarp/mpi/distributed_plan.hpp"
#include "dgwarp/mpi/large_transfers.hpp"
#include "mesh_parts.hpp"

using namespace dgwarp;

namespace {

// `count` boundary nodes turned by 10 degrees about the origin (the rectangle's centre; static nodes ignore it).
BoundaryMotion turn(std::size_t count) {
    BoundaryMotion m(count);
    for (NodeMotion& x : m) x.rotation = {0, 0, 10 * 3.141592653589793 / 180};
    return m;
}

int run_failure(const std::string& scenario, int rank, int size) {
    const Mesh mesh = make_rect_box();
    const BoundarySet whole = test::rect_box_boundary(mesh);
    test::Part part = test::make_part(mesh, whole, rank, size, test::Partition::round_robin);
    Method method = Method::dg_idw;
    MethodOptions options;
    const bool odd = rank == 1;
    if (scenario == "bad-option" && odd) options.dg_idw.a_translation = -1;
    if (scenario == "other-method" && odd) method = Method::dg_harmonic;
    if (scenario == "other-option" || scenario == "nan-point") method = Method::dg_harmonic;
    if (scenario == "other-option" && odd) options.dg_harmonic.wall_spacing = 3;
    if (scenario == "nan-point" && odd) {
        // The first local node that is not a boundary node.
        std::vector<std::uint8_t> on_boundary(part.global_ids.size(), 0);
        for (NodeId n : part.boundary.nodes) on_boundary[static_cast<std::size_t>(n)] = 1;
        for (std::size_t i = 0; i < on_boundary.size(); ++i)
            if (!on_boundary[i]) {
                part.points[2 * i] = std::numeric_limits<double>::quiet_NaN();
                break;
            }
    }
    if (scenario == "duplicate-id" && odd) part.global_ids.back() = part.global_ids.front();
    int failed = 0;
    try {
        const mpi::DistributedPlan plan =
            mpi::prepare_distributed(MPI_COMM_WORLD, method, 2, part.points, part.global_ids, part.boundary, options);
        std::vector<double> out(part.points.size());
        mpi::deform_distributed(plan, part.points, turn(part.boundary.nodes.size()), out);
    } catch (const std::exception& e) {
        failed = 1;
        std::printf("process %d: error: %s\n", rank, e.what());
    }
    std::fflush(stdout);
    int total = 0;
    MPI_Reduce(&failed, &total, 1, MPI_INT, MPI_SUM, 0, MPI_COMM_WORLD);
    if (rank == 0) std::printf("failed on %d of %d processes\n", total, size);
    return 0;
}

int run_ghosts(int rank, int size) {
    const Mesh mesh = make_rect_box();
    const BoundarySet whole = test::rect_box_boundary(mesh);
    // Round robin: interface nodes, boundary ones among them, are held by several processes.
    const test::Part part = test::make_part(mesh, whole, rank, size, test::Partition::round_robin);
    // The owner of a boundary node: the lowest rank listing it.
    std::vector<int> lists(whole.nodes.size(), 0), owner(whole.nodes.size(), size);
    for (std::int32_t slot : part.boundary_slot) lists[static_cast<std::size_t>(slot)] = 1;
    for (std::size_t b = 0; b < whole.nodes.size(); ++b) {
        const int mine = lists[b] ? rank : size;
        MPI_Allreduce(&mine, &owner[b], 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD);
    }
    long long mismatches = 0, ghosts = 0;
    for (Method method : {Method::dg_idw, Method::dg_harmonic}) {
        const BoundaryMotion truth = turn(whole.nodes.size());
        std::vector<double> reference(mesh.points.size());
        deform(prepare(method, 2, mesh.points, whole), mesh.points, truth, reference);
        BoundaryMotion mine = turn(part.boundary.nodes.size());
        if (rank == 1)
            for (std::size_t j = 0; j < mine.size(); ++j)
                if (owner[static_cast<std::size_t>(part.boundary_slot[j])] != rank) {
                    mine[j].rotation[2] *= 2;  // a ghost: not this process's to say
                    ++ghosts;
                }
        const mpi::DistributedPlan plan =
            mpi::prepare_distributed(MPI_COMM_WORLD, method, 2, part.points, part.global_ids, part.boundary);
        std::vector<double> out(part.points.size());
        mpi::deform_distributed(plan, part.points, mine, out);
        for (std::size_t i = 0; i < part.global_ids.size(); ++i)
            for (int d = 0; d < 2; ++d)
                mismatches += out[2 * i + d] != reference[static_cast<std::size_t>(part.global_ids[i]) * 2 + d];
    }
    long long total = 0, total_ghosts = 0;
    MPI_Reduce(&mismatches, &total, 1, MPI_LONG_LONG, MPI_SUM, 0, MPI_COMM_WORLD);
    MPI_Reduce(&ghosts, &total_ghosts, 1, MPI_LONG_LONG, MPI_SUM, 0, MPI_COMM_WORLD);
    if (rank == 0)
        std::printf("ghosts: %lld boundary copies given another motion; %s (%lld coordinates differ)\n", total_ghosts,
                    total == 0 && total_ghosts > 0 ? "same bits" : "DIFFERENT", total);
    return total == 0 ? 0 : 1;
}

// Transfers in rounds and pieces (what a part beyond MPI's int counts takes) give the one-round result.
int run_small_chunks(int rank, int size) {
    struct Record {
        std::int64_t id;
        double x[3];
    };
    std::vector<Record> mine(static_cast<std::size_t>(7 * rank + 2));
    for (std::size_t k = 0; k < mine.size(); ++k) mine[k] = {rank * 1000 + static_cast<std::int64_t>(k), {1.0 * k, 2.0, 3.0}};
    const auto once = mpi::detail::allgather_records<Record>(MPI_COMM_WORLD, mine);
    const auto rounds = mpi::detail::allgather_records<Record>(MPI_COMM_WORLD, mine, 3);
    bool same = once.size() == rounds.size() && std::memcmp(once.data(), rounds.data(), once.size() * sizeof(Record)) == 0;
    std::size_t expected = 0;
    for (int r = 0; r < size; ++r) expected += static_cast<std::size_t>(7 * r + 2);
    same = same && once.size() == expected && once.back().id == (size - 1) * 1000 + 7 * (size - 1) + 1;
    if (size > 1) {
        std::vector<std::byte> bytes(23);
        for (std::size_t k = 0; k < bytes.size(); ++k) bytes[k] = static_cast<std::byte>(k * 7);
        if (rank == 0) mpi::detail::send_bytes(MPI_COMM_WORLD, bytes, 1, 9, 5);
        if (rank == 1) same = same && mpi::detail::receive_bytes(MPI_COMM_WORLD, 0, 9, 5) == bytes;
    }
    int ok = same ? 1 : 0, all_ok = 0;
    MPI_Reduce(&ok, &all_ok, 1, MPI_INT, MPI_SUM, 0, MPI_COMM_WORLD);
    if (rank == 0) std::printf("chunks: %s (%d of %d processes)\n", all_ok == size ? "same" : "DIFFERENT", all_ok, size);
    return all_ok == size || rank != 0 ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
    MPI_Init(&argc, &argv);
    int rank = 0, size = 1;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Comm_size(MPI_COMM_WORLD, &size);
    int code = 2;
    if (argc == 2) {
        const std::string scenario = argv[1];
        code = scenario == "ghost-motion"   ? run_ghosts(rank, size)
               : scenario == "small-chunks" ? run_small_chunks(rank, size)
                                            : run_failure(scenario, rank, size);
    } else if (rank == 0) {
        std::fprintf(stderr, "usage: mpirun -np P %s SCENARIO\n", argv[0]);
    }
    MPI_Finalize();
    return code;
}
