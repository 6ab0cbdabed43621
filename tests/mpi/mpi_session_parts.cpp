// The library's MPI layer a program without a partition of its own uses
// (dgwarp/mpi: mesh_parts, root_session, agreement, reductions,
// part_reductions), run by ctest with mpirun at P = 1 and 3. Every process
// runs the same tests in the same order (their collectives meet); a test
// failing on one process fails the run.
#include <mpi.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <new>
#include <numeric>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "dgwarp/cases/rect_box.hpp"
#include "dgwarp/core/error.hpp"
#include "dgwarp/motion/resolve_motion.hpp"
#include "dgwarp/mpi/agreement.hpp"
#include "dgwarp/mpi/mesh_parts.hpp"
#include "dgwarp/mpi/morton_partition.hpp"
#include "dgwarp/mpi/part_reductions.hpp"
#include "dgwarp/mpi/part_run.hpp"
#include "dgwarp/mpi/part_setup.hpp"
#include "dgwarp/mpi/reductions.hpp"
#include "dgwarp/mpi/root_session.hpp"
#include "../support/one_process_run.hpp"
#include "mesh_parts.hpp"
#include "dgwarp/quality/mesh_quality.hpp"
#include "dgwarp/run/run_deformation.hpp"

using namespace dgwarp;

namespace {

int rank_of(MPI_Comm comm = MPI_COMM_WORLD) {
    int r = 0;
    MPI_Comm_rank(comm, &r);
    return r;
}

int size_of(MPI_Comm comm = MPI_COMM_WORLD) {
    int s = 1;
    MPI_Comm_size(comm, &s);
    return s;
}

// Every moving boundary node turned by 10 degrees about the origin.
BoundaryMotion turn(const BoundarySet& b) {
    BoundaryMotion m(b.nodes.size());
    for (std::size_t j = 0; j < m.size(); ++j)
        if (b.moving[j]) m[j].rotation = {0, 0, 10 * 3.141592653589793 / 180};
    return m;
}

// The checks every split must pass: every node held, once per part, with its
// coordinates; every cell's nodes in its part; boundary nodes, flags and slots.
void expect_valid_split(const Mesh& mesh, const BoundarySet& whole, const std::vector<mpi::NodePart>& parts) {
    const std::size_t n = mesh.num_points();
    std::vector<int> holders(n, 0);
    std::vector<std::int32_t> slot_of(n, -1);
    for (std::size_t b = 0; b < whole.nodes.size(); ++b) slot_of[static_cast<std::size_t>(whole.nodes[b])] = static_cast<std::int32_t>(b);
    for (const mpi::NodePart& p : parts) {
        ASSERT_EQ(p.points.size(), p.global_ids.size() * 2);
        std::set<std::int64_t> seen(p.global_ids.begin(), p.global_ids.end());
        EXPECT_EQ(seen.size(), p.global_ids.size()) << "a node held twice by one part";
        std::vector<NodeId> expected_boundary;
        std::vector<std::int32_t> expected_slots;
        for (std::size_t i = 0; i < p.global_ids.size(); ++i) {
            const auto g = static_cast<std::size_t>(p.global_ids[i]);
            ++holders[g];
            EXPECT_EQ(p.points[2 * i], mesh.points[2 * g]);
            EXPECT_EQ(p.points[2 * i + 1], mesh.points[2 * g + 1]);
            if (slot_of[g] >= 0) {
                expected_boundary.push_back(static_cast<NodeId>(i));
                expected_slots.push_back(slot_of[g]);
            }
        }
        EXPECT_EQ(p.boundary.nodes, expected_boundary);
        EXPECT_EQ(p.slots, expected_slots);
        ASSERT_EQ(p.boundary.moving.size(), p.slots.size());
        for (std::size_t j = 0; j < p.slots.size(); ++j)
            EXPECT_EQ(p.boundary.moving[j], whole.moving[static_cast<std::size_t>(p.slots[j])]);
    }
    for (std::size_t g = 0; g < n; ++g) EXPECT_GE(holders[g], 1) << "node " << g << " held by no part";
}

TEST(SplitMesh, EveryCellsNodesInItsPart) {
    const Mesh mesh = make_rect_box();
    const BoundarySet whole = test::rect_box_boundary(mesh);
    for (int parts : {1, 2, 3, 5}) {
        const std::vector<mpi::NodePart> split = mpi::split_mesh(mesh, whole, parts);
        ASSERT_EQ(split.size(), static_cast<std::size_t>(parts));
        expect_valid_split(mesh, whole, split);
        const std::vector<std::int32_t> cell_part = mpi::morton_cell_parts(mesh, parts);
        for (std::size_t c = 0; c < mesh.cells.types.size(); ++c) {
            const mpi::NodePart& p = split[static_cast<std::size_t>(cell_part[c])];
            for (std::int64_t k = mesh.cells.offsets[c]; k < mesh.cells.offsets[c + 1]; ++k)
                EXPECT_NE(std::find(p.global_ids.begin(), p.global_ids.end(), mesh.cells.nodes[k]), p.global_ids.end());
        }
        // The nodes of one part: those of its cells and no other.
        std::size_t held = 0;
        for (const mpi::NodePart& p : split) held += p.global_ids.size();
        if (parts == 1) {
            EXPECT_EQ(held, mesh.num_points());
        } else {
            EXPECT_GT(held, mesh.num_points());  // interface nodes in several parts
        }
    }
}

TEST(SplitMesh, NodeListsAndLooseNodes) {
    Mesh mesh = make_rect_box();
    const BoundarySet whole = test::rect_box_boundary(mesh);
    // A node of no cell goes to part 0.
    mesh.points.insert(mesh.points.end(), {100.0, 100.0});
    const auto loose = static_cast<std::int64_t>(mesh.num_points() - 1);
    const std::vector<mpi::NodePart> split = mpi::split_mesh(mesh, whole, 3);
    expect_valid_split(mesh, whole, split);
    EXPECT_EQ(split[0].global_ids.back(), loose);
    // Lists: each part the nodes of its list, in the list's order, once.
    const std::vector<std::vector<NodeId>> lists = {{5, 3, 5, 0}, {1, 2}, {4}};
    const std::vector<mpi::NodePart> listed = mpi::split_mesh(mesh, whole, 3, lists);
    EXPECT_EQ(std::vector<std::int64_t>(listed[0].global_ids.begin(), listed[0].global_ids.begin() + 3),
              (std::vector<std::int64_t>{5, 3, 0}));
    EXPECT_EQ(listed[1].global_ids, (std::vector<std::int64_t>{1, 2}));
    EXPECT_EQ(listed[2].global_ids, (std::vector<std::int64_t>{4}));
    // The nodes of no list, after part 0's own, in order.
    EXPECT_EQ(listed[0].global_ids.size(), 3 + mesh.num_points() - 6);
    EXPECT_EQ(listed[0].global_ids[3], 6);
    expect_valid_split(mesh, whole, listed);
    EXPECT_THROW(mpi::split_mesh(mesh, whole, 2, {{0, 1}, {static_cast<NodeId>(mesh.num_points())}}), MeshError);
    EXPECT_THROW(mpi::split_mesh(mesh, whole, 0), UsageError);
}

// Rank 0 drives; the others serve until it stops them, and return serve_root's code.
template <class Root>
int drive(MPI_Comm comm, Root&& root, int stop_code, std::vector<std::string>* payloads = nullptr) {
    if (rank_of(comm) == 0) {
        root();
        mpi::root_stop(comm, stop_code);
        return stop_code;
    }
    return mpi::serve_root(comm, [&](const std::string& payload) {
        if (payloads) payloads->push_back(payload);
        return payload == "fail" ? 5 : 0;
    });
}

TEST(RootSession, StepsBitIdenticalToOneProcess) {
    const Mesh mesh = make_rect_box();
    const BoundarySet whole = test::rect_box_boundary(mesh);
    const BoundaryMotion motion = turn(whole);
    for (Method method : {Method::dg_idw, Method::idw}) {
        std::vector<double> one(mesh.points.size()), many(mesh.points.size(), -1);
        if (rank_of() == 0) deform(prepare(method, 2, mesh.points, whole), mesh.points, motion, one);
        std::vector<double> seconds;
        drive(MPI_COMM_WORLD,
              [&] {
                  const mpi::RootRun run = mpi::root_prepare(MPI_COMM_WORLD, mesh, whole, method);
                  EXPECT_EQ(run.parts.size(), static_cast<std::size_t>(size_of()));
                  EXPECT_EQ(run.plan.prepare_seconds.size(), static_cast<std::size_t>(size_of()));
                  for (int k = 0; k < 2; ++k) mpi::root_deform(run, motion, many, seconds);
              },
              0);
        if (rank_of() == 0) {
            EXPECT_EQ(many, one) << method_name(method);
            EXPECT_EQ(seconds.size(), static_cast<std::size_t>(size_of()));
        }
    }
}

TEST(RootSession, PreparesAgainAfterAFailure) {
    const Mesh mesh = make_rect_box();
    const BoundarySet whole = test::rect_box_boundary(mesh);
    std::vector<double> out(mesh.points.size()), one(mesh.points.size()), seconds;
    if (rank_of() == 0) deform(prepare(Method::dg_idw, 2, mesh.points, whole), mesh.points, turn(whole), one);
    drive(MPI_COMM_WORLD,
          [&] {
              MethodOptions bad;
              bad.dg_idw.a_translation = -1;
              EXPECT_THROW(mpi::root_prepare(MPI_COMM_WORLD, mesh, whole, Method::dg_idw, bad), Error);
              const mpi::RootRun run = mpi::root_prepare(MPI_COMM_WORLD, mesh, whole, Method::dg_idw);
              mpi::root_deform(run, turn(whole), out, seconds);
          },
          0);
    if (rank_of() == 0) {
        EXPECT_EQ(out, one);
    }
}

TEST(RootSession, PayloadsAndExitCodes) {
    std::vector<std::string> payloads;
    // The root's non-zero code wins; else the last payload's.
    const int a = drive(MPI_COMM_WORLD, [&] { mpi::root_run_everywhere(MPI_COMM_WORLD, "fail"); }, 0, &payloads);
    const int b = drive(MPI_COMM_WORLD, [&] { mpi::root_run_everywhere(MPI_COMM_WORLD, "fine"); }, 2, &payloads);
    if (rank_of() > 0) {
        EXPECT_EQ(a, 5);
        EXPECT_EQ(b, 2);
        EXPECT_EQ(payloads, (std::vector<std::string>{"fail", "fine"}));
    }
}

// The error of `failing` (the last rank), as every process sees it.
template <class Make>
std::exception_ptr agreed(Make&& make) {
    const int failing = size_of() - 1;
    try {
        mpi::collectively(MPI_COMM_WORLD, [&] {
            if (rank_of() == failing) make();
        });
    } catch (...) {
        return std::current_exception();
    }
    return nullptr;
}

std::string prefix() { return rank_of() == size_of() - 1 ? "" : "process " + std::to_string(size_of() - 1) + ": "; }

TEST(Agreement, EveryProcessThrowsTheSameKind) {
    EXPECT_EQ(agreed([] {}), nullptr);
    try {
        std::rethrow_exception(agreed([] { throw UsageError("bad option"); }));
    } catch (const UsageError& e) {
        EXPECT_EQ(std::string(e.what()), prefix() + "bad option");
    }
    try {
        std::rethrow_exception(agreed([] { throw InvalidResultError("7 inverted", 7); }));
    } catch (const InvalidResultError& e) {
        EXPECT_EQ(e.count(), 7);
        EXPECT_EQ(std::string(e.what()), prefix() + "7 inverted");
    }
    try {
        std::rethrow_exception(agreed([] { throw MeshError("node 3", "wall", 3); }));
    } catch (const MeshError& e) {
        EXPECT_EQ(rank_of(), size_of() - 1);  // the failing process's own error, whole
        EXPECT_EQ(e.index(), 3);
    } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()), prefix() + "node 3");
    }
    const std::exception_ptr oom = agreed([] { throw std::bad_alloc(); });
    if (rank_of() == size_of() - 1) {
        EXPECT_THROW(std::rethrow_exception(oom), std::bad_alloc);
    } else {
        try {
            std::rethrow_exception(oom);
        } catch (const std::runtime_error& e) {
            EXPECT_EQ(std::string(e.what()), prefix() + "out of memory");
        }
    }
}

