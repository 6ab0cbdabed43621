#include "motion_bridge.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <fenv.h>
#include <optional>
#include <span>
#include <sstream>

#include "dgwarp/core/error.hpp"
#include "dgwarp/core/stopwatch.hpp"
#include "dgwarp/io/openfoam/openfoam_poly_mesh.hpp"
#include "dgwarp/methods/method.hpp"
#include "dgwarp/methods/option_table.hpp"
#include "dgwarp/run/deform_frame.hpp"
#include "dgwarp/run/original_cells.hpp"
#include "dgwarp/run/run_deformation.hpp"
#ifdef DGWARP_BRIDGE_MPI
#include <mpi.h>

#include "dgwarp/mpi/collective_checks.hpp"
#include "dgwarp/mpi/distributed_plan.hpp"
#endif

namespace dgwarp_bridge {

namespace {

using dgwarp::Method;
using dgwarp::NodeId;


/// Floating-point traps off while the library runs, on every OpenMP thread,
/// and as they were afterwards. OpenFOAM traps invalid operations, division by
/// zero and overflow (FOAM_SIGFPE, on by default); the library computes with
/// IEEE arithmetic's infinities and NaNs where they are harmless (e.g. the
/// barycentric coordinates of a degenerate graph simplex, then discarded), as
/// every program but a trapping one does.
class NoFloatingPointTraps {
  public:
    NoFloatingPointTraps() : saved_(fegetexcept()) { set_everywhere(0); }
    ~NoFloatingPointTraps() { set_everywhere(saved_); }
    NoFloatingPointTraps(const NoFloatingPointTraps&) = delete;
    NoFloatingPointTraps& operator=(const NoFloatingPointTraps&) = delete;

  private:
    static void set(int traps) {
        feclearexcept(FE_ALL_EXCEPT);
        fedisableexcept(FE_ALL_EXCEPT);
        if (traps) feenableexcept(traps);
    }
    static void set_everywhere(int traps) {
        set(traps);
#pragma omp parallel
        set(traps);
    }
    int saved_;
};

/// Runs `f` without floating-point traps, turning the library's exceptions into the bridge's.
template <class F>
auto translated(F&& f) -> decltype(f()) {
    const NoFloatingPointTraps no_traps;
    try {
        return f();
    } catch (const Error&) {
        throw;
    } catch (const std::bad_alloc&) {
        throw Error("out of memory");
    } catch (const std::exception& e) {
        throw Error(e.what());
    }
}

Method method_of(const std::string& name) {
    if (const auto m = dgwarp::method_from_name(name)) return *m;
    std::string list;
    for (Method m : dgwarp::all_methods) list += (list.empty() ? "" : ", ") + std::string(dgwarp::method_name(m));
    throw Error("unknown method '" + name + "'; the methods are " + list);
}

dgwarp::Repair repair_of(const std::string& name) {
    if (name == "default") return dgwarp::Repair::method_default;
    if (name == "untangle") return dgwarp::Repair::untangle;
    if (name == "none") return dgwarp::Repair::none;
    throw Error("repair must be default, untangle or none, got '" + name + "'");
}

}  // namespace

struct Solver::Impl {
    Method method = Method::dg_harmonic;
    dgwarp::MethodOptions options;
    std::string options_text;
    dgwarp::FrameOptions frame;
    dgwarp::Mesh mesh;
    dgwarp::BoundarySet boundary;
    dgwarp::OriginalCells original;
    std::optional<dgwarp::Plan> plan;
#ifdef DGWARP_BRIDGE_MPI
    std::optional<dgwarp::mpi::DistributedPlan> distributed;
#endif
    bool parallel = false;
    std::int64_t moving = 0, fixed = 0;
    std::vector<std::string> patch_names;  // every patch, in the mesh's order
    std::vector<std::int32_t> slot_patch;  // per boundary slot: the first moving patch holding it, or -1
    double diagonal = 0;                   // of this process's points0
    double prepare_seconds = 0;

