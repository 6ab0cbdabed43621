// mpi_session.hpp with MPI: rank 0 hands each process the nodes of a block
// of cells, then drives prepare_distributed / deform_distributed on all.
#include <mpi.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <optional>
#include <string>
#include <type_traits>

#include <CLI/CLI.hpp>

#include "commands.hpp"
#include "dgwarp/core/error.hpp"
#include "dgwarp/core/parallel_for.hpp"
#include "dgwarp/core/stopwatch.hpp"
#include "dgwarp/mpi/distributed_plan.hpp"
#include "dgwarp/mpi/large_transfers.hpp"
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

enum MpiCommand : int { command_stop = 0, command_prepare = 1, command_deform = 2, command_everywhere = 3 };
struct MpiPrepareHeader {
    int method;
    int dim;
    int threads;
    MethodOptions options;
};
static_assert(std::is_trivially_copyable_v<MpiPrepareHeader>);
static_assert(sizeof(NodeMotion) == 9 * sizeof(double));

// Vectors of any size (in pieces of at most INT_MAX bytes: large_transfers.hpp).
template <class T>
void mpi_send_vector(const std::vector<T>& v, int to, int tag) {
    mpi::detail::send_bytes(MPI_COMM_WORLD, std::as_bytes(std::span<const T>(v)), to, tag);
}