TEST(Reductions, SumsGathersAndTexts) {
    const int rank = rank_of(), size = size_of();
    EXPECT_EQ(mpi::sum(MPI_COMM_WORLD, std::int64_t{rank + 1}), std::int64_t{size * (size + 1) / 2});
    EXPECT_EQ(mpi::min(MPI_COMM_WORLD, 1.5 + rank), 1.5);
    EXPECT_EQ(mpi::max(MPI_COMM_WORLD, std::int64_t{rank}), std::int64_t{size - 1});
    EXPECT_EQ(mpi::sum(MPI_COMM_WORLD, std::vector<double>{1.0, double(rank)}),
              (std::vector<double>{double(size), double(size * (size - 1) / 2)}));
    // Rank r gives r values r.
    std::vector<std::int64_t> counts, expected, expected_counts;
    for (int r = 0; r < size; ++r) {
        expected.insert(expected.end(), static_cast<std::size_t>(r), r);
        expected_counts.push_back(r);
    }
    EXPECT_EQ(mpi::all_gather(MPI_COMM_WORLD, std::vector<std::int64_t>(static_cast<std::size_t>(rank), rank), &counts),
              expected);
    EXPECT_EQ(counts, expected_counts);
    const int root = size - 1;
    const std::vector<std::string> texts = mpi::gather_text(MPI_COMM_WORLD, std::string(static_cast<std::size_t>(rank), 'x'), root);
    if (rank == root) {
        ASSERT_EQ(texts.size(), static_cast<std::size_t>(size));
        for (int r = 0; r < size; ++r) EXPECT_EQ(texts[static_cast<std::size_t>(r)], std::string(static_cast<std::size_t>(r), 'x'));
    } else {
        EXPECT_TRUE(texts.empty());
    }
    EXPECT_EQ(mpi::broadcast_text(MPI_COMM_WORLD, rank == root ? "from the root" : "ignored", root), "from the root");
}

