// mpi_session.hpp with MPI: rank 0 hands each process the nodes of a block
// of cells, then drives prepare_distributed / deform_distributed on all.
#include <mpi.h>

#include <algorithm>
#include <cstdlib>
#include <exception>
#include <optional>
#include <type_traits>

#include "dgwarp/core/error.hpp"
#include "dgwarp/core/parallel_for.hpp"
#include "dgwarp/core/stopwatch.hpp"
#include "dgwarp/mpi/distributed_plan.hpp"
#include "dgwarp/mpi/morton_partition.hpp"
#include "mpi_session.hpp"

namespace dgwarp::cli {

// What a process holds: its nodes (global ids, coordinates) and boundary.
struct MpiPart {
    std::vector<std::int64_t> global_ids;
    std::vector<double> points;
    BoundarySet boundary;
};

namespace {

bool mpi_started = false;
int mpi_my_rank = 0, mpi_size = 1;

enum MpiCommand : int { command_stop = 0, command_prepare = 1, command_deform = 2 };
struct MpiPrepareHeader {
    int method;
    int dim;
    int threads;
    MethodOptions options;
};
static_assert(std::is_trivially_copyable_v<MpiPrepareHeader>);
static_assert(sizeof(NodeMotion) == 9 * sizeof(double));

template <class T>
void mpi_send_vector(const std::vector<T>& v, int to, int tag) {
    const auto n = static_cast<long long>(v.size() * sizeof(T));
    MPI_Send(&n, 1, MPI_LONG_LONG, to, tag, MPI_COMM_WORLD);
    MPI_Send(v.data(), static_cast<int>(n), MPI_BYTE, to, tag, MPI_COMM_WORLD);
}

template <class T>
std::vector<T> mpi_receive_vector(int from, int tag) {
    long long n = 0;
    MPI_Recv(&n, 1, MPI_LONG_LONG, from, tag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    std::vector<T> v(static_cast<std::size_t>(n) / sizeof(T));
    MPI_Recv(v.data(), static_cast<int>(n), MPI_BYTE, from, tag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    return v;
}

// This process's side of a prepare: the plan over its part, its seconds gathered to rank 0.
mpi::DistributedPlan mpi_prepare_part(const MpiPrepareHeader& h, const MpiPart& part, std::vector<double>* seconds,
                                      std::int64_t* outside_total) {
    Stopwatch sw;
    std::optional<mpi::DistributedPlan> plan;
    std::exception_ptr error;
    try {
        plan = mpi::prepare_distributed(MPI_COMM_WORLD, static_cast<Method>(h.method), h.dim, part.points,
                                        part.global_ids, part.boundary, h.options);
    } catch (const Error&) {  // on every process alike (prepare_distributed's errors are collective)
        error = std::current_exception();
    }
    const double s = sw.lap();
    if (seconds) seconds->resize(mpi_size);
    MPI_Gather(&s, 1, MPI_DOUBLE, seconds ? seconds->data() : nullptr, 1, MPI_DOUBLE, 0, MPI_COMM_WORLD);
    if (error) std::rethrow_exception(error);
    // The volume nodes outside the graph's hull, summed over the processes
    // (rank 0's report warns about them wherever they are).
    const std::int64_t outside = plan_summary(plan->plan).outside_hull;
    MPI_Reduce(&outside, outside_total ? outside_total : nullptr, 1, MPI_INT64_T, MPI_SUM, 0, MPI_COMM_WORLD);
    return std::move(*plan);
}

}  // namespace

struct DistributedRun {
    int dim = 3;
    std::vector<MpiPart> parts;                           // per rank (rank 0's too)
    std::vector<std::vector<std::int32_t>> slots;      // per rank, per local boundary node: its whole-BoundarySet index
    mpi::DistributedPlan plan;                         // rank 0's
    std::int64_t outside_hull = 0;                     // volume nodes outside the hull, summed over the processes
};

int mpi_start(int& argc, char**& argv) {
    // Open MPI's mpirun sets OMPI_COMM_WORLD_SIZE in every process it starts;
    // without it, no MPI (a plain dgwarp starts as fast as without MPI).
    if (!std::getenv("OMPI_COMM_WORLD_SIZE") && !std::getenv("PMIX_RANK")) return 1;
    MPI_Init(&argc, &argv);
    mpi_started = true;
    MPI_Comm_rank(MPI_COMM_WORLD, &mpi_my_rank);
    MPI_Comm_size(MPI_COMM_WORLD, &mpi_size);
    // One thread per process unless --threads says otherwise (P mpi_size
    // share the machine's cores).
    if (mpi_size > 1) set_num_threads(1);
    return mpi_size;
}

int mpi_rank() { return mpi_my_rank; }
int mpi_processes() { return mpi_size; }

void mpi_stop() {
    if (!mpi_started) return;
    if (mpi_my_rank == 0 && mpi_size > 1) {
        int command = command_stop;
        MPI_Bcast(&command, 1, MPI_INT, 0, MPI_COMM_WORLD);
    }
    MPI_Finalize();
    mpi_started = false;
}

void mpi_serve() {
    std::optional<mpi::DistributedPlan> plan;
    MpiPart part;
    for (;;) {
        int command = command_stop;
        MPI_Bcast(&command, 1, MPI_INT, 0, MPI_COMM_WORLD);
        if (command == command_stop) return;
        try {
            if (command == command_prepare) {
                MpiPrepareHeader h{};
                MPI_Bcast(&h, sizeof h, MPI_BYTE, 0, MPI_COMM_WORLD);
                set_num_threads(h.threads);
                plan.reset();
                part.global_ids = mpi_receive_vector<std::int64_t>(0, 1);
                part.points = mpi_receive_vector<double>(0, 2);
                part.boundary.nodes = mpi_receive_vector<NodeId>(0, 3);
                part.boundary.moving = mpi_receive_vector<std::uint8_t>(0, 4);
                plan = mpi_prepare_part(h, part, nullptr, nullptr);
            } else if (command == command_deform) {
                const BoundaryMotion motion = mpi_receive_vector<NodeMotion>(0, 5);
                std::vector<double> out(part.points.size());
                Stopwatch sw;
                mpi::deform_distributed(*plan, part.points, motion, out);
                const double s = sw.lap();
                MPI_Gather(&s, 1, MPI_DOUBLE, nullptr, 1, MPI_DOUBLE, 0, MPI_COMM_WORLD);
                mpi_send_vector(out, 0, 6);
            }
        } catch (const Error&) {
            // Raised on rank 0 too (the library's distributed errors are
            // collective): rank 0 reports it; wait for the next command.
        }
    }
}

std::shared_ptr<DistributedRun> mpi_prepare(const Mesh& mesh, const BoundarySet& boundary, Method method,
                                            const MethodOptions& options,
                                            const std::vector<std::vector<NodeId>>& node_parts, Plan& rank0_plan,
                                            std::vector<double>& seconds) {
    auto run = std::make_shared<DistributedRun>();
    run->dim = mesh.dim;
    // Process r holds the nodes of its block of cells along a Morton curve
    // (mpi/morton_partition.hpp; a solver brings its own partition), in order
    // of first use, or those of node_parts[r]; nodes of none go to rank 0.
    const std::size_t cells = mesh.cells.types.size(), n = mesh.num_points();
    run->parts.resize(mpi_size);
    run->slots.resize(mpi_size);
    std::vector<std::int32_t> seen(n, -1);  // last rank that took the node
    std::vector<std::int32_t> boundary_slot(n, -1);
    for (std::size_t b = 0; b < boundary.nodes.size(); ++b) boundary_slot[boundary.nodes[b]] = static_cast<std::int32_t>(b);
    auto take = [&](int r, NodeId node) {
        MpiPart& p = run->parts[r];
        if (seen[node] == r) return;
        seen[node] = r;
        const auto local = static_cast<NodeId>(p.global_ids.size());
        p.global_ids.push_back(node);
        for (int d = 0; d < mesh.dim; ++d) p.points.push_back(mesh.points[static_cast<std::size_t>(node) * mesh.dim + d]);
        if (boundary_slot[node] >= 0) {
            p.boundary.nodes.push_back(local);  // ascending: locals are numbered in order
            p.boundary.moving.push_back(boundary.moving[boundary_slot[node]]);
            run->slots[r].push_back(boundary_slot[node]);
        }
    };
    if (node_parts.size() == static_cast<std::size_t>(mpi_size)) {
        for (int r = 0; r < mpi_size; ++r)
            for (NodeId node : node_parts[r]) take(r, node);
    } else {
        const std::vector<std::int32_t> cell_part = mpi::morton_cell_parts(mesh, mpi_size);
        for (std::size_t c = 0; c < cells; ++c)
            for (std::int64_t k = mesh.cells.offsets[c]; k < mesh.cells.offsets[c + 1]; ++k)
                take(cell_part[c], mesh.cells.nodes[k]);
    }
    for (std::size_t node = 0; node < n; ++node)
        if (seen[node] < 0) take(0, static_cast<NodeId>(node));

    int command = command_prepare;
    MPI_Bcast(&command, 1, MPI_INT, 0, MPI_COMM_WORLD);
    MpiPrepareHeader h{static_cast<int>(method), mesh.dim, num_threads(), options};
    MPI_Bcast(&h, sizeof h, MPI_BYTE, 0, MPI_COMM_WORLD);
    for (int r = 1; r < mpi_size; ++r) {
        mpi_send_vector(run->parts[r].global_ids, r, 1);
        mpi_send_vector(run->parts[r].points, r, 2);
        mpi_send_vector(run->parts[r].boundary.nodes, r, 3);
        mpi_send_vector(run->parts[r].boundary.moving, r, 4);
    }
    std::int64_t outside = 0;
    run->plan = mpi_prepare_part(h, run->parts[0], &seconds, &outside);
    rank0_plan = run->plan.plan;
    run->outside_hull = outside;
    return run;
}

std::int64_t mpi_outside_hull(const DistributedRun& run) { return run.outside_hull; }

StepReport mpi_deform(const DistributedRun& run, const BoundaryMotion& motion, std::span<double> out,
                      std::vector<double>& seconds) {
    int command = command_deform;
    MPI_Bcast(&command, 1, MPI_INT, 0, MPI_COMM_WORLD);
    auto motions_of = [&](int r) {
        BoundaryMotion m(run.slots[r].size());
        for (std::size_t j = 0; j < m.size(); ++j) m[j] = motion[run.slots[r][j]];
        return m;
    };
    for (int r = 1; r < mpi_size; ++r) mpi_send_vector(motions_of(r), r, 5);
    const MpiPart& mine = run.parts[0];
    std::vector<double> local(mine.points.size());
    Stopwatch sw;
    StepReport report;
    // An error is raised on every process alike (the library's distributed
    // errors are collective): none sends its result.
    report = mpi::deform_distributed(run.plan, mine.points, motions_of(0), local);
    const double s = sw.lap();
    seconds.resize(mpi_size);
    MPI_Gather(&s, 1, MPI_DOUBLE, seconds.data(), 1, MPI_DOUBLE, 0, MPI_COMM_WORLD);
    auto place = [&](const MpiPart& p, const std::vector<double>& x) {
        for (std::size_t i = 0; i < p.global_ids.size(); ++i)
            std::copy_n(x.data() + i * run.dim, run.dim, out.data() + static_cast<std::size_t>(p.global_ids[i]) * run.dim);
    };
    place(mine, local);
    for (int r = 1; r < mpi_size; ++r) place(run.parts[r], mpi_receive_vector<double>(r, 6));
    return report;
}

}  // namespace dgwarp::cli
