// dgwarp: deform CFD volume meshes to follow moving boundaries.
#include <csignal>
#include <iostream>
#include <new>
#include <string>

#include "commands.hpp"
#include "dgwarp/core/atomic_write.hpp"
#include "dgwarp/core/error.hpp"
#include "dgwarp/core/version.hpp"
#include "flag_values.hpp"
#include "mpi_session.hpp"
#include "report.hpp"

namespace {

// Ctrl-C or a kill during a write: the temporary file goes too (the old
// output is intact anyway), then the signal ends the program as it would have.
extern "C" void remove_temporaries_and_stop(int sig) {
    dgwarp::remove_unfinished_temporary_files();
    std::signal(sig, SIG_DFL);
    std::raise(sig);
}

void remove_temporaries_on_signals() {
    // A signal the caller ignores (nohup, a background job's SIGINT) stays ignored.
    for (int sig : {SIGINT, SIGTERM, SIGHUP})
        if (std::signal(sig, remove_temporaries_and_stop) == SIG_IGN) std::signal(sig, SIG_IGN);
}

}  // namespace

namespace {
int run_command(int argc, char** argv);
}  // namespace

int main(int argc, char** argv) {
    using namespace dgwarp::cli;
    remove_temporaries_on_signals();
    // Under mpirun (docs/MPI.md), rank 0 runs the command and the other ranks
    // serve its distributed prepares and steps until it stops them.
    try {
        mpi_start(argc, argv);
    } catch (const dgwarp::Error& e) {
        std::cerr << "dgwarp: error: " << e.what() << "\n";
        return exit_bad_input;
    }
    if (mpi_rank() > 0) {
        // Rank 0's exit code, or that of the last run every process made: every rank exits alike.
        const int code = mpi_serve();
        mpi_stop();
        return code;
    }
    const int code = run_command(argc, argv);
    mpi_stop(code);
    return code;
}

namespace {

int run_command(int argc, char** argv) {
    using namespace dgwarp::cli;
    CLI::App app{"dgwarp: deform CFD volume meshes to follow moving and deforming boundaries.\n"
                 "Methods: dg-harmonic (the default, with its guard), the paper's DG-IDW (Delaunay-graph\n"
                 "inverse distance weighting, Wang, Qin & Zhao), DGM, IDW, RBF and the laplacian reference."};
    app.name("dgwarp");
    app.require_subcommand(1);
    app.set_version_flag("--version", "dgwarp " + std::string(dgwarp::version()));
    app.footer(
        "Examples (in the repository's folder: examples/motions/ has a motion file of every kind):\n"
        "  dgwarp demo                              run the built-in example\n"
        "  dgwarp case naca0012 -o naca0012.su2     write one of the paper's test meshes\n"
        "  dgwarp info naca0012.su2                 counts, markers, bounding box, quality\n"
        "  dgwarp check naca0012.su2 -m examples/motions/airfoil_rotate.json\n"
        "                                           check a motion against a mesh, every frame\n"
        "  dgwarp deform naca0012.su2 -m examples/motions/airfoil_rotate.json -o turned.su2\n"
        "                                           deform a mesh\n"
        "  dgwarp prepare naca0012.su2 -m examples/motions/airfoil_rotate.json -o naca0012.plan\n"
        "                                           build the plan once for many steps\n"
        "  dgwarp quality turned.su2 --reference naca0012.su2   quality summary of a mesh\n"
        "  dgwarp convert naca0012.su2 naca0012.vtu convert between formats\n"
        "  dgwarp picture turned.su2 -o turned.png  a 2D mesh coloured by quality\n"
        "  dgwarp bench --quick                     the paper's tables, ours beside them\n"
        "Run 'dgwarp COMMAND --help' for a command's options and examples.\n"
        "Exit codes: 0 success, 1 usage error, 2 bad input, 3 invalid result, 4 internal error.");
    add_deform_command(app);
    add_prepare_command(app);
    add_check_command(app);
    add_info_command(app);
    add_quality_command(app);
    add_convert_command(app);
    add_picture_command(app);
    add_demo_command(app);
    add_case_command(app);
    add_motion_field_command(app);
    add_bench_command(app);

    try {
        use_threads(0);  // OMP_NUM_THREADS too large would crash OpenMP; --threads sets it again
        app.parse(argc, argv);
        check_standard_output();
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForVersion& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        app.exit(e);
        return exit_usage;
    } catch (const dgwarp::UsageError& e) {
        std::cerr << "dgwarp: " << e.what() << "\nRun with --help for more information.\n";
        return exit_usage;
    } catch (const dgwarp::InvalidResultError& e) {
        std::cerr << "dgwarp: invalid result: " << e.what() << "\n";
        return exit_invalid_result;
    } catch (const dgwarp::Error& e) {
        std::cerr << "dgwarp: error: " << e.what() << "\n";
        return exit_bad_input;
    } catch (const std::bad_alloc&) {
        std::cerr << "dgwarp: out of memory\n";
        return exit_internal;
    } catch (const std::exception& e) {
        std::cerr << "dgwarp: internal error: " << e.what() << "\n";
        return exit_internal;
    }
    return exit_ok;
}

}  // namespace