TEST(PartReductions, AsOneProcessOverTheWholeMesh) {
    const int rank = rank_of(), size = size_of();
    // 1,000 cells' qualities with ties at the minimum (cells 17 and 900) and inverted cells.
    std::vector<double> all(1000);
    for (std::size_t c = 0; c < all.size(); ++c) all[c] = 0.05 + 0.9 * std::fmod(0.6180339887 * double(c), 1.0);
    all[17] = all[900] = -0.25;
    all[400] = 0.0;
    // This process's cells: every size-th, from the end (ids not ascending).
    std::vector<double> mine;
    std::vector<std::int64_t> ids;
    for (std::int64_t c = 999 - rank; c >= 0; c -= size) {
        mine.push_back(all[static_cast<std::size_t>(c)]);
        ids.push_back(c);
    }
    const QualitySummary whole = summarize_quality(all);
    const QualitySummary parts = mpi::quality_over_parts(MPI_COMM_WORLD, mine, ids);
    EXPECT_EQ(parts.cells, whole.cells);
    EXPECT_EQ(parts.min, whole.min);
    EXPECT_EQ(parts.worst_cell, 17);
    EXPECT_EQ(parts.inverted, whole.inverted);
    EXPECT_EQ(parts.histogram.counts, whole.histogram.counts);
    EXPECT_NEAR(parts.mean, whole.mean, 1e-14);
    // The worst inverted: -0.25 at 17 and 900, then 0 at 400.
    std::vector<std::int64_t> inverted;
    for (std::size_t i = 0; i < mine.size(); ++i)
        if (mine[i] <= 0) inverted.push_back(static_cast<std::int64_t>(i));
    const auto [worst, count] = mpi::worst_over_parts(MPI_COMM_WORLD, inverted, mine, ids, 2);
    EXPECT_EQ(worst, (std::vector<std::int64_t>{17, 900}));
    EXPECT_EQ(count, 3);
    // A warning every process gives, once; one only the last gives, with its
    // rank; an empty marker on some processes only, dropped.
    std::vector<Warning> warnings = {Warning(WarningCode::other, "everywhere")};
    if (rank == size - 1) warnings.emplace_back(WarningCode::other, "only here");
    if (rank == 0 && size > 1) warnings.emplace_back(WarningCode::empty_named_marker, "marker 'w' has no elements", "w");
    const std::vector<Warning> agreed_warnings = mpi::warnings_over_parts(MPI_COMM_WORLD, warnings);
    if (rank == 0) {
        std::vector<std::string> texts;
        for (const Warning& w : agreed_warnings) texts.push_back(w.text);
        const std::string only = size > 1 ? "process " + std::to_string(size - 1) + ": only here" : "only here";
        EXPECT_EQ(texts, (std::vector<std::string>{"everywhere", only}));
    } else {
        EXPECT_TRUE(agreed_warnings.empty());
    }
}

