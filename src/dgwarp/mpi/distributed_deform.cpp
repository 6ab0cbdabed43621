// deform_distributed: exchange the motions, one step of the method on the
// working nodes, this process's nodes copied out.
#include <algorithm>
#include <cmath>
#include <exception>
#include <string>
#include <type_traits>

#include "dgwarp/core/error.hpp"
#include "dgwarp/methods/dg_idw_step.hpp"
#include "dgwarp/methods/graph_vertex_motion.hpp"
#include "dgwarp/methods/method_inputs.hpp"
#include "dgwarp/mpi/collective_checks.hpp"
#include "dgwarp/mpi/distributed_plan.hpp"
#include "dgwarp/mpi/large_transfers.hpp"

namespace dgwarp::mpi {

namespace {

// A NodeMotion travels as one record of 9 doubles (t, w, c).
static_assert(std::is_standard_layout_v<NodeMotion> && sizeof(NodeMotion) == 9 * sizeof(double));

std::string check_step_input(const DistributedPlan& p, std::span<const double> points, const BoundaryMotion& motion,
                             std::span<const double> out) {
    const auto values = static_cast<std::size_t>(p.num_local_points) * static_cast<std::size_t>(p.dim);
    if (points.size() != values || out.size() != values)
        return "the plan is for " + std::to_string(p.num_local_points) + " local points (" + std::to_string(values) +
               " values), got " + std::to_string(points.size()) + " point values and " + std::to_string(out.size()) +
               " output values";
    if (motion.size() != p.local_boundary_index.size())
        return "the motion has " + std::to_string(motion.size()) + " entries but this process has " +
               std::to_string(p.local_boundary_index.size()) + " boundary nodes";
    for (std::size_t j = 0; j < motion.size(); ++j)
        if (const std::string problem = motion_value_problem(motion[j]); !problem.empty())
            return "the motion of local boundary node " + std::to_string(j) + " cannot be used: " + problem;
    return {};
}

std::vector<int> displacements(const std::vector<int>& counts) {
    std::vector<int> d(counts.size(), 0);
    for (std::size_t r = 1; r < counts.size(); ++r) d[r] = d[r - 1] + counts[r - 1];
    return d;
}

}  // namespace

StepReport deform_distributed(const DistributedPlan& p, std::span<const double> points, const BoundaryMotion& motion,
                              std::span<double> out) {
    detail::throw_if_any_failed(p.comm, check_step_input(p, points, motion, out), "its step's arrays");
    // The working boundary nodes' motions (every boundary node for the
    // gather-all methods, the ones a step reads for DG-IDW): this process's
    // own, and the ones received; the rest stay zero (never read).
    const std::size_t nb = p.gather_all ? static_cast<std::size_t>(p.num_boundary_nodes)
                                        : std::get<DgIdwPlan>(p.plan).boundary_nodes.size();
    BoundaryMotion all(nb);
    for (std::size_t j = 0; j < motion.size(); ++j) all[p.local_boundary_index[j]] = motion[j];

    StepReport report;
    std::string local_error;
    std::vector<double> working_out(p.working_points.size());
    if (p.gather_all) {
        std::vector<NodeMotion> send(p.my_owned_local.size()), recv(p.owned_boundary.size());
        for (std::size_t k = 0; k < send.size(); ++k) send[k] = motion[p.my_owned_local[k]];
        // Counted in motions (a 72-byte datatype), not doubles: 9 times the nodes before an int overflows.
        const detail::RecordType motion_type(sizeof(NodeMotion));
        const std::vector<int> displs = displacements(p.owned_counts);
        MPI_Allgatherv(send.data(), static_cast<int>(send.size()), motion_type.get(), recv.data(),
                       p.owned_counts.data(), displs.data(), motion_type.get(), p.comm);
        for (std::size_t k = 0; k < recv.size(); ++k) all[p.owned_boundary[k]] = recv[k];
        std::string other_error;
        try {
            report = deform(p.plan, p.working_points, all, working_out, p.options);
        } catch (const InvalidResultError& e) {
            // A non-finite result may be on this process alone: said on every one below.
            // Otherwise (DGM's folded graph) every process has the same replicated graph
            // and throws the same error here.
            std::int64_t count = 0;
            if (non_finite_result(method_name(plan_method(p.plan)), p.dim, working_out, all, count).empty()) throw;
            local_error = e.what();
        } catch (const std::exception& e) {
            other_error = e.what();  // memory, or anything else this process alone met
        }
        detail::throw_if_any_failed(p.comm, other_error, "its step");
    } else {
        const auto& plan = std::get<DgIdwPlan>(p.plan);
        std::vector<NodeMotion> send(p.send_local.size()), recv(p.recv_boundary.size());
        for (std::size_t k = 0; k < send.size(); ++k) send[k] = motion[p.send_local[k]];
        const detail::RecordType motion_type(sizeof(NodeMotion));
        const std::vector<int> sdispl = displacements(p.send_counts), rdispl = displacements(p.recv_counts);
        MPI_Alltoallv(send.data(), p.send_counts.data(), sdispl.data(), motion_type.get(), recv.data(),
                      p.recv_counts.data(), rdispl.data(), motion_type.get(), p.comm);
        for (std::size_t k = 0; k < recv.size(); ++k) all[p.recv_boundary[k]] = recv[k];
        // The whole boundary's largest rotation (it sets the Taylor terms, so
        // the bits) and the conflicts of the shared vertices each process counts.
        // A boundary node this process holds but does not own has its owner's
        // motion in `all` (received above), whatever this process gave it.
        double angle2 = 0, angle2_max = 0;
        for (std::size_t j = 0; j < motion.size(); ++j) {
            if (!plan.boundary_moving[p.local_boundary_index[j]]) continue;
            const Vec3& w = all[p.local_boundary_index[j]].rotation;
            angle2 = std::max(angle2, p.dim == 2 ? w[2] * w[2] : w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
        }
        MPI_Allreduce(&angle2, &angle2_max, 1, MPI_DOUBLE, MPI_MAX, p.comm);
        const std::int64_t mine = count_conflicting_shared_vertices(p.counted_shared_offsets, p.counted_shared_members,
                                                                    plan.boundary_moving, all);
        std::int64_t total = 0;
        MPI_Allreduce(&mine, &total, 1, MPI_INT64_T, MPI_SUM, p.comm);
        deform_dg_idw_bounded(plan, p.working_points, all, working_out, angle2_max);
        report.conflicting_shared_vertices = total;
        std::int64_t count = 0;
        local_error = non_finite_result("dg-idw", p.dim, working_out, all, count);
    }
    // No process returns a non-finite coordinate (nodes numbered in the process's working set).
    detail::throw_if_any_failed(p.comm, local_error, "its step's result", true);
    for (std::int64_t i = 0; i < p.num_local_points; ++i)
        std::copy_n(working_out.data() + static_cast<std::size_t>(p.local_to_working[i]) * p.dim, p.dim,
                    out.data() + static_cast<std::size_t>(i) * p.dim);
    return report;
}

}  // namespace dgwarp::mpi
