// root_session.hpp: the root broadcasts a command, then the command's data.
#include "dgwarp/mpi/root_session.hpp"

#include <algorithm>
#include <cstring>
#include <exception>
#include <optional>
#include <type_traits>

#include "dgwarp/core/parallel_for.hpp"
#include "dgwarp/core/stopwatch.hpp"
#include "dgwarp/methods/option_table.hpp"
#include "dgwarp/mpi/large_transfers.hpp"
#include "dgwarp/mpi/reductions.hpp"

namespace dgwarp::mpi {

namespace {

enum Command : int { command_stop = 0, command_prepare = 1, command_deform = 2, command_everywhere = 3 };
enum Tag : int { tag_ids = 7401, tag_points, tag_boundary, tag_moving, tag_motion, tag_result };

// What every process needs to prepare besides its part; the method options
// go as the option table's text (exact: methods/option_table.hpp).
struct PrepareHeader {
    int method;
    int dim;
    int threads;
};
static_assert(std::is_trivially_copyable_v<NodeMotion>);

// Vectors of any size (in pieces of at most INT_MAX bytes: large_transfers.hpp).
template <class T>
void send_vector(MPI_Comm comm, const std::vector<T>& v, int to, int tag) {
    detail::send_bytes(comm, std::as_bytes(std::span<const T>(v)), to, tag);
}

template <class T>
std::vector<T> receive_vector(MPI_Comm comm, int from, int tag) {
    const std::vector<std::byte> bytes = detail::receive_bytes(comm, from, tag);
    std::vector<T> v(bytes.size() / sizeof(T));
    if (!bytes.empty()) std::memcpy(v.data(), bytes.data(), bytes.size());
    return v;
}

void broadcast_command(MPI_Comm comm, int command) { MPI_Bcast(&command, 1, MPI_INT, 0, comm); }

}  // namespace

PartPlan prepare_part(MPI_Comm comm, Method method, int dim, std::span<const double> points,
                      std::span<const std::int64_t> global_ids, const BoundarySet& boundary,
                      const MethodOptions& options) {
    Stopwatch sw;
    std::optional<DistributedPlan> plan;
    std::exception_ptr error;
    try {
        plan = prepare_distributed(comm, method, dim, points, global_ids, boundary, options);
    } catch (const std::exception&) {  // on every process alike (prepare_distributed's failures are collective)
        error = std::current_exception();
    }
    const double s = sw.lap();
    const bool root = rank_in(comm) == 0;
    PartPlan out;
    if (root) out.prepare_seconds.resize(static_cast<std::size_t>(processes_in(comm)));
    MPI_Gather(&s, 1, MPI_DOUBLE, root ? out.prepare_seconds.data() : nullptr, 1, MPI_DOUBLE, 0, comm);
    if (error) std::rethrow_exception(error);
    out.outside_hull = sum(comm, plan_summary(plan->plan).outside_hull);
    out.plan = std::move(*plan);
    return out;
}

StepReport deform_part(const PartPlan& plan, std::span<const double> points, const BoundaryMotion& motion,
                       std::span<double> out, std::vector<double>& seconds) {
    const MPI_Comm comm = plan.plan.comm;
    Stopwatch sw;
    const StepReport report = deform_distributed(plan.plan, points, motion, out);
    const double s = sw.lap();
    const bool root = rank_in(comm) == 0;
    seconds.resize(root ? static_cast<std::size_t>(processes_in(comm)) : 0);
    MPI_Gather(&s, 1, MPI_DOUBLE, root ? seconds.data() : nullptr, 1, MPI_DOUBLE, 0, comm);
    return report;
}

RootRun root_prepare(MPI_Comm comm, const Mesh& mesh, const BoundarySet& boundary, Method method,
                     const MethodOptions& options, const std::vector<std::vector<NodeId>>& node_parts,
                     int threads) {
    const int size = processes_in(comm);
    RootRun run;
    run.comm = comm;
    run.dim = mesh.dim;
    run.parts = split_mesh(mesh, boundary, size, node_parts);
    broadcast_command(comm, command_prepare);
    PrepareHeader h{static_cast<int>(method), mesh.dim, threads};
    MPI_Bcast(&h, sizeof h, MPI_BYTE, 0, comm);
    broadcast_text(comm, method_options_text(options));
    for (int r = 1; r < size; ++r) {
        const NodePart& p = run.parts[static_cast<std::size_t>(r)];
        send_vector(comm, p.global_ids, r, tag_ids);
        send_vector(comm, p.points, r, tag_points);
        send_vector(comm, p.boundary.nodes, r, tag_boundary);
        send_vector(comm, p.boundary.moving, r, tag_moving);
    }
    const NodePart& mine = run.parts.front();
    run.plan = prepare_part(comm, method, mesh.dim, mine.points, mine.global_ids, mine.boundary, options);
    return run;
}

StepReport root_deform(const RootRun& run, const BoundaryMotion& motion, std::span<double> out,
                       std::vector<double>& seconds) {
    const MPI_Comm comm = run.comm;
    const int size = processes_in(comm);
    broadcast_command(comm, command_deform);
    auto motions_of = [&](const NodePart& p) {
        BoundaryMotion m(p.slots.size());
        for (std::size_t j = 0; j < m.size(); ++j) m[j] = motion[static_cast<std::size_t>(p.slots[j])];
        return m;
    };
    for (int r = 1; r < size; ++r) send_vector(comm, motions_of(run.parts[static_cast<std::size_t>(r)]), r, tag_motion);
    const NodePart& mine = run.parts.front();
    std::vector<double> local(mine.points.size());
    // An error is raised on every process alike (the distributed errors are
    // collective): none sends its result.
    const StepReport report = deform_part(run.plan, mine.points, motions_of(mine), local, seconds);
    const auto dim = static_cast<std::size_t>(run.dim);
    auto place = [&](const NodePart& p, const std::vector<double>& x) {
        for (std::size_t i = 0; i < p.global_ids.size(); ++i)
            std::copy_n(x.data() + i * dim, dim, out.data() + static_cast<std::size_t>(p.global_ids[i]) * dim);
    };
    place(mine, local);
    for (int r = 1; r < size; ++r)
        place(run.parts[static_cast<std::size_t>(r)], receive_vector<double>(comm, r, tag_result));
    return report;
}

void root_run_everywhere(MPI_Comm comm, const std::string& payload) {
    broadcast_command(comm, command_everywhere);
    broadcast_text(comm, payload);
}

void root_stop(MPI_Comm comm, int exit_code) {
    if (processes_in(comm) < 2) return;
    broadcast_command(comm, command_stop);
    MPI_Bcast(&exit_code, 1, MPI_INT, 0, comm);
}

int serve_root(MPI_Comm comm, const std::function<int(const std::string& payload)>& run_payload) {
    std::optional<PartPlan> plan;
    NodePart part;
    int code = 0;
    for (;;) {
        int command = command_stop;
        MPI_Bcast(&command, 1, MPI_INT, 0, comm);
        if (command == command_stop) {
            int root_code = 0;
            MPI_Bcast(&root_code, 1, MPI_INT, 0, comm);
            return root_code != 0 ? root_code : code;
        }
        try {
            if (command == command_everywhere) {
                const std::string payload = broadcast_text(comm, {});
                code = run_payload ? run_payload(payload) : 0;
            } else if (command == command_prepare) {
                PrepareHeader h{};
                MPI_Bcast(&h, sizeof h, MPI_BYTE, 0, comm);
                const MethodOptions options = method_options_from_text(broadcast_text(comm, {}));
                if (h.threads > 0) set_num_threads(h.threads);
                plan.reset();
                part.global_ids = receive_vector<std::int64_t>(comm, 0, tag_ids);
                part.points = receive_vector<double>(comm, 0, tag_points);
                part.boundary.nodes = receive_vector<NodeId>(comm, 0, tag_boundary);
                part.boundary.moving = receive_vector<std::uint8_t>(comm, 0, tag_moving);
                plan = prepare_part(comm, static_cast<Method>(h.method), h.dim, part.points, part.global_ids,
                                    part.boundary, options);
            } else if (command == command_deform) {
                const BoundaryMotion motion = receive_vector<NodeMotion>(comm, 0, tag_motion);
                std::vector<double> out(part.points.size()), seconds;
                deform_part(*plan, part.points, motion, out, seconds);
                send_vector(comm, out, 0, tag_result);
            }
        } catch (const std::exception&) {
            // Raised on the root too (the distributed errors are collective):
            // the root reports it; wait for the next command.
        }
    }
}

}  // namespace dgwarp::mpi