TEST(PartSetup, DiagonalAndOrientationsAsTheWholeMesh) {
    const int rank = rank_of(), size = size_of();
    const Mesh whole = make_rect_box();
    const std::vector<mpi::NodePart> split = mpi::split_mesh(whole, test::rect_box_boundary(whole), size);
    Mesh part;
    part.dim = 2;
    part.points = split[static_cast<std::size_t>(rank)].points;
    double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
    for (std::size_t i = 0; i < whole.points.size(); ++i) {
        lo[i % 2] = std::min(lo[i % 2], whole.points[i]);
        hi[i % 2] = std::max(hi[i % 2], whole.points[i]);
    }
    EXPECT_EQ(mpi::bounding_box_diagonal_over_parts(MPI_COMM_WORLD, part),
              std::sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1])));
    // Two triangles and a quadrilateral per process; rank 0's triangles both
    // -1, the others' one of each: the triangles' majority is -1 only over
    // the whole mesh (each other process alone is balanced, +1).
    Mesh cells;
    cells.dim = 2;
    cells.points.assign(8, 0.0);
    const NodeId tri[3] = {0, 1, 2}, quad[4] = {0, 1, 2, 3};
    cells.cells.push_back(CellType::triangle, tri);
    cells.cells.push_back(CellType::triangle, tri);
    cells.cells.push_back(CellType::quadrilateral, quad);
    const std::vector<std::int8_t> own = rank == 0 ? std::vector<std::int8_t>{-1, -1, 1} : std::vector<std::int8_t>{1, -1, 1};
    EXPECT_EQ(mpi::dominant_orientations_over_parts(MPI_COMM_WORLD, cells, own), (std::vector<std::int8_t>{-1, -1, 1}));
    EXPECT_THROW(mpi::dominant_orientations_over_parts(MPI_COMM_WORLD, cells, std::vector<std::int8_t>{1}), MeshError);
}

