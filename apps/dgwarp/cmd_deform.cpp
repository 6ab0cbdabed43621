// dgwarp deform MESH --motion M.json -o OUT: move the mesh with its boundary.
#include <malloc.h>

#include <cstdio>
#include <iomanip>
#include <iostream>
#include <memory>
#include <optional>

#include "commands.hpp"
#include "deform_processors.hpp"
#include "deform_report.hpp"
#include "deform_setup.hpp"
#include "dgwarp/core/atomic_write.hpp"
#include "dgwarp/core/error.hpp"
#include "dgwarp/core/stopwatch.hpp"
#include "dgwarp/io/mesh_io.hpp"
#include "dgwarp/io/openfoam/openfoam_frames.hpp"
#include "dgwarp/job/frame_outputs.hpp"
#include "dgwarp/quality/mesh_quality.hpp"
#include "dgwarp/run/run_deformation.hpp"
#include "flag_values.hpp"
#include "foam_output.hpp"
#include "output_files.hpp"
#include "report.hpp"

namespace dgwarp::cli {

namespace {

/// The output of `method` when several methods run: OUT with the method's name before the extension.
std::filesystem::path method_output(const std::filesystem::path& out, Method method, bool several) {
    if (!several) return out;
    std::filesystem::path p = out;
    p.replace_filename(out.stem().string() + "_" + std::string(method_name(method)) + out.extension().string());
    return p;
}

/// The run's plan (built or loaded; under mpirun, on every process:
/// `distributed`); false, with the run's error set, when the method failed
/// and the run goes on with the other methods.
bool plan_run(const Inputs& in, Method method, const DeformArgs& a, bool several, ProgressLine& progress,
              MethodRun& run, std::shared_ptr<DistributedRun>& distributed) {
    try {
        run.planned = plan_method(in, method, a.plan, progress, &distributed);
        return true;
    } catch (const InvalidResultError& e) {
        run.error = e.what();
        run.invalid = true;
    } catch (const Error& e) {
        if (!several) throw;
        run.error = e.what();
        run.invalid = run.failed = true;  // no mesh: the run is not valid
    }
    run.planned.method = method;
    return false;
}

/// The frames of `run` (planned by plan_run: run.planned, or the run's
/// error when `planned` is false, and then nothing more is done).
/// `foam_times`: for an OpenFOAM case output, each frame's time folder (foam_output.hpp); empty otherwise.
/// `beside`: with --foam-processors, the processor folders written with the whole case.
void deform_with_method(Inputs& in, MethodRun& run, bool planned, const DistributedRun* distributed,
                        const DeformArgs& a, bool several, bool text, const std::vector<std::string>& foam_times,
                        const std::vector<OpenFoamProcessor>& beside, ProgressLine& progress,
                        WarningPrinter& warnings) {
    if (!planned) return;
    const Method method = run.planned.method;
    const std::size_t frames = frame_count(in.spec);
    if (text && !several) print_plan(std::cout, in, run.planned, warnings);
    if (text && several)
        for (const auto& w : job_plan_warnings(run.planned)) warnings.print(std::string(method_name(method)) + ": " + w.text);
    const auto out = method_output(a.output, method, several);
    FrameOutputs outputs{out, frames, foam_times, beside};
    if (const std::string w = foam_times.empty() ? dropped_extras_warning(in.extras, in.args.mesh, out) : "";
        !w.empty() && !a.quiet)
        std::cerr << "warning: " << w << "\n";
    MethodRunOptions options;
    options.frame.repair = a.untangle ? Repair::untangle : a.no_untangle ? Repair::none : Repair::method_default;
    options.frame.untangle_target = a.untangle_target;
    options.write_invalid = a.allow_invalid;
    options.keep_step_errors = several;  // with --method all, the other methods go on
    RunCallbacks on;
    const std::string name(method_name(method));
    on.frame_started = [&](std::size_t k) {
        // Frame k as in the rows, the JSON and the file names (0-based), and how far the series is.
        const std::string phase = name + ": deforming" +
                                  (frames > 1 ? " frame " + std::to_string(k) + " (" + std::to_string(k + 1) + " of " +
                                                    std::to_string(frames) + ")"
                                              : "");
        progress.phase(phase);
        return progress.reporter(phase);
    };
    on.repair_started = [&](std::size_t) { progress.phase(name + ": untangling" + (a.untangle ? "" : " (last resort)")); };
    // One process: the plan's own step (run/deform_frame.hpp's step_frame,
    // DG-harmonic's guard on the frame's measure); spread over processes:
    // theirs, together.
    std::vector<double> process_seconds;
    if (distributed)
        on.step = [&](const ResolvedFrame& motion, std::span<double> step_out, const ProgressFn&) {
            return mpi_deform(*distributed, motion.motion, step_out, process_seconds);
        };
    dgwarp::run_method(in, run, outputs, options, on, [&](JobFrame& f) {
        f.process_seconds = process_seconds;
        if (text && !several) {
            progress.clear();
            print_frame(in, f, frames, warnings);
        }
    });
    progress.clear();
}

void print_table(const Inputs& in, const std::vector<MethodRun>& runs) {
    std::cout << "\nmethod       prepare     deform     min quality  mean quality  inverted  ratio min   status\n";
    char line[256];
    std::snprintf(line, sizeof line, "%-11s  %9s  %9s  %11.4f  %12.4f  %8lld  %9s   %s\n", "original", "", "",
                  in.original.summary.min, in.original.summary.mean,
                  static_cast<long long>(in.original.summary.inverted), "", "");
    std::cout << line;
    for (const MethodRun& r : runs) {
        const std::string name(method_name(r.planned.method));
        // The status last and whole: an error message is never cut.
        if (r.frames.empty()) {
            std::snprintf(line, sizeof line, "%-11s  %9s  %9s  %11s  %12s  %8s  %9s   ", name.c_str(),
                          r.error.empty() ? "" : "-", "-", "-", "-", "-", "-");
            std::cout << line << (r.failed ? "failed: " : "") << r.error << "\n";
        } else {
            const JobFrame& f = r.frames.back();
            double deform_seconds = 0;
            for (const auto& fr : r.frames) deform_seconds += fr.step_seconds;
            std::string status = r.error.empty() ? "ok" : r.error;
            if (f.step.guard.kept_redo)
                status += " (redone by laplacian, " + std::to_string(f.step.substeps) + " increments)";
            else if (f.step.substeps > 1)
                status += " (" + std::to_string(f.step.substeps) +
                          (r.planned.method == Method::dgm ? " DGM sub-steps)" : " increments)");
            if (r.failed) status = "failed: " + status;
            std::snprintf(line, sizeof line, "%-11s  %9s  %9s  %11.4f  %12.4f  %8lld  %9.4f   ", name.c_str(),
                          milliseconds(r.planned.prepare_seconds).c_str(), milliseconds(deform_seconds).c_str(),
                          f.quality.min, f.quality.mean, static_cast<long long>(f.quality.inverted), f.ratio.min);
            std::cout << line << status << "\n";
        }
    }
}

/// The files each method wrote (--method all), one line per method: "wrote F",
/// or for a time series "wrote FIRST ... LAST (N files)".
void print_written(const std::vector<MethodRun>& runs) {
    for (const MethodRun& r : runs) {
        std::vector<std::string> files;
        for (const JobFrame& f : r.frames)
            if (!f.output.empty()) files.push_back(f.output);
        if (files.empty()) continue;
        std::cout << "wrote " << files.front();
        if (files.size() > 1) std::cout << " ... " << files.back() << " (" << files.size() << " files)";
        std::cout << "\n";
    }
}

void run_deform(const DeformArgs& given) {
    DeformArgs a = given;
    set_sync_writes(a.sync);
    const bool foam = writes_openfoam(a.output);
    if (foam) {
        // "case/" names the folder "case": --method all writes case_dg-idw, ...
        std::filesystem::path out = a.output;
        while (out.filename().empty() && out.has_parent_path() && out.parent_path() != out) out = out.parent_path();
        a.output = out.string();
    } else if (!a.foam_time.empty()) {
        throw CLI::ValidationError("--foam-time", "is for an OpenFOAM case output (a folder, a name ending in '/')");
    }
    if (a.foam_processors && (!foam || !reads_openfoam(a.setup.mesh) ||
                              openfoam_unread_processor_folders(a.setup.mesh).empty()))
        throw CLI::ValidationError("--foam-processors",
                                   "is for an OpenFOAM case holding constant/polyMesh and processor* folders "
                                   "(decomposePar's usual layout) deformed into an OpenFOAM case");
    a.setup.writable_for = given.output;  // marker names the output cannot hold are made into ones it can
    std::vector<std::string> foam_times;
    const std::vector<Method> methods = chosen_methods(a.setup, true);
    const bool several = methods.size() > 1;
    if (several && !a.plan.empty())
        throw CLI::ValidationError("--plan", "a saved plan belongs to one method; it cannot be used with --method all");
    require_mesh_extension("--output", a.output);
    if (foam && deforms_per_processor(a, methods)) {
        // mpirun on a decomposed case: each process reads and writes its own processor folder.
        run_deform_per_processor(a, given.output);
        return;
    }
    const bool text = !a.json && !a.quiet;
    ProgressLine progress(text);
    Inputs in = read_motion_inputs(a.setup, progress, [&](const MotionSpec& spec) {
        // Every file this run may write (each method's, each frame's), before any work.
        std::vector<std::filesystem::path> inputs = motion_named_files(spec);
        inputs.insert(inputs.end(), {a.setup.mesh, a.setup.motion});
        for (const auto& file : mesh_input_files(a.setup.mesh)) inputs.push_back(file);
        if (!a.plan.empty()) inputs.emplace_back(a.plan);
        const std::size_t frames = frame_count(spec);
        if (foam) {
            foam_times = foam_time_names(spec, frames, a.foam_time);
            for (Method m : methods)
                check_openfoam_frame_outputs(method_output(a.output, m, several), foam_times, a.setup.mesh, inputs,
                                             a.foam_processors);
            return;
        }
        check_folder_writable(std::filesystem::path(a.output).parent_path());
        for (Method m : methods)
            for (std::size_t k = 0; k < frames; ++k) check_output(frame_path(method_output(a.output, m, several), k, frames), inputs);
    });
    // What the output's format cannot store (a marker name SU2 cannot hold):
    // refused now, naming the file, not after the work.
    {
        WriteOptions write_options;
        write_options.extras = &in.extras;
        check_mesh_writable(a.output, output_mesh(in), write_options);
    }
    if (foam && output_mesh(in).dim != 3)
        throw MeshError("OpenFOAM meshes are 3D: the " + std::to_string(in.mesh.dim) + "D mesh " + a.setup.mesh +
                        " cannot be written to the OpenFOAM case " + a.output);
    const std::size_t frames = frame_count(in.spec);
    // The first method's plan, with the original's quality measured beside it.
    std::vector<MethodRun> runs(methods.size());
    std::vector<char> planned(methods.size(), 0);
    std::vector<std::shared_ptr<DistributedRun>> distributed(methods.size());
    measure_original_cells(in, [&] {
        planned[0] = plan_run(in, methods[0], a, several, progress, runs[0], distributed[0]);
    });
#ifdef __GLIBC__
    // The prepare's freed temporaries (the triangulation, the k-d trees,
    // the factorisation's work arrays: blocks under 2 MiB, and Eigen's from
    // malloc) stay in malloc's heaps, scattered among live blocks: given
    // back, deform's peak at 865k nodes (with the frame's arrays) 421 -> 393 MB.
    malloc_trim(0);
#endif
    WarningPrinter warnings(text);
    if (text) print_inputs(std::cout, in, frames, warnings);
    // A decomposed case in its usual layout: which mesh this run reads and writes.
    std::vector<Warning> job_warnings;
    std::vector<OpenFoamProcessor> beside;
    if (a.foam_processors) {
        progress.phase("reading the processor folders");
        beside = read_processors_beside(a.setup.mesh, output_mesh(in).num_points());
        progress.clear();
    }
    if (auto w = unread_processors_warning(a.setup.mesh, a.foam_processors)) {
        w->text += " (--foam-processors writes them too)";
        warnings.print(w->text);
        job_warnings.push_back(std::move(*w));
    }

    for (std::size_t i = 0; i < methods.size(); ++i) {
        if (i > 0) planned[i] = plan_run(in, methods[i], a, several, progress, runs[i], distributed[i]);
        deform_with_method(in, runs[i], planned[i] != 0, distributed[i].get(), a, several, text, foam_times, beside,
                           progress, warnings);
    }
    if (text && several) {
        print_table(in, runs);
        print_written(runs);
    }
    // A shorter series than an earlier run's: its other frames are still there.
    if (!foam)
        for (const MethodRun& r : runs) {
            if (std::none_of(r.frames.begin(), r.frames.end(), [](const JobFrame& f) { return !f.output.empty(); }))
                continue;
            if (auto w = stale_frames_warning(method_output(a.output, r.planned.method, several), frames)) {
                warnings.print(w->text);
                job_warnings.push_back(std::move(*w));
            }
        }

    if (a.json) {
        nlohmann::json j = inputs_json(in, "deform");
        if (!runs[0].planned.plan_file.empty()) j["options"] = options_json(runs[0].planned.options, true);
        j["output"] = given.output;
        j["processes"] = mpi_processes();
        for (const auto& r : runs)
            for (const auto& w : job_plan_warnings(r.planned)) {
                const std::string name = several ? std::string(method_name(r.planned.method)) : std::string();
                j["warnings"].push_back(several ? name + ": " + w.text : w.text);
                j["warning_items"].push_back(warning_json(w, name));
            }
        if (several) {
            j["methods"] = nlohmann::json::array();
            for (const auto& r : runs) j["methods"].push_back(run_json(r));
        } else {
            const nlohmann::json run = run_json(runs[0]);
            for (const auto& [key, value] : run.items()) j[key] = value;
        }
        for (const Warning& w : job_warnings) {
            j["warnings"].push_back(w.text);
            j["warning_items"].push_back(warning_json(w));
        }
        j["valid"] = std::none_of(runs.begin(), runs.end(), [](const MethodRun& r) { return r.invalid; });
        std::cout << j.dump(2) << "\n";
    }
    // A method that inverted cells or failed makes the run invalid (exit 3);
    // --allow-invalid writes inverted meshes, but a failed method has none.
    std::int64_t invalid_runs = 0, failed_runs = 0;
    std::string what, failed, advice;
    for (const MethodRun& r : runs)
        if (r.invalid) {
            ++invalid_runs;
            const std::string line = std::string(method_name(r.planned.method)) + (r.failed ? " failed: " : ": ") + r.error;
            what += (what.empty() ? "" : "; ") + line;
            if (r.failed) {
                ++failed_runs;
                failed += (failed.empty() ? "" : "; ") + line;
            } else {
                advice += (advice.empty() ? "" : "; ") + invalid_result_advice(r.planned.method, a);
            }
        }
    if (invalid_runs > 0) {
        const std::string others = several && invalid_runs < static_cast<std::int64_t>(runs.size())
                                       ? " (the other methods' files were written)"
                                       : "";
        if (failed_runs == invalid_runs)  // nothing inverted: --allow-invalid would not help
            throw InvalidResultError(what + others, invalid_runs);
        if (!a.allow_invalid)
            throw InvalidResultError(what + ". Nothing was written for an invalid frame" + others + ". " + advice +
                                         "; or --allow-invalid to write it anyway",
                                     invalid_runs);
        if (failed_runs > 0)
            throw InvalidResultError(failed + ". The other methods' files were written (--allow-invalid)", failed_runs);
        if (!a.quiet) std::cerr << "warning: " << what << "; written anyway (--allow-invalid)\n";
    }
}

}  // namespace

std::string invalid_result_advice(Method method, const DeformArgs& a) {
    // Every frame is measured from the original mesh, so splitting a motion
    // into frames does not help; these do. What was already tried (given on
    // the command line) is not suggested again.
    const auto given = [&](const char* flag) { return a.setup.given.count(flag) > 0; };
    std::vector<std::string> tries;
    const auto add = [&](bool already, const std::string& what) {
        if (!already) tries.push_back(what);
    };
    const std::string untangle = "--untangle to repair the inverted cells";
    switch (method) {
        case Method::dg_idw:
            tries.push_back("--method dg-harmonic (robust next to fixed walls and for large rotations, docs/dg-harmonic.md)");
            add(given("--length-scale"), "--length-scale auto when a fixed wall is close to the moving one");
            add(a.untangle, untangle);
            break;
        case Method::dgm:
            add(given("--dgm-substep"), "--dgm-substep");
            tries.push_back("--method dg-harmonic");
            break;
        case Method::idw:
            tries.push_back("--method dg-harmonic");
            add(a.untangle, untangle);
            break;
        case Method::rbf:
            tries.push_back("--method dg-harmonic");
            add(given("--rbf-radius"), "a compact support (--rbf-radius)");
            add(a.untangle, untangle);
            break;
        case Method::laplacian:  // its increments already doubled up to 64 (docs/laplacian.md)
            add(given("--laplacian-exponent"), "another stiffness exponent (--laplacian-exponent 1 or 2)");
            add(given("--laplacian-model"), "the displacement Laplacian (--laplacian-model laplacian)");
            add(a.untangle, untangle);
            break;
        case Method::dg_harmonic:
            add(!a.no_untangle, "without --no-untangle (its last resort repairs the cells its step folds)");
            tries.push_back(given("--harmonic-wall-spacing")
                                ? "a smaller --harmonic-wall-spacing than " + a.setup.option("harmonic-wall-spacing") +
                                      " (a finer coarse level)"
                                : "a finer coarse level (--harmonic-wall-spacing 3)");
            break;
    }
    std::string advice = "For " + std::string(method_name(method)) + ": ";
    if (method == Method::dg_harmonic && !a.no_untangle)
        advice += std::string(a.untangle ? "--untangle" : "its untangle last resort") + " could not repair every cell; ";
    if (tries.empty()) {
        advice += "every option that could help was given";
    } else {
        advice += "try ";
        for (std::size_t k = 0; k < tries.size(); ++k)
            advice += (k == 0 ? "" : k + 1 == tries.size() ? ", or " : ", ") + tries[k];
    }
    if (method == Method::dg_harmonic)
        advice += "; check that the boundary motion itself does not fold the boundary's faces (docs/dg-harmonic.md)";
    return advice;
}

void add_deform_command(CLI::App& app) {
    auto args = std::make_shared<DeformArgs>();
    CLI::App* cmd = app.add_subcommand("deform", "Deform a mesh to follow the motion of its boundary markers");
    add_setup_options(cmd, args->setup);
    cmd->add_option("-o,--output", args->output,
                    "Output mesh (.su2, .msh, .vtu, .cgns; VTU adds displacement and quality; a CGNS output of a "
                    "CGNS input is a copy of it with new coordinates); a time series writes "
                    "one file per frame, numbered before the extension; --method all one per method. An "
                    "OpenFOAM case folder (a folder, a name ending in '/'): the moved points go to "
                    "CASE/<time>/polyMesh/points (--foam-time)")
        ->required();
    cmd->add_option("--foam-time", args->foam_time,
                    "OpenFOAM output: the time folder of the moved points (default 0; 'constant' replaces "
                    "constant/polyMesh/points); a series writes one per frame, named by its time (or number)");
    cmd->add_flag("--foam-processors", args->foam_processors,
                  "An OpenFOAM case holding constant/polyMesh and processor* folders (decomposePar's usual layout): "
                  "also write each processor's points (the whole mesh's, through its pointProcAddressing), so that a "
                  "parallel run reads the moved mesh too");
    cmd->add_option("--plan", args->plan, "Use a plan saved by 'dgwarp prepare' instead of building it");
    cmd->add_flag("--allow-invalid", args->allow_invalid, "Write the result even if cells are inverted");
    CLI::Option* untangle_flag =
        cmd->add_flag("--untangle", args->untangle,
                      "After each step, move the volume nodes around inverted cells until none is inverted "
                      "(boundary nodes stay; docs/UNTANGLE.md)");
    cmd->add_option("--untangle-target", args->untangle_target,
                    "With --untangle: also repair the cells of quality at or below this (default " +
                        number_text(UntangleOptions{}.target_quality) + ": inverted only)")
        ->check(number_between(0, 0.99))
        ->needs(untangle_flag);
    cmd->add_flag("--no-untangle", args->no_untangle,
                  "dg-harmonic: no last resort (by default, cells its step inverts are repaired by the untangle "
                  "step, reported in the output)")
        ->excludes(untangle_flag);
    cmd->add_flag("--sync", args->sync,
                  "Wait for the disk before renaming each output into place (fsync), so that it survives a power "
                  "cut right after the run too (without: a failed or interrupted write never leaves a partial file "
                  "either way; the disk's write time is spared)");
    cmd->add_flag("--json", args->json, "Print a JSON report (schema in docs/JSON.md)");
    cmd->add_flag("-q,--quiet", args->quiet, "Print nothing but errors");
    cmd->footer(
        "The motion file names each moving marker's motion (docs/MOTION.md); markers not named stay fixed.\n"
        "--method all runs every method and prints a comparison table (as the paper's tables).\n"
        "Exit code 3 when a cell is inverted: nothing is written for that frame unless --allow-invalid.\n"
        "No output (nor a frame's or a method's) may be an input; outputs are checked before the work.\n"
        "OpenFOAM (docs/OPENFOAM.md): CASE/constant/polyMesh is read; the moved points are written to\n"
        "OUT/0/polyMesh/points (OUT may be CASE itself: nothing else in it changes; another OUT gets a copy\n"
        "of CASE's constant/polyMesh).\n\n"
        "Examples (in the repository's folder: examples/motions/ has a motion file of every kind):\n"
        "  dgwarp case naca0012 -o naca0012.su2\n"
        "  dgwarp deform naca0012.su2 --motion examples/motions/airfoil_rotate.json -o turned.vtu\n"
        "  dgwarp deform naca0012.su2 --motion examples/motions/airfoil_rotate.json -o cmp.su2 --method all\n"
        "  dgwarp deform naca0012.su2 --motion examples/motions/airfoil_pitch_plunge.json -o pitch.su2"
        "   (one file per frame)\n"
        "  dgwarp deform tests/data/openfoam/mixed --motion examples/motions/openfoam_mixed_lift.json -o mixed/\n"
        "      (an OpenFOAM case: mixed/0/polyMesh/points beside a copy of its constant/polyMesh)\n"
        "  dgwarp prepare naca0012.su2 --motion examples/motions/airfoil_rotate.json -o naca0012.plan\n"
        "  dgwarp deform naca0012.su2 --motion examples/motions/airfoil_rotate.json --plan naca0012.plan -o turned.su2 "
        "--json");
    cmd->callback([args] { run_deform(*args); });
}

}  // namespace dgwarp::cli
