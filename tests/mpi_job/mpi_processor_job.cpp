// The library's job on a decomposed OpenFOAM case (dgwarp/mpi_job), run by
// ctest with mpirun at as many processes as the case has processor folders:
//   mpi_processor_job CASE WORK_DIR [SPHERE_CASE]
// CASE: the mixed case decomposed (its `top` moves); SPHERE_CASE: the
// snappy sphere decomposed in as many processors, whose sphere moves until
// cells fold away from the boundary (what dg-harmonic's last resort repairs).
// Every process reads only its processor folder; the case written is, read
// back whole, one process's run over the reconstructed case bit for bit.
// Every process runs the same tests in the same order (their collectives
// meet); a test failing on one process fails the run.
#include <mpi.h>

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "dgwarp/core/error.hpp"
#include "dgwarp/io/mesh_io.hpp"
#include "dgwarp/io/motion_file.hpp"
#include "dgwarp/mesh/mesh_counts.hpp"
#include "dgwarp/mpi/reductions.hpp"
#include "dgwarp/mpi/root_session.hpp"
#include "dgwarp/mpi_job/processor_job.hpp"
#include "dgwarp/run/run_deformation.hpp"
#include "../support/one_process_run.hpp"

using namespace dgwarp;
namespace fs = std::filesystem;

namespace {

fs::path case_path, work, sphere_case;

int rank_of() { return mpi::rank_in(MPI_COMM_WORLD); }
int size_of() { return mpi::processes_in(MPI_COMM_WORLD); }

// Rank 0 writes `text` to work/name; every process returns its path once it is there.
fs::path shared_file(const std::string& name, const std::string& text) {
    const fs::path p = work / name;
    if (rank_of() == 0) std::ofstream(p) << text;
    MPI_Barrier(MPI_COMM_WORLD);
    return p;
}

// A fresh output folder, the same on every process.
fs::path fresh_output(const std::string& name) {
    const fs::path p = work / name;
    if (rank_of() == 0) fs::remove_all(p);
    MPI_Barrier(MPI_COMM_WORLD);
    return p;
}

struct PartRun {
    JobInputs in;
    mpi::ProcessorCase c;
    mpi::PartPlan plan;
};

PartRun read_and_prepare(const fs::path& motion, const fs::path& out, Method method, const fs::path& in_case = case_path) {
    PartRun r;
    r.c = mpi::read_processor_job(MPI_COMM_WORLD, {in_case, motion, out, {}}, r.in);
    r.plan = mpi::prepare_part(MPI_COMM_WORLD, method, 3, r.in.mesh.points, r.c.part.point_ids, r.in.boundary.boundary);
    return r;
}

// The top rises and plunges in a series of three frames, moving in each.
const char* series_motion =
    R"({"markers": {"top": {"periodic": {"plunge": {"amplitude": [0, 0, 0.05], "frequency": 1, "phase_deg": 30}}}},
        "default": "fixed", "shared_nodes": "moving_wins", "time": {"time_step": 0.25, "steps": 3}})";

TEST(ProcessorJob, TheCaseWrittenIsOneProcessRunOverTheWholeCaseBitForBit) {
    const fs::path motion = shared_file("series.json", series_motion);
    const Mesh whole = read_mesh(case_path.string());
    const MotionSpec spec = read_motion_file(motion);
    for (Method method : {Method::dg_idw, Method::dg_harmonic}) {
        SCOPED_TRACE(std::string(method_name(method)));
        const fs::path out = fresh_output(std::string("series-") + std::string(method_name(method)));
        PartRun r = read_and_prepare(motion, out, method);

        // What the processes agreed on is the whole case's.
        const MeshCounts w = mesh_counts(whole);
        EXPECT_EQ(r.c.counts.nodes, w.nodes);
        EXPECT_EQ(r.c.counts.cells, w.cells);
        EXPECT_EQ(r.c.counts.cell_types, w.cell_types);
        ASSERT_EQ(r.c.counts.markers.size(), w.markers.size());
        for (std::size_t m = 0; m < w.markers.size(); ++m) {
            EXPECT_EQ(r.c.counts.markers[m].name, w.markers[m].name);
            EXPECT_EQ(r.c.counts.markers[m].elements, w.markers[m].elements);
            EXPECT_EQ(r.c.counts.markers[m].nodes, w.markers[m].nodes);
        }
        EXPECT_EQ(r.c.time_names, (std::vector<std::string>{"0", "0.25", "0.5"}));

        std::vector<std::string> written;
        const RunReport parts = mpi::run_processor_job(
            MPI_COMM_WORLD, r.in, r.c, r.plan, {},
            {.frame_started = {}, .frame_done = [&](const mpi::ProcessorFrame& f) {
                 written.push_back(f.written.string());
                 return true;
             }});
        ASSERT_EQ(written.size(), 3u);
        EXPECT_EQ(written[1], (out / ("processor" + std::to_string(rank_of())) / "0.25" / "polyMesh" / "points").string());

        // One process over the reconstructed case.
        const test::OneProcessRun whole_run = test::one_process_run(whole, spec, method);
        const RunReport& one = whole_run.report;
        const std::vector<std::vector<double>>& one_points = whole_run.points;
        ASSERT_EQ(parts.frames.size(), one.frames.size());
        for (std::size_t k = 0; k < one.frames.size(); ++k) {
            EXPECT_EQ(parts.frames[k].quality.min, one.frames[k].quality.min);
            EXPECT_EQ(parts.frames[k].quality.worst_cell, one.frames[k].quality.worst_cell);
            // The processors' time folders, read back as the whole case.
            const Mesh back = read_mesh((out / r.c.time_names[k]).string());
            ASSERT_EQ(back.points.size(), one_points[k].size());
            std::size_t differ = 0;
            for (std::size_t i = 0; i < back.points.size(); ++i) differ += back.points[i] != one_points[k][i];
            EXPECT_EQ(differ, 0u) << "frame " << k;
            EXPECT_NE(back.points, whole.points) << "frame " << k << " did not move";
        }
    }
}