TEST(PartSetup, InterfaceNodesOnEveryMarkerAnyProcessHasThemOn) {
    const int rank = rank_of(), size = size_of();
    // Every process: its own node (global 100 + rank), then the shared nodes 7 and 8.
    Mesh part;
    part.dim = 2;
    part.points = {double(rank), 0, 7, 0, 8, 0};
    const std::vector<std::int64_t> ids = {100 + rank, 7, 8};
    part.markers = {{"a", {}}, {"b", {}}};
    const NodeId own_node = 0, seven = 1, eight = 2;
    if (rank == size - 1) part.markers[0].elements.push_back(CellType::vertex, {&seven, 1});
    if (rank == 0) {
        part.markers[1].elements.push_back(CellType::vertex, {&own_node, 1});
        part.markers[1].elements.push_back(CellType::vertex, {&eight, 1});
    }
    const std::vector<NodeId> interface = {seven, eight};
    const std::vector<std::uint8_t> owned = mpi::share_interface_markers(MPI_COMM_WORLD, part, interface, ids);
    EXPECT_EQ(owned, rank == 0 ? (std::vector<std::uint8_t>{1, 1, 1}) : (std::vector<std::uint8_t>{1, 0, 0}));
    EXPECT_EQ(marker_nodes(part.markers[0]), (std::vector<NodeId>{seven}));
    EXPECT_EQ(marker_nodes(part.markers[1]),
              rank == 0 ? (std::vector<NodeId>{own_node, eight}) : (std::vector<NodeId>{eight}));
}