template <class T>
std::vector<T> mpi_receive_vector(int from, int tag) {
    const std::vector<std::byte> bytes = mpi::detail::receive_bytes(MPI_COMM_WORLD, from, tag);
    std::vector<T> v(bytes.size() / sizeof(T));
    if (!bytes.empty()) std::memcpy(v.data(), bytes.data(), bytes.size());
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
    } catch (const std::exception&) {  // on every process alike (prepare_distributed's failures are collective)
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

void mpi_stop(int exit_code) {
    if (!mpi_started) return;
    if (mpi_my_rank == 0 && mpi_size > 1) {
        int command = command_stop;
        MPI_Bcast(&command, 1, MPI_INT, 0, MPI_COMM_WORLD);
        MPI_Bcast(&exit_code, 1, MPI_INT, 0, MPI_COMM_WORLD);
    }
    MPI_Finalize();
    mpi_started = false;
}

int mpi_serve() {
    std::optional<mpi::DistributedPlan> plan;
    MpiPart part;
    int code = exit_ok;
    for (;;) {
        int command = command_stop;
        MPI_Bcast(&command, 1, MPI_INT, 0, MPI_COMM_WORLD);
        if (command == command_stop) {
            int rank0_code = exit_ok;
            MPI_Bcast(&rank0_code, 1, MPI_INT, 0, MPI_COMM_WORLD);
            return rank0_code != exit_ok ? rank0_code : code;
        }
        try {
            if (command == command_everywhere) {
                code = run_everywhere(mpi_broadcast_text(""));
            } else if (command == command_prepare) {
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
    // Per rank, the nodes it took (a node of several of a rank's cells is held once:
    // remembering only the last rank that took it held it again after another's cell).
    std::vector<std::vector<bool>> taken(static_cast<std::size_t>(mpi_size), std::vector<bool>(n, false));
    std::vector<std::uint8_t> held(n, 0);  // by some rank
    std::vector<std::int32_t> boundary_slot(n, -1);
    for (std::size_t b = 0; b < boundary.nodes.size(); ++b) boundary_slot[boundary.nodes[b]] = static_cast<std::int32_t>(b);
    auto take = [&](int r, NodeId node) {
        MpiPart& p = run->parts[r];
        if (taken[static_cast<std::size_t>(r)][static_cast<std::size_t>(node)]) return;
        taken[static_cast<std::size_t>(r)][static_cast<std::size_t>(node)] = true;
        held[static_cast<std::size_t>(node)] = 1;
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
        if (!held[node]) take(0, static_cast<NodeId>(node));

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

void mpi_run_everywhere(const std::string& payload) {
    int command = command_everywhere;
    MPI_Bcast(&command, 1, MPI_INT, 0, MPI_COMM_WORLD);
    mpi_broadcast_text(payload);
}

namespace {

// The kinds of error mpi_agree passes between processes (main's exit codes).
enum MpiErrorKind : int { error_none = 0, error_usage = 1, error_input = 2, error_invalid = 3, error_internal = 4 };

}  // namespace

void mpi_agree(const std::exception_ptr& error) {
    int kind = error_none;
    std::string message;
    std::int64_t count = 0;
    if (error) {
        try {
            std::rethrow_exception(error);
        } catch (const CLI::ParseError& e) {
            kind = error_usage;
            message = e.what();
        } catch (const InvalidResultError& e) {
            kind = error_invalid;
            message = e.what();
            count = e.count();
        } catch (const Error& e) {
            kind = error_input;
            message = e.what();
        } catch (const std::exception& e) {
            kind = error_internal;
            message = e.what();
        }
    }
    // The lowest failing rank.
    int failing = kind != error_none ? mpi_my_rank : mpi_size;
    MPI_Allreduce(MPI_IN_PLACE, &failing, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD);
    if (failing == mpi_size) return;
    if (failing == mpi_my_rank) {
        MPI_Bcast(&kind, 1, MPI_INT, failing, MPI_COMM_WORLD);
        MPI_Bcast(&count, 1, MPI_INT64_T, failing, MPI_COMM_WORLD);
        long long n = static_cast<long long>(message.size());
        MPI_Bcast(&n, 1, MPI_LONG_LONG, failing, MPI_COMM_WORLD);
        MPI_Bcast(message.data(), static_cast<int>(n), MPI_CHAR, failing, MPI_COMM_WORLD);
        std::rethrow_exception(error);
    }
    MPI_Bcast(&kind, 1, MPI_INT, failing, MPI_COMM_WORLD);
    MPI_Bcast(&count, 1, MPI_INT64_T, failing, MPI_COMM_WORLD);
    long long n = 0;
    MPI_Bcast(&n, 1, MPI_LONG_LONG, failing, MPI_COMM_WORLD);
    message.assign(static_cast<std::size_t>(n), '\0');
    MPI_Bcast(message.data(), static_cast<int>(n), MPI_CHAR, failing, MPI_COMM_WORLD);
    message = "process " + std::to_string(failing) + ": " + message;
    switch (kind) {
        case error_usage: throw CLI::ValidationError(message);
        case error_invalid: throw InvalidResultError(message, count);
        case error_input: throw Error(message);
        default: throw std::runtime_error(message);
    }
}

std::int64_t mpi_sum(std::int64_t value) {
    MPI_Allreduce(MPI_IN_PLACE, &value, 1, MPI_INT64_T, MPI_SUM, MPI_COMM_WORLD);
    return value;
}
std::vector<std::int64_t> mpi_sum(std::vector<std::int64_t> values) {
    MPI_Allreduce(MPI_IN_PLACE, values.data(), static_cast<int>(values.size()), MPI_INT64_T, MPI_SUM, MPI_COMM_WORLD);
    return values;
}
std::vector<double> mpi_sum(std::vector<double> values) {
    MPI_Allreduce(MPI_IN_PLACE, values.data(), static_cast<int>(values.size()), MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
    return values;
}
double mpi_min(double value) {
    MPI_Allreduce(MPI_IN_PLACE, &value, 1, MPI_DOUBLE, MPI_MIN, MPI_COMM_WORLD);
    return value;
}
double mpi_max(double value) {
    MPI_Allreduce(MPI_IN_PLACE, &value, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
    return value;
}
std::int64_t mpi_min(std::int64_t value) {
    MPI_Allreduce(MPI_IN_PLACE, &value, 1, MPI_INT64_T, MPI_MIN, MPI_COMM_WORLD);
    return value;
}
std::int64_t mpi_max(std::int64_t value) {
    MPI_Allreduce(MPI_IN_PLACE, &value, 1, MPI_INT64_T, MPI_MAX, MPI_COMM_WORLD);
    return value;
}

std::vector<std::int64_t> mpi_all_gather(const std::vector<std::int64_t>& values, std::vector<int>* counts) {
    std::vector<int> n(mpi_size, 0), displ(mpi_size, 0);
    const int mine = static_cast<int>(values.size());
    MPI_Allgather(&mine, 1, MPI_INT, n.data(), 1, MPI_INT, MPI_COMM_WORLD);
    for (int r = 1; r < mpi_size; ++r) displ[r] = displ[r - 1] + n[r - 1];
    std::vector<std::int64_t> all(static_cast<std::size_t>(displ[mpi_size - 1] + n[mpi_size - 1]));
    MPI_Allgatherv(values.data(), mine, MPI_INT64_T, all.data(), n.data(), displ.data(), MPI_INT64_T, MPI_COMM_WORLD);
    if (counts) *counts = std::move(n);
    return all;
}

std::vector<std::string> mpi_gather_text(const std::string& text) {
    std::vector<int> n(mpi_size, 0), displ(mpi_size, 0);
    const int mine = static_cast<int>(text.size());
    MPI_Gather(&mine, 1, MPI_INT, n.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
    for (int r = 1; r < mpi_size; ++r) displ[r] = displ[r - 1] + n[r - 1];
    std::string all(mpi_my_rank == 0 ? static_cast<std::size_t>(displ[mpi_size - 1] + n[mpi_size - 1]) : 0, '\0');
    MPI_Gatherv(text.data(), mine, MPI_CHAR, all.data(), n.data(), displ.data(), MPI_CHAR, 0, MPI_COMM_WORLD);
    std::vector<std::string> texts;
    if (mpi_my_rank == 0)
        for (int r = 0; r < mpi_size; ++r) texts.push_back(all.substr(static_cast<std::size_t>(displ[r]), static_cast<std::size_t>(n[r])));
    return texts;
}

std::string mpi_broadcast_text(const std::string& text) {
    long long n = static_cast<long long>(text.size());
    MPI_Bcast(&n, 1, MPI_LONG_LONG, 0, MPI_COMM_WORLD);
    std::string out = mpi_my_rank == 0 ? text : std::string(static_cast<std::size_t>(n), '\0');
    MPI_Bcast(out.data(), static_cast<int>(n), MPI_CHAR, 0, MPI_COMM_WORLD);
    return out;
}

std::shared_ptr<DistributedRun> mpi_prepare_own(Method method, int dim, const MethodOptions& options,
                                                std::span<const double> points, std::span<const std::int64_t> global_ids,
                                                const BoundarySet& boundary, Plan& my_plan, std::vector<double>& seconds,
                                                std::int64_t& outside_hull) {
    auto run = std::make_shared<DistributedRun>();
    run->dim = dim;
    MpiPart part;  // mpi_prepare_part's input (copies: prepare holds no reference to them)
    part.points.assign(points.begin(), points.end());
    part.global_ids.assign(global_ids.begin(), global_ids.end());
    part.boundary = boundary;
    const MpiPrepareHeader h{static_cast<int>(method), dim, num_threads(), options};
    std::int64_t outside = 0;
    run->plan = mpi_prepare_part(h, part, mpi_my_rank == 0 ? &seconds : nullptr, &outside);
    MPI_Bcast(&outside, 1, MPI_INT64_T, 0, MPI_COMM_WORLD);
    outside_hull = outside;
    run->outside_hull = outside;
    my_plan = run->plan.plan;
    return run;
}

StepReport mpi_deform_own(const DistributedRun& run, std::span<const double> points, const BoundaryMotion& motion,
                          std::span<double> out, std::vector<double>& seconds) {
    Stopwatch sw;
    const StepReport report = mpi::deform_distributed(run.plan, points, motion, out);
    const double s = sw.lap();
    seconds.resize(mpi_my_rank == 0 ? mpi_size : 0);
    MPI_Gather(&s, 1, MPI_DOUBLE, mpi_my_rank == 0 ? seconds.data() : nullptr, 1, MPI_DOUBLE, 0, MPI_COMM_WORLD);
    return report;
}

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