TEST(ProcessorJob, AnInvertedFrameWritesNothingOnAnyProcess) {
    if (sphere_case.empty()) GTEST_SKIP() << "no decomposed sphere case for this many processes";
    // The sphere moves 0.48 of its radius 0.5 toward the side: cells fold between it and the side, none of
    // them with every node on the boundary.
    const fs::path motion = shared_file("sink.json", R"({"markers": {"sphere": {"translate": [0, 0, 0.48]}}, "default": "fixed"})");
    const auto points_file = [](const fs::path& out) {
        return out / ("processor" + std::to_string(rank_of())) / "0" / "polyMesh" / "points";
    };
    // DG-IDW: the frame is reported invalid, nothing is written.
    {
        const fs::path out = fresh_output("sink-dg-idw");
        PartRun r = read_and_prepare(motion, out, Method::dg_idw, sphere_case);
        bool any_written = false;
        const RunReport report = mpi::run_processor_job(
            MPI_COMM_WORLD, r.in, r.c, r.plan, {},
            {.frame_started = {}, .frame_done = [&](const mpi::ProcessorFrame& f) {
                 any_written |= !f.written.empty();
                 return true;
             }});
        ASSERT_EQ(report.frames.size(), 1u);
        EXPECT_GT(report.frames[0].inverted_by_motion, 0);
        EXPECT_FALSE(any_written);
        EXPECT_FALSE(fs::exists(points_file(out)));
    }
    // dg-harmonic repairs what its step folds (its last resort over the processes): valid, written, and the
    // coordinates of one process's run over the whole case, last resort and all, bit for bit.
    {
        const fs::path out = fresh_output("sink-dg-harmonic");
        PartRun r = read_and_prepare(motion, out, Method::dg_harmonic, sphere_case);
        const RunReport report = mpi::run_processor_job(MPI_COMM_WORLD, r.in, r.c, r.plan, {}, {});
        ASSERT_EQ(report.frames.size(), 1u);
        const FrameReport& f = report.frames[0];
        EXPECT_TRUE(f.last_resort);
        ASSERT_TRUE(f.untangled.has_value());
        EXPECT_GT(f.untangled->inverted_before, 0);
        EXPECT_EQ(f.inverted_by_motion, 0);
        EXPECT_TRUE(fs::exists(points_file(out)));
        // (One process without dg-harmonic's guard, which the parts do not run: the same step.)
        const Mesh whole = read_mesh(sphere_case.string());
        MethodOptions unguarded;
        unguarded.dg_harmonic.redo_below = -1;
        const test::OneProcessRun one =
            test::one_process_run(whole, read_motion_file(motion), Method::dg_harmonic, unguarded);
        ASSERT_TRUE(one.report.frames.at(0).last_resort);
        EXPECT_EQ(one.report.frames[0].untangled->inverted_before, f.untangled->inverted_before);
        EXPECT_EQ(one.report.frames[0].untangled->nodes_moved, f.untangled->nodes_moved);
        EXPECT_EQ(one.report.frames[0].quality.min, f.quality.min);
        const Mesh back = read_mesh((out / "0").string());
        ASSERT_EQ(back.points.size(), one.points[0].size());
        std::size_t differ = 0;
        for (std::size_t i = 0; i < back.points.size(); ++i) differ += back.points[i] != one.points[0][i];
        EXPECT_EQ(differ, 0u);
        // Without it, the step's folds: the frame is invalid, written only when asked.
        const fs::path raw = fresh_output("sink-dg-harmonic-raw");
        PartRun s = read_and_prepare(motion, raw, Method::dg_harmonic, sphere_case);
        mpi::ProcessorRunOptions options;
        options.last_resort = false;
        const RunReport folded = mpi::run_processor_job(MPI_COMM_WORLD, s.in, s.c, s.plan, options, {});
        EXPECT_GT(folded.frames.at(0).inverted_by_motion, 0);
        EXPECT_FALSE(folded.frames[0].last_resort);
        EXPECT_FALSE(fs::exists(points_file(raw)));
        options.write_invalid = true;
        mpi::run_processor_job(MPI_COMM_WORLD, s.in, s.c, s.plan, options, {});
        EXPECT_TRUE(fs::exists(points_file(raw)));
    }
}