// This process's part of `whole`: the cells morton_cell_parts gives it, their
// nodes, the marker elements whose nodes it holds, and its interface nodes'
// markers shared (as a decomposed case's processor folder holds it).
struct MeshPart {
    Mesh mesh;
    std::vector<std::int64_t> global_ids, cell_ids;
};

MeshPart part_of(const Mesh& whole, int rank, int size) {
    const std::vector<std::int32_t> cell_part = mpi::morton_cell_parts(whole, size);
    MeshPart p;
    p.mesh.dim = whole.dim;
    std::vector<NodeId> local(whole.num_points(), -1);
    std::vector<int> holders(whole.num_points(), 0);
    std::vector<std::vector<std::uint8_t>> held(static_cast<std::size_t>(size), std::vector<std::uint8_t>(whole.num_points(), 0));
    for (std::size_t c = 0; c < whole.cells.size(); ++c)
        for (std::int64_t k = whole.cells.offsets[c]; k < whole.cells.offsets[c + 1]; ++k) {
            const auto n = static_cast<std::size_t>(whole.cells.nodes[static_cast<std::size_t>(k)]);
            if (!held[static_cast<std::size_t>(cell_part[c])][n]++) ++holders[n];
        }
    const auto local_of = [&](NodeId g) {
        if (local[static_cast<std::size_t>(g)] < 0) {
            local[static_cast<std::size_t>(g)] = static_cast<NodeId>(p.global_ids.size());
            p.global_ids.push_back(g);
            for (int d = 0; d < whole.dim; ++d) p.mesh.points.push_back(whole.points[static_cast<std::size_t>(g) * 2 + d]);
        }
        return local[static_cast<std::size_t>(g)];
    };
    for (std::size_t c = 0; c < whole.cells.size(); ++c) {
        if (cell_part[c] != rank) continue;
        std::vector<NodeId> nodes;
        for (std::int64_t k = whole.cells.offsets[c]; k < whole.cells.offsets[c + 1]; ++k)
            nodes.push_back(local_of(whole.cells.nodes[static_cast<std::size_t>(k)]));
        p.mesh.cells.push_back(whole.cells.types[c], nodes);
        p.cell_ids.push_back(static_cast<std::int64_t>(c));
    }
    for (const Marker& m : whole.markers) {
        Marker mine{m.name, {}};
        for (std::size_t e = 0; e < m.elements.size(); ++e) {
            std::vector<NodeId> nodes;
            for (std::int64_t k = m.elements.offsets[e]; k < m.elements.offsets[e + 1]; ++k) {
                const NodeId g = m.elements.nodes[static_cast<std::size_t>(k)];
                if (local[static_cast<std::size_t>(g)] >= 0) nodes.push_back(local[static_cast<std::size_t>(g)]);
            }
            if (nodes.size() == static_cast<std::size_t>(m.elements.offsets[e + 1] - m.elements.offsets[e]))
                mine.elements.push_back(m.elements.types[e], nodes);
        }
        p.mesh.markers.push_back(std::move(mine));
    }
    std::vector<NodeId> interface;
    for (std::size_t i = 0; i < p.global_ids.size(); ++i)
        if (holders[static_cast<std::size_t>(p.global_ids[i])] > 1) interface.push_back(static_cast<NodeId>(i));
    mpi::share_interface_markers(MPI_COMM_WORLD, p.mesh, interface, p.global_ids);
    return p;
}

