// deform_processors.hpp: each process reads, deforms, measures and writes its
// own processor folder of a decomposed OpenFOAM case; rank 0 reports.
#include "deform_processors.hpp"

#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <limits>
#include <nlohmann/json.hpp>
#include <variant>

#include "commands.hpp"
#include "dgwarp/core/error.hpp"
#include "dgwarp/core/stopwatch.hpp"
#include "dgwarp/io/marker_types.hpp"
#include "dgwarp/io/motion_file.hpp"
#include "dgwarp/io/openfoam/openfoam_frames.hpp"
#include "dgwarp/mpi/agreement.hpp"
#include "dgwarp/mpi/part_reductions.hpp"
#include "dgwarp/mpi/part_run.hpp"
#include "dgwarp/mpi/part_setup.hpp"
#include "dgwarp/mpi/reductions.hpp"
#include "distributed_run.hpp"
#include "flag_values.hpp"
#include "foam_output.hpp"
#include "output_files.hpp"
#include "processor_part.hpp"
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

// The arguments every process needs, sent by rank 0 (mpi_run_everywhere).
nlohmann::json processor_args_json(const DeformArgs& a, const std::string& given_output) {
    const SetupArgs& s = a.setup;
    return {{"mesh", s.mesh},
            {"motion", s.motion},
            {"method", s.method},
            {"method_given", s.method_given},
            {"given", std::vector<std::string>(s.given.begin(), s.given.end())},
            {"zone", s.zone},
            {"threads", s.threads},
            {"options", s.options},
            {"output", a.output},
            {"given_output", given_output},
            {"json", a.json},
            {"allow_invalid", a.allow_invalid},
            {"no_untangle", a.no_untangle},
            {"foam_time", a.foam_time},
            {"quiet", a.quiet}};
}

DeformArgs processor_args_from_json(const nlohmann::json& j, std::string& given_output) {
    DeformArgs a;
    SetupArgs& s = a.setup;
    s.mesh = j.at("mesh");
    s.motion = j.at("motion");
    s.method = j.at("method");
    s.method_given = j.at("method_given");
    for (const auto& g : j.at("given")) s.given.insert(g.get<std::string>());
    s.zone = j.at("zone");
    s.threads = j.at("threads");
    s.options = j.at("options").get<std::map<std::string, std::string, std::less<>>>();
    a.output = j.at("output");
    given_output = j.at("given_output");
    a.json = j.at("json");
    a.allow_invalid = j.at("allow_invalid");
    a.no_untangle = j.at("no_untangle");
    a.foam_time = j.at("foam_time");
    a.quiet = j.at("quiet");
    return a;
}