    /// The local checks and the mesh: everything that can fail on one process alone.
    void build(PolyMesh&& in, const Settings& settings) {
        method = method_of(settings.method);
        for (const auto& [name, value] : settings.options) {
            const std::optional<Method> owner = dgwarp::option_method(name);
            if (owner && *owner != method)
                throw Error("option " + name + " is an option of " + std::string(dgwarp::method_name(*owner)) +
                            "; it does nothing with " + settings.method);
            dgwarp::set_method_option(options, name, value);
            options_text += " " + name + " " + value;
        }
        frame.repair = repair_of(settings.repair);
        if (parallel && frame.repair != dgwarp::Repair::none && !(frame.repair == dgwarp::Repair::method_default &&
                                                                  method != Method::dg_harmonic))
            frame.repair = dgwarp::Repair::none;  // repairs move nodes of one process's cells: not in parallel

        const auto num_points = static_cast<std::int64_t>(in.points.size() / 3);
        if (in.face_offsets.empty() || in.owner.size() + 1 != in.face_offsets.size())
            throw Error("the polyMesh has " + std::to_string(in.owner.size()) + " owners for " +
                        std::to_string(in.face_offsets.empty() ? 0 : in.face_offsets.size() - 1) + " faces");
        dgwarp::foam::PolyMesh pm;
        pm.points = std::move(in.points);
        pm.face_offsets = std::move(in.face_offsets);
        pm.face_nodes = std::move(in.face_nodes);
        pm.owner = std::move(in.owner);
        pm.neighbour = std::move(in.neighbour);
        for (const Patch& p : in.patches) {
            dgwarp::foam::Patch patch;
            patch.name = p.name;
            patch.info.type = p.type;
            patch.start = p.start;
            patch.size = p.size;
            patch.processor = p.role == PatchRole::interface;
            pm.patches.push_back(std::move(patch));
        }
        const dgwarp::foam::FaceLines where{"polyMesh/faces", "polyMesh/owner", {}};
        dgwarp::foam::PolyMeshPart part = dgwarp::foam::poly_mesh_part(std::move(pm), in.num_cells, where,
                                                                       dgwarp::foam::Format::binary);
        mesh = std::move(part.mesh);
        if (static_cast<std::int64_t>(mesh.num_points()) != num_points) throw Error("points lost building the mesh");

        // The boundary: every point of a moving or fixed patch, moving when on a moving patch.
        std::vector<std::pair<NodeId, std::uint8_t>> nodes;
        std::size_t marker = 0;
        for (const Patch& p : in.patches) {
            if (p.role == PatchRole::interface) continue;
            const std::uint8_t is_moving = p.role == PatchRole::moving ? 1 : 0;
            for (const NodeId n : mesh.markers[marker].elements.nodes) nodes.emplace_back(n, is_moving);
            ++marker;
        }
        std::sort(nodes.begin(), nodes.end(), [](const auto& a, const auto& b) {
            return a.first != b.first ? a.first < b.first : a.second > b.second;  // moving first: it wins
        });
        for (std::size_t i = 0; i < nodes.size(); ++i) {
            if (i > 0 && nodes[i].first == nodes[i - 1].first) continue;
            boundary.nodes.push_back(nodes[i].first);
            boundary.moving.push_back(nodes[i].second);
            (nodes[i].second ? moving : fixed) += 1;
        }
        slot_patch.assign(boundary.nodes.size(), -1);
        marker = 0;
        for (std::size_t p = 0; p < in.patches.size(); ++p) {
            patch_names.push_back(in.patches[p].name);
            if (in.patches[p].role == PatchRole::interface) continue;
            if (in.patches[p].role == PatchRole::moving)
                for (const NodeId n : mesh.markers[marker].elements.nodes) {
                    const auto slot = std::lower_bound(boundary.nodes.begin(), boundary.nodes.end(), n) - boundary.nodes.begin();
                    if (slot_patch[static_cast<std::size_t>(slot)] < 0)
                        slot_patch[static_cast<std::size_t>(slot)] = static_cast<std::int32_t>(p);
                }
            ++marker;
        }
        const dgwarp::BoundingBox box = dgwarp::bounding_box(mesh);
        diagonal = std::hypot(box.max[0] - box.min[0], box.max[1] - box.min[1], box.max[2] - box.min[2]);
        original = dgwarp::measure_original(mesh);
    }
};

Solver::Solver(PolyMesh mesh, const Settings& settings, const Parallel* parallel) : impl_(std::make_unique<Impl>()) {
    Impl& s = *impl_;
    s.parallel = parallel != nullptr;
#ifndef DGWARP_BRIDGE_MPI
    if (s.parallel) throw Error("this dgwarpFoam was built without MPI: it cannot run in parallel");
#endif
    std::string failure;
    try {
        translated([&] { s.build(std::move(mesh), settings); });
    } catch (const Error& e) {
        if (!s.parallel) throw;
        failure = e.what();
    }
    dgwarp::Stopwatch sw;
#ifdef DGWARP_BRIDGE_MPI
    if (s.parallel) {
        // Every process throws, or none (the failing one with its message).
        translated([&] { dgwarp::mpi::detail::throw_if_any_failed(MPI_COMM_WORLD, failure, "the mesh or the settings"); });
        // prepare_distributed agrees on its own failures (every process throws).
        translated([&] {
            s.distributed.emplace(dgwarp::mpi::prepare_distributed(MPI_COMM_WORLD, s.method, 3, s.mesh.points,
                                                                   parallel->global_ids, s.boundary, s.options));
        });
        s.prepare_seconds = sw.lap();
        return;
    }
#endif
    translated([&] { s.plan.emplace(dgwarp::prepare_for_frames(s.method, s.mesh, s.boundary, s.options)); });
    s.prepare_seconds = sw.lap();
}

Solver::~Solver() = default;

std::int64_t Solver::moving_points() const { return impl_->moving; }
std::int64_t Solver::fixed_points() const { return impl_->fixed; }

std::string Solver::summary() const {
    const Impl& s = *impl_;
    std::ostringstream o;
    o << "dgwarp " << dgwarp::method_name(s.method) << (s.options_text.empty() ? "" : " (") << s.options_text
      << (s.options_text.empty() ? "" : " )") << ": " << s.mesh.num_points() << " points, " << s.mesh.cells.size()
      << " cells, " << s.moving << " moving and " << s.fixed << " fixed boundary points; prepared in ";
    char seconds[32];
    std::snprintf(seconds, sizeof seconds, "%.3f s", s.prepare_seconds);
    o << seconds;
    return o.str();
}

StepResult Solver::step(const double* displacement, const std::vector<RigidMotion>& rigid, double* new_points) {
    Impl& s = *impl_;
    if (!rigid.empty() && rigid.size() != s.patch_names.size())
        throw Error(std::to_string(rigid.size()) + " rigid motions for " + std::to_string(s.patch_names.size()) +
                    " patches");
    return translated([&] {
        dgwarp::BoundaryMotion motion(s.boundary.nodes.size());
        std::string mismatch;
        for (std::size_t i = 0; i < motion.size(); ++i) {
            if (!s.boundary.moving[i]) continue;
            const auto node = static_cast<std::size_t>(s.boundary.nodes[i]);
            const double* d = displacement + 3 * node;
            const std::int32_t p = s.slot_patch[i];
            if (p < 0 || rigid.empty() || !rigid[static_cast<std::size_t>(p)].rigid) {
                motion[i].translation = {d[0], d[1], d[2]};
                continue;
            }
            const RigidMotion& r = rigid[static_cast<std::size_t>(p)];
            motion[i] = {{r.translation[0], r.translation[1], r.translation[2]},
                         {r.rotation[0], r.rotation[1], r.rotation[2]},
                         {r.centre[0], r.centre[1], r.centre[2]}};
            // The rigid motion must put the point where its displacement does.
            double moved[3];
            dgwarp::apply_motion(motion[i], std::span<const double>(s.mesh.points.data() + 3 * node, 3), moved);
            for (int k = 0; k < 3; ++k)
                if (mismatch.empty() &&
                    !(std::abs(moved[k] - (s.mesh.points[3 * node + k] + d[k])) <= 1e-9 * s.diagonal))
                    mismatch = "patch " + s.patch_names[static_cast<std::size_t>(p)] +
                               ": its rigid motion moves point " + std::to_string(node) + " elsewhere than its displacement (" +
                               std::to_string(moved[k] - s.mesh.points[3 * node + k]) + " against " +
                               std::to_string(d[k]) + " in coordinate " + std::to_string(k) + ")";
        }
#ifdef DGWARP_BRIDGE_MPI
        if (s.parallel) dgwarp::mpi::detail::throw_if_any_failed(MPI_COMM_WORLD, mismatch, "a patch's rigid motion");
#endif
        if (!mismatch.empty()) throw Error(mismatch);
        const std::span<double> out(new_points, s.mesh.points.size());
        dgwarp::FrameReport report;
        std::optional<dgwarp::FrameCells> measured;
#ifdef DGWARP_BRIDGE_MPI
        if (s.distributed) {
            dgwarp::Stopwatch sw;
            report.step = dgwarp::mpi::deform_distributed(*s.distributed, s.mesh.points, motion, out);
            report.step_seconds = sw.lap();
        } else
#endif
            measured = dgwarp::step_frame(*s.plan, s.mesh, s.original, s.boundary.nodes, nullptr, motion, s.options, out,
                                          report);
        dgwarp::finish_frame(s.method, s.mesh, s.original, s.boundary.nodes, s.frame, out, report, {},
                             std::move(measured));

        StepResult r;
        r.cells = static_cast<std::int64_t>(s.mesh.cells.size());
        r.inverted = report.inverted_by_motion;
        r.worst_inverted = report.worst_inverted;
        r.min_quality = report.quality.min;
        r.mean_quality = report.quality.mean;
        if (report.untangled) r.repaired = report.untangled->below_target_before - report.untangled->below_target_after;
        r.last_resort = report.last_resort;
        r.guard_redo = report.step.guard.kept_redo;
        r.step_seconds = report.step_seconds;
        r.repair_seconds = report.repair_seconds;
        r.quality_seconds = report.quality_seconds;
        for (const dgwarp::Warning& w : dgwarp::step_warnings(report.step)) r.warnings.push_back(w.text);
        return r;
    });
}

}  // namespace dgwarp_bridge