TEST(PartRun, FramesOverThePartsAreOneProcessRunOverTheWholeMesh) {
    const int rank = rank_of(), size = size_of();
    const Mesh whole = make_rect_box();
    MotionSpec spec;
    spec.frames.resize(2);
    for (std::size_t k = 0; k < 2; ++k)
        spec.frames[k].markers["rectangle"] = RigidMotion{NodeMotion{.rotation = {0, 0, (10.0 + 25.0 * double(k)) * 3.141592653589793 / 180}}};
    // One process over the whole mesh.
    const test::OneProcessRun whole_run = test::one_process_run(whole, spec, Method::dg_idw);
    const RunReport& one = whole_run.report;
    const std::vector<std::vector<double>>& one_points = whole_run.points;
    // Every process over its part.
    MeshPart part = part_of(whole, rank, size);
    const ResolvedBoundary boundary = resolve_boundary(part.mesh, spec);
    std::vector<std::int8_t> own = cell_orientations(part.mesh);
    std::vector<std::int8_t> orientation = mpi::dominant_orientations_over_parts(MPI_COMM_WORLD, part.mesh, own);
    const OriginalCells original = measure_original(part.mesh, std::move(own), std::move(orientation));
    const mpi::PartPlan plan =
        mpi::prepare_part(MPI_COMM_WORLD, Method::dg_idw, 2, part.mesh.points, part.global_ids, boundary.boundary);
    const mpi::PartRunContext ctx{MPI_COMM_WORLD, part.mesh, spec, boundary, original, plan, part.cell_ids};
    std::size_t seen = 0;
    mpi::PartRunCallbacks on;
    on.frame_done = [&](const mpi::PartFrameView& f) {
        ++seen;
        // This process's coordinates are the whole run's, bit for bit.
        for (std::size_t i = 0; i < part.global_ids.size(); ++i)
            for (int dd = 0; dd < 2; ++dd)
                EXPECT_EQ(f.points[i * 2 + dd], one_points[f.frame][static_cast<std::size_t>(part.global_ids[i]) * 2 + dd]);
        return true;
    };
    const RunReport parts = mpi::run_frames_on_parts(ctx, {}, on);
    ASSERT_EQ(parts.frames.size(), one.frames.size());
    EXPECT_EQ(seen, one.frames.size());
    for (std::size_t k = 0; k < one.frames.size(); ++k) {
        const FrameReport &a = parts.frames[k], &b = one.frames[k];
        EXPECT_EQ(a.quality.cells, b.quality.cells);
        EXPECT_EQ(a.quality.min, b.quality.min);
        EXPECT_EQ(a.quality.worst_cell, b.quality.worst_cell);
        EXPECT_EQ(a.quality.histogram.counts, b.quality.histogram.counts);
        EXPECT_NEAR(a.quality.mean, b.quality.mean, 1e-13);
        EXPECT_EQ(a.ratio.min, b.ratio.min);
        EXPECT_EQ(a.inverted_by_motion, b.inverted_by_motion);
        EXPECT_EQ(a.worst_inverted, b.worst_inverted);
    }
    // A failure in one process's frame_done stops every process, with its error.
    on.frame_done = [&](const mpi::PartFrameView&) {
        if (rank == size - 1) throw IoError("part.out", "disk full");
        return true;
    };
    EXPECT_THROW(mpi::run_frames_on_parts(ctx, {}, on), Error);
}

}  // namespace

int main(int argc, char** argv) {
    MPI_Init(&argc, &argv);
    ::testing::InitGoogleTest(&argc, argv);
    const int failed = RUN_ALL_TESTS();
    // Every process's verdict: the run fails when one fails.
    int any = failed != 0;
    MPI_Allreduce(MPI_IN_PLACE, &any, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
    MPI_Finalize();
    return any;
}