TEST(ProcessorJob, CellsTheBoundaryItselfFoldsAreReportedNotRepaired) {
    // The top sinks through the case: cells with every node on the boundary fold, which no repair of the
    // volume can help. dg-harmonic's last resort does not run (as on one process); the frame is invalid.
    const fs::path motion = shared_file(
        "through.json", R"({"markers": {"top": {"translate": [0, 0, -2]}}, "default": "fixed", "shared_nodes": "moving_wins"})");
    const fs::path out = fresh_output("through");
    PartRun r = read_and_prepare(motion, out, Method::dg_harmonic);
    const RunReport report = mpi::run_processor_job(MPI_COMM_WORLD, r.in, r.c, r.plan, {}, {});
    ASSERT_EQ(report.frames.size(), 1u);
    EXPECT_GT(report.frames[0].inverted_on_boundary, 0);
    EXPECT_FALSE(report.frames[0].last_resort);
    EXPECT_FALSE(report.frames[0].untangled.has_value());
    EXPECT_FALSE(fs::exists(out / ("processor" + std::to_string(rank_of())) / "0" / "polyMesh" / "points"));
}

TEST(ProcessorJob, RefusalSaysWhyTheCaseIsReadWhole) {
    const int p = size_of();
    const fs::path lift = shared_file(
        "lift.json", R"({"markers": {"top": {"translate": [0, 0, 0.05]}}, "default": "fixed", "shared_nodes": "moving_wins"})");
    EXPECT_EQ(mpi::processor_job_refusal(case_path, lift, p), "");
    EXPECT_NE(mpi::processor_job_refusal(case_path, lift, p + 1).find("processor folders, for"), std::string::npos);
    const fs::path slide = shared_file(
        "slide.json", R"({"markers": {"top": {"translate": [0, 0, 0.05]}, "sides": "slide"}, "default": "fixed"})");
    EXPECT_NE(mpi::processor_job_refusal(case_path, slide, p).find("marker 'sides' slides"), std::string::npos)
        << mpi::processor_job_refusal(case_path, slide, p);
    EXPECT_NE(mpi::processor_job_refusal(case_path, work / "missing.json", p).find("missing.json"), std::string::npos);
    // A motion file that is not one: an error on every process alike, naming the file.
    const fs::path broken = shared_file("broken.json", "{");
    JobInputs in;
    try {
        mpi::read_processor_job(MPI_COMM_WORLD, {case_path, broken, work / "never", {}}, in);
        ADD_FAILURE() << "no error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("broken.json:1: expected valid JSON"), std::string::npos) << e.what();
    }
    EXPECT_FALSE(fs::exists(work / "never"));
}

}  // namespace

int main(int argc, char** argv) {
    MPI_Init(&argc, &argv);
    ::testing::InitGoogleTest(&argc, argv);
    if (argc != 3 && argc != 4) {
        std::fprintf(stderr, "usage: mpi_processor_job CASE WORK_DIR [SPHERE_CASE]\n");
        MPI_Finalize();
        return 2;
    }
    case_path = argv[1];
    work = argv[2];
    if (argc == 4) sphere_case = argv[3];
    if (rank_of() == 0) fs::create_directories(work);
    MPI_Barrier(MPI_COMM_WORLD);
    const int failed = RUN_ALL_TESTS();
    int any = failed != 0;
    MPI_Allreduce(MPI_IN_PLACE, &any, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
    MPI_Finalize();
    return any;
}
