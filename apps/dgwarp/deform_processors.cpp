// deform_processors.hpp: each process reads, deforms, measures and writes its
// own processor folder of a decomposed OpenFOAM case; rank 0 reports.
#include "deform_processors.hpp"

#include <mpi.h>

#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "dgwarp/core/atomic_write.hpp"
#include "dgwarp/core/error.hpp"
#include "dgwarp/core/stopwatch.hpp"
#include "dgwarp/mpi/agreement.hpp"
#include "dgwarp/mpi_job/processor_job.hpp"
#include "distributed_run.hpp"
#include "flag_values.hpp"
#include "foam_output.hpp"
#include "output_files.hpp"
#include "report.hpp"

namespace dgwarp::cli {

namespace fs = std::filesystem;

namespace {

const MPI_Comm world = MPI_COMM_WORLD;

/// Runs `phase` on this process, then agrees with the others (mpi::agree):
/// every process goes on, or every process throws the first failure (a
/// command-line error as a UsageError).
template <class F>
void collectively(F&& phase) {
    mpi::collectively(world, [&] {
        try {
            phase();
        } catch (const CLI::ParseError& e) {
            throw UsageError(e.what());
        }
    });
}

}  // namespace

// The arguments every process needs, sent by rank 0 (mpi_run_everywhere):
// every field of both structs.
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(SetupArgs, mesh, motion, method, method_given, given, zone, su2_config,
                                   rename_markers, writable_for, threads, options)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(DeformArgs, setup, output, plan, json, allow_invalid, untangle, no_untangle,
                                   untangle_target, foam_time, foam_processors, quiet, sync)

namespace {

void deform_per_processor(const DeformArgs& a, const std::string& given_output) {
    const int rank = mpi_rank(), processes = mpi_processes();
    const bool text = rank == 0 && !a.json && !a.quiet;
    ProgressLine progress(text);
    WarningPrinter warnings(text);
    use_threads(a.setup.threads);
    set_sync_writes(a.sync);  // every process's outputs, as rank 0's
    const Method method = chosen_methods(a.setup, false).front();
    collectively([&] {
        if (rank == 0) refuse_other_methods_options(a.setup, method);
    });

    // Each process reads the motion and its own processor folder, and classifies and measures its part.
    const auto time_names = [&](const MotionSpec& spec) {
        try {
            return foam_time_names(spec, frame_count(spec), a.foam_time);
        } catch (const CLI::ParseError& e) {
            throw UsageError(e.what());
        }
    };
    Inputs in;
    in.args = a.setup;
    const mpi::ProcessorCase job = mpi::read_processor_job(world, {a.setup.mesh, a.setup.motion, a.output, time_names},
                                                           in, [&](const std::string& phase) { progress.phase(phase); });
    progress.clear();
    const std::size_t frames = frame_count(in.spec);
    if (text) {
        std::cout << "mesh      " << in.args.mesh << ": " << describe_mesh(job.counts) << ", read by " << processes
                  << " processes, each its own processor folder\n";
        std::cout << "motion    " << in.args.motion << ": " << frames << " frame" << (frames == 1 ? "" : "s")
                  << "; moving: " << names_or_none(in.boundary.moving_markers)
                  << "; static: " << names_or_none(in.boundary.static_markers) << "\n";
        std::cout << "boundary  " << job.boundary_nodes << " nodes (" << job.moving_nodes << " moving)\n";
        for (const auto& w : in.boundary.warnings) warnings.print(w.text);
    }

    // The plan, on every process over its own nodes.
    MethodRun run;
    run.planned.method = method;
    run.planned.options = method_options(a.setup);
    progress.phase("preparing " + std::string(method_name(method)) + " on " + std::to_string(processes) + " processes");
    Stopwatch sw;
    std::shared_ptr<DistributedRun> distributed;
    collectively([&] {
        std::int64_t outside_hull = 0;
        distributed = mpi_prepare_own(method, 3, run.planned.options, in.mesh.points, job.part.point_ids,
                                      in.boundary.boundary, run.planned.plan, run.planned.process_prepare_seconds,
                                      outside_hull);
        run.planned.outside_hull_over_processes = outside_hull;
    });
    run.planned.prepare_seconds = sw.lap();
    progress.clear();
    if (text) print_plan(std::cout, in, run.planned, warnings);

    mpi::ProcessorRunOptions options;
    options.write_invalid = a.allow_invalid;
    options.last_resort = !a.no_untangle;
    mpi::ProcessorRunCallbacks on;
    on.frame_started = [&](std::size_t k) {
        progress.phase(std::string(method_name(method)) + ": deforming" +
                       (frames > 1 ? " frame " + std::to_string(k) + " (" + std::to_string(k + 1) + " of " +
                                         std::to_string(frames) + ")"
                                   : ""));
    };
    on.frame_done = [&](const mpi::ProcessorFrame& done) {
        JobFrame f;
        static_cast<FrameReport&>(f) = done.view.report;
        f.frame = done.view.frame;
        f.time = done.view.time;
        f.own_parts = true;
        f.process_seconds = done.view.process_seconds;
        if (!done.written.empty()) {
            f.output = openfoam_points_file(fs::path(a.output) / "processor*", job.time_names[f.frame]).file.string();
            f.write_seconds = done.write_seconds;
        }
        if (text) {
            progress.clear();
            print_frame(in, f, frames, warnings);
        }
        return add_frame(run, std::move(f), a.allow_invalid);
    };
    mpi::run_processor_job(world, in, job, *distributed->own, options, on);
    progress.clear();

    if (a.json && rank == 0) {
        nlohmann::json j = inputs_json(in, "deform");
        j["mesh"] = mesh_json(job.counts);
        j["boundary"]["nodes"] = job.boundary_nodes;
        j["boundary"]["moving_nodes"] = job.moving_nodes;
        j["output"] = given_output;
        j["processes"] = processes;
        for (const auto& w : job_plan_warnings(run.planned)) {
            j["warnings"].push_back(w.text);
            j["warning_items"].push_back(warning_json(w));
        }
        const nlohmann::json method_run = run_json(run);
        for (const auto& [key, value] : method_run.items()) j[key] = value;
        j["valid"] = !run.invalid;
        std::cout << j.dump(2) << "\n";
    }
    if (run.invalid) {
        if (!a.allow_invalid)
            throw InvalidResultError(run.error + ". Nothing was written for an invalid frame. " +
                                         invalid_result_advice(method, a) + "; or --allow-invalid to write it anyway",
                                     1);
        if (!a.quiet && rank == 0) std::cerr << "warning: " << run.error << "; written anyway (--allow-invalid)\n";
    }
}

}  // namespace

bool deforms_per_processor(const DeformArgs& a, const std::vector<Method>& methods) {
    if (mpi_processes() < 2 || methods.size() != 1 || !a.plan.empty() || a.untangle || !writes_openfoam(a.output) ||
        !a.setup.su2_config.empty() || !a.setup.rename_markers.empty())
        return false;
    // Otherwise the whole case is read on rank 0 (mpi_session.hpp).
    return mpi::processor_job_refusal(a.setup.mesh, a.setup.motion, mpi_processes()).empty();
}

void run_deform_per_processor(const DeformArgs& a, const std::string& given_output) {
    mpi_run_everywhere(nlohmann::json{{"args", a}, {"given_output", given_output}}.dump());
    deform_per_processor(a, given_output);
}

int run_everywhere(const std::string& payload) {
    // Rank 0 reports every error; the other processes only exit with its code.
    try {
        const nlohmann::json j = nlohmann::json::parse(payload);
        deform_per_processor(j.at("args").get<DeformArgs>(), j.at("given_output").get<std::string>());
        return exit_ok;
    } catch (const CLI::ParseError&) {
        return exit_usage;
    } catch (const UsageError&) {
        return exit_usage;
    } catch (const InvalidResultError&) {
        return exit_invalid_result;
    } catch (const Error&) {
        return exit_bad_input;
    } catch (const std::exception&) {
        return exit_internal;
    }
}

}  // namespace dgwarp::cli
