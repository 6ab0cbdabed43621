#pragma once
// The Delaunay graph of DG-IDW and DGM: the Delaunay triangulation (2D) or
// tetrahedralisation (3D) of the boundary nodes in their original positions,
// and the graph simplex that holds each volume node (METHODS.md, "DG-IDW",
// prepare steps 1 and 2). Plain data out; CGAL stays inside the .cpp files.
//
// What "Delaunay" guarantees (3D; in 2D the graph is built on the original
// coordinates, CGAL's exact predicates breaking ties): the graph is built on the boundary points each
// moved by less than 1e-12 of their bounding-box diagonal (by an amount
// hashed from the point's coordinates; points on a face of the bounding box
// do not move), so that exactly cospherical, cocircular or grid-aligned
// points (a sphere's nodes, a structured wall) need no exact arithmetic; see
// graph/triangulate_cgal.hpp. Every simplex is positively oriented in the
// original coordinates (checked exactly; the graph is rebuilt with fewer
// points moved, at worst none, when a check fails), and no original point
// lies inside a simplex's circumsphere by more than that tolerance: the graph
// is a Delaunay triangulation of the original points up to ties, which the
// perturbation breaks. Volume nodes are located at their original coordinates,
// and every weight uses the original coordinates.
//
// Indices: a "boundary index" b is a position in the boundary node list
// given to build_located_graph (BoundarySet order); a graph vertex v stands
// for one or more boundary indices with identical coordinates.
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "dgwarp/core/progress.hpp"
#include "dgwarp/mesh/mesh.hpp"

namespace dgwarp {

struct DelaunayGraph {
    int dim = 3;
    /// Graph vertex v stands for boundary indices
    /// vertex_nodes[vertex_offsets[v] .. vertex_offsets[v+1]), ascending; more
    /// than one when boundary nodes share coordinates. Vertices are numbered in
    /// the order of their smallest boundary index.
    std::vector<std::int32_t> vertex_offsets{0};  // num_vertices() + 1
    std::vector<std::int32_t> vertex_nodes;       // one entry per boundary index
    /// num_simplices() × (dim + 1) graph vertex ids, positively oriented.
    std::vector<std::int32_t> simplices;

    std::size_t num_vertices() const { return vertex_offsets.size() - 1; }
    std::size_t num_simplices() const { return simplices.size() / static_cast<std::size_t>(dim + 1); }
};

/// Where each query node lies in the graph.
struct GraphLocation {
    /// Per query node (in the order given), the graph simplex holding it. A
    /// node outside the graph's convex hull gets the finite simplex across the
    /// hull facet (edge in 2D) that CGAL's walk stopped at: the hull simplex
    /// whose outer facet faces the node.
    std::vector<std::int32_t> simplex;
    std::int64_t outside_count = 0;  // query nodes outside the convex hull
};

/// Wall-clock seconds of the two stages (for benchmarks and logs).
struct GraphTimings {
    double triangulate_seconds = 0;  // deduplication + Delaunay insertion + tables
    double locate_seconds = 0;       // ordering + point location
    bool spatially_sorted = false;   // whether the queries were sorted along a Morton curve
    int triangulation_builds = 0;    // 3D: 1 when the graph on perturbed coordinates passed its check (see above), up to 3; 2D: 1
};

struct LocatedGraph {
    DelaunayGraph graph;
    GraphLocation location;
    GraphTimings timings;
};

/// The order in which query nodes are located. Each walk starts from the
/// previous node's simplex, so a spatially coherent order keeps walks short.
enum class LocateOrder {
    automatic,  // the given order when it is coherent (see is_coherent_order), else Morton
    morton,     // along a Morton (Z-order) curve (morton_order.hpp: a radix sort, about a
                // quarter of the time of CGAL's Hilbert sort for walks as short)
    given,      // the order of query_nodes
};

struct GraphOptions {
    LocateOrder order = LocateOrder::automatic;
    /// morton_order(dim, points, query_nodes), when the caller has it already
    /// (DG-harmonic's coarse-point selection visits the volume nodes in that
    /// order too): used instead of sorting again when the order is Morton.
    /// Ignored unless it has one entry per query node.
    std::span<const std::uint32_t> morton = {};
    /// Work of the caller's that does not need the graph (allocating its
    /// per-node arrays, hashing the mesh): run beside the triangulation's
    /// build, which is serial, on a second thread when there is one
    /// (run_concurrently), on the thread that then computes the visiting
    /// order; its time counts in GraphTimings::locate_seconds when it
    /// outlasts the build. Must not call progress.
    std::function<void()> beside_build = {};
    /// Work of the caller's that needs the graph but not the location
    /// (DG-harmonic's coarse factorisation): called with the whole graph on
    /// the calling thread, with every thread for its loops, while the
    /// location runs beside it on a thread of its own (run_beside: with one
    /// thread, this work first). Must not call progress.
    std::function<void(const DelaunayGraph&)> beside_locate = {};
};

/// Whether visiting `nodes` (ids into `points`, num_points × dim) in the
/// given order is spatially coherent: the mean distance between consecutive
/// nodes is at most 4 times the typical spacing (bounding-box volume / count)^(1/dim).
/// Mesh generators' node orders usually are (Gmsh's HXT: about 1.5); a random
/// order is not (about 0.5 n^(1/dim)). Empty and single-node lists are coherent.
bool is_coherent_order(int dim, std::span<const double> points, std::span<const NodeId> nodes);

/// Builds the Delaunay graph of the boundary nodes and locates the query nodes in it.
///  dim:            2 or 3
///  points:         num_points × dim mesh coordinates, row-major
///  boundary_nodes: node ids of the graph's points (any order; index b of this
///                  list is "boundary index" b)
///  query_nodes:    node ids to locate (usually the volume nodes)
/// Throws MeshError when a node id is out of range, when there are fewer than
/// dim + 1 distinct boundary points, or when they are all collinear (2D) /
/// coplanar (3D), so that no graph simplex exists.
///  progress:       gets the fraction done (core/progress.hpp): the
///                  triangulation counts for the first graph_progress_share,
///                  then each located block of 8192 nodes.
LocatedGraph build_located_graph(int dim, std::span<const double> points,
                                 std::span<const NodeId> boundary_nodes,
                                 std::span<const NodeId> query_nodes,
                                 const GraphOptions& options = {}, const ProgressFn& progress = {});

/// The part of build_located_graph's progress given to the triangulation
/// (about its share of the time on large meshes; the rest is locating).
inline constexpr double graph_progress_share = 0.4;

}  // namespace dgwarp