/// "a, b", or "none".
void deform_per_processor(const DeformArgs& a, const std::string& given_output) {
    const int rank = mpi_rank(), processes = mpi_processes();
    const bool text = rank == 0 && !a.json && !a.quiet;
    ProgressLine progress(text);
    WarningPrinter warnings(text);
    use_threads(a.setup.threads);
    const Method method = chosen_methods(a.setup, false).front();
    Inputs in;
    in.args = a.setup;
    ProcessorPart part;
    std::vector<NodeId> interface;
    std::vector<std::string> foam_times;
    Stopwatch sw;

    // Each process reads the motion and its own processor folder.
    collectively([&] {
        if (rank == 0) refuse_other_methods_options(a.setup, method);
        in.spec = read_motion_file(a.setup.motion);
        foam_times = foam_time_names(in.spec, frame_count(in.spec), a.foam_time);
        if (rank == 0) {
            std::vector<fs::path> inputs = motion_named_files(in.spec);
            inputs.insert(inputs.end(), {a.setup.mesh, a.setup.motion});
            for (const auto& file : mesh_input_files(a.setup.mesh)) inputs.push_back(file);
            check_openfoam_frame_outputs(a.output, foam_times, a.setup.mesh, inputs);
        }
        const std::vector<fs::path> processors = openfoam_processor_meshes(a.setup.mesh);
        if (processors.size() != static_cast<std::size_t>(processes))
            throw FormatError(a.setup.mesh + ": " + std::to_string(processors.size()) + " processor folders for " +
                              std::to_string(processes) + " processes");
        progress.phase("reading " + processors[static_cast<std::size_t>(rank)].string());
        OpenFoamProcessorMesh read = read_openfoam_processor(processors[static_cast<std::size_t>(rank)]);
        part.poly_mesh = processors[static_cast<std::size_t>(rank)];
        part.point_ids = std::move(read.point_ids);
        part.cell_ids = std::move(read.cell_ids);
        part.points_format = read.points_format;
        interface = std::move(read.interface_nodes);
        in.mesh = std::move(read.mesh);
        for (const Marker& m : in.mesh.markers) part.marker_elements.push_back(static_cast<std::int64_t>(m.elements.size()));
    });
    in.read_seconds = sw.lap();

    // The same patches, in the same order, on every process.
    std::string names;
    for (const Marker& m : in.mesh.markers) names += m.name + "\n";
    const std::string names0 = mpi::broadcast_text(world, names);
    collectively([&] {
        if (names != names0)
            throw ParseError((part.poly_mesh / "boundary").string(), 0,
                             "the patches of processor 0, in the same order (decomposePar writes every patch to every "
                             "processor)",
                             "other patches");
    });

    // The boundary: each process's nodes on the markers every process has them on.
    progress.phase("classifying the boundary");
    part.owned = mpi::share_interface_markers(world, in.mesh, interface, part.point_ids);
    // The tolerance one process takes: 1e-9 × the whole case's bounding-box diagonal.
    if (in.spec.shared_tolerance <= 0) in.spec.shared_tolerance = 1e-9 * mpi::bounding_box_diagonal_over_parts(world, in.mesh);
    collectively([&] {
        in.boundary = resolve_boundary(in.mesh, in.spec);
        // Each process holds its processor's part only; the sliding nodes'
        // first pass needs every boundary node (run/slide_pass.hpp).
        if (!in.boundary.sliding_markers.empty())
            throw Error("marker '" + in.boundary.sliding_markers.front() +
                        "' slides: sliding markers are not supported when each process reads its own processor "
                        "folder; run on one process, or on the reconstructed case");
    });
    const MeshCounts counts = case_counts(in.mesh, part);
    std::int64_t boundary_nodes = 0, moving_nodes = 0;
    for (std::size_t b = 0; b < in.boundary.boundary.nodes.size(); ++b)
        if (part.owned[static_cast<std::size_t>(in.boundary.boundary.nodes[b])]) {
            ++boundary_nodes;
            moving_nodes += in.boundary.boundary.moving[b];
        }
    boundary_nodes = mpi::sum(world, boundary_nodes);
    moving_nodes = mpi::sum(world, moving_nodes);
    in.resolve_seconds = sw.lap();

    // The original quality, judged by the whole case's majority orientation per cell type.
    progress.phase("measuring the original mesh's quality");
    std::vector<std::int8_t> own = cell_orientations(in.mesh);
    std::vector<std::int8_t> orientation = mpi::dominant_orientations_over_parts(world, in.mesh, own);
    in.original = measure_original(in.mesh, std::move(own), std::move(orientation));
    in.original.summary = mpi::quality_over_parts(world, in.original.quality, part.cell_ids);
    warn_already_inverted(in);
    in.boundary.warnings =
        mpi::warnings_over_parts(world, in.boundary.warnings, mpi::sum(world, owned_moving_and_static(in.mesh, in.boundary, part.owned)),
                      in.spec.shared_nodes);
    in.quality_seconds = sw.lap();
    progress.clear();
    const std::size_t frames = frame_count(in.spec);
    if (text) {
        std::cout << "mesh      " << in.args.mesh << ": " << describe_mesh(counts) << ", read by " << processes
                  << " processes, each its own processor folder\n";
        std::cout << "motion    " << in.args.motion << ": " << frames << " frame" << (frames == 1 ? "" : "s")
                  << "; moving: " << names_or_none(in.boundary.moving_markers)
                  << "; static: " << names_or_none(in.boundary.static_markers) << "\n";
        std::cout << "boundary  " << boundary_nodes << " nodes (" << moving_nodes << " moving)\n";
        for (const auto& w : in.boundary.warnings) warnings.print(w.text);
    }

    // The plan, on every process over its own nodes.
    MethodRun run;
    run.planned.method = method;
    run.planned.options = method_options(a.setup);
    progress.phase("preparing " + std::string(method_name(method)) + " on " + std::to_string(processes) + " processes");
    std::int64_t outside_hull = 0;
    collectively([&] {
        run.planned.distributed =
            mpi_prepare_own(method, 3, run.planned.options, in.mesh.points, part.point_ids, in.boundary.boundary,
                            run.planned.plan, run.planned.process_prepare_seconds, outside_hull);
    });
    run.planned.prepare_seconds = sw.lap();
    progress.clear();
    if (text) print_plan(std::cout, in, run.planned, warnings);

    bool base_written = false;
    const mpi::PartRunContext ctx{world, in.mesh, in.spec, in.boundary, in.original, *run.planned.distributed->own,
                                  part.cell_ids};
    mpi::PartRunCallbacks on;
    on.frame_started = [&](std::size_t k) {
        progress.phase(std::string(method_name(method)) + ": deforming" +
                       (frames > 1 ? " frame " + std::to_string(k) + " (" + std::to_string(k + 1) + " of " +
                                         std::to_string(frames) + ")"
                                   : ""));
    };
    on.frame_done = [&](const mpi::PartFrameView& view) {
        FrameResult f;
        static_cast<FrameReport&>(f) = view.report;
        f.frame = view.frame;
        f.time = view.time;
        f.own_parts = true;
        f.process_seconds = view.process_seconds;
        Stopwatch write_sw;
        if (method == Method::dg_harmonic && !a.no_untangle && f.inverted_by_motion > 0 && f.inverted_on_boundary == 0)
            // One process would repair them (the last resort); it moves nodes
            // that several processes hold, so it is not run on the parts.
            throw InvalidResultError(
                "dg-harmonic inverted " + std::to_string(f.inverted_by_motion) + " cell" +
                    (f.inverted_by_motion == 1 ? "" : "s") + " in frame " + std::to_string(f.frame) + " (worst: " +
                    cell_list(f.worst_inverted) +
                    "), which its last resort (untangle) would repair on one process; it does not run when each "
                    "process reads its own processor folder. Nothing was written for this frame. Run with "
                    "--untangle (rank 0 then reads the whole case and repairs them), or on one process",
                f.inverted_by_motion);
        if (f.valid() || a.allow_invalid) {
            write_processor_points(a.output, foam_times[f.frame], part, view.points, base_written);
            f.output = openfoam_points_file(fs::path(a.output) / "processor*", foam_times[f.frame]).file.string();
            f.write_seconds = write_sw.lap();
        }
        if (text) {
            progress.clear();
            print_frame(in, f, frames, warnings);
        }
        return add_frame(run, std::move(f), a.allow_invalid);
    };
    RunOptions options;
    options.stop_at_invalid = false;  // add_frame decides (--allow-invalid)
    mpi::run_frames_on_parts(ctx, options, on);
    progress.clear();

    if (a.json && rank == 0) {
        nlohmann::json j = inputs_json(in, "deform");
        j["mesh"] = mesh_json(counts);
        j["boundary"]["nodes"] = boundary_nodes;
        j["boundary"]["moving_nodes"] = moving_nodes;
        j["output"] = given_output;
        j["processes"] = processes;
        for (const auto& w : plan_warnings(run.planned)) {
            j["warnings"].push_back(w.text);
            j["warning_items"].push_back(warning_json(w));
        }
        const nlohmann::json method_run = run_json(in, run);
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

/// True when a marker of `spec` moves by a per-node table (node ids of the whole case).
bool has_node_tables(const MotionSpec& spec) {
    const auto tabled = [](const MarkerMotion& m) {
        return std::holds_alternative<PrescribedDisplacements>(m) || std::holds_alternative<PrescribedPositions>(m) ||
               std::holds_alternative<PrescribedNodeMotions>(m);
    };
    if (tabled(spec.default_motion)) return true;
    for (const MotionFrame& frame : spec.frames)
        for (const auto& [name, motion] : frame.markers)
            if (tabled(motion)) return true;
    return false;
}

}  // namespace

bool deforms_per_processor(const DeformArgs& a, const std::vector<Method>& methods) {
    if (mpi_processes() < 2 || methods.size() != 1 || !a.plan.empty() || a.untangle || !writes_openfoam(a.output))
        return false;
    try {
        const std::vector<fs::path> processors = openfoam_processor_meshes(a.setup.mesh);
        if (processors.size() != static_cast<std::size_t>(mpi_processes())) return false;
        MotionSpec spec = read_motion_file(a.setup.motion);
        if (has_node_tables(spec) || !a.setup.su2_config.empty() || !a.setup.rename_markers.empty()) return false;
        // Sliding markers (2D cases, symmetry planes) need every boundary node
        // in one first pass: the whole case is read on rank 0.
        const std::vector<OpenFoamPatchType> patches = openfoam_patch_types(processors.front());
        // So do cyclic patches: a node's image may be on another processor.
        if (std::any_of(patches.begin(), patches.end(), [](const OpenFoamPatchType& p) {
                return is_cyclic_type(p.type) || p.type == "processorCyclic";
            }))
            return false;
        std::vector<std::string> typed;
        for (const OpenFoamPatchType& p : patches)
            if (slides_by_type(p.type)) typed.push_back(p.name);
        slide_unless_named(spec, typed);
        return std::none_of(patches.begin(), patches.end(), [&](const OpenFoamPatchType& p) {
            return std::any_of(spec.frames.begin(), spec.frames.end(), [&](const MotionFrame& f) {
                return std::holds_alternative<SlideMotion>(marker_motion(spec, f, p.name));
            });
        });
    } catch (const Error&) {
        return false;  // the whole-case run reports it
    }
}

void run_deform_per_processor(const DeformArgs& a, const std::string& given_output) {
    mpi_run_everywhere(processor_args_json(a, given_output).dump());
    deform_per_processor(a, given_output);
}

int run_everywhere(const std::string& payload) {
    // Rank 0 reports every error; the other processes only exit with its code.
    try {
        std::string given_output;
        const DeformArgs a = processor_args_from_json(nlohmann::json::parse(payload), given_output);
        deform_per_processor(a, given_output);
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
