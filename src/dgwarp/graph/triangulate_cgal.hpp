#pragma once
// Internal: the one implementation of triangulate_and_locate_2d/_3d
// (triangulate_detail.hpp), a template over what differs between CGAL's 2D
// and 3D Delaunay triangulations. Included only by triangulate_2d.cpp and
// triangulate_3d.cpp, which define that part (the `Dim` below):
//
//   static constexpr int dim;                  2 or 3
//   using Kernel, Delaunay, Point, Handle;     Handle: a face (2D) or cell (3D) of Delaunay
//   using SortTraits;                          CGAL::Spatial_sort_traits_adapter_<dim> over a Point array
//   static Point point_of(points, node);       node's coordinates
//   static void check_spans(dt, vertices);     throws MeshError when dt has fewer than dim dimensions
//   static auto finite_simplices(dt);          its finite faces / cells, as handles
//   static std::size_t finite_simplex_count(dt);
//   static Handle locate(dt, point, lt, li, lj, hint); the simplex holding point (may be infinite), its locate
//                                              type and CGAL's indices of the vertex / edge / facet it is on
//   static void incident(dt, s, lt, li, lj, out); every simplex (finite or not) holding the vertex, edge or
//                                              facet `point` was located on (lt VERTEX, EDGE, FACET)
//   static bool sees(dt, s, point);            for an infinite simplex s: whether point is on the outer side
//                                              of (or on the plane of) its hull facet
//
// Location is independent of the order of the queries: a walk's result
// depends on where it starts (the previous query's simplex), so a node on a
// graph face, edge or vertex, or outside the hull, gets the lowest-numbered
// finite simplex among all that hold it (that it sees across the hull),
// not the one the walk reached first. The distributed prepare (dgwarp/mpi)
// locates each process's own nodes and relies on this to give every node the
// simplex, and so the bits, of the single-process run.
#include <CGAL/hilbert_sort.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <numeric>
#include <utility>
#include <vector>

#include "dgwarp/core/parallel_for.hpp"
#include "dgwarp/core/stopwatch.hpp"
#include "dgwarp/graph/triangulate_detail.hpp"

namespace dgwarp::detail {

// The order-independent simplex of a query (see the file comment): `s`, lt,
// li, lj as the walk found them. `scratch` and `seen` are reused buffers.
template <class Dim>
typename Dim::Handle canonical_simplex(const typename Dim::Delaunay& dt, const typename Dim::Point& p,
                                       typename Dim::Handle s, typename Dim::Delaunay::Locate_type lt, int li,
                                       int lj, std::vector<typename Dim::Handle>& scratch,
                                       std::vector<typename Dim::Handle>& seen) {
    using Delaunay = typename Dim::Delaunay;
    using Handle = typename Dim::Handle;
    if (lt == Delaunay::OUTSIDE_CONVEX_HULL) {
        // Every infinite simplex whose hull facet the node sees: they form a
        // connected patch around the walk's one; the lowest-numbered finite
        // simplex behind them.
        seen.assign(1, s);
        Handle best = s->neighbor(s->index(dt.infinite_vertex()));
        for (std::size_t i = 0; i < seen.size(); ++i) {
            const Handle c = seen[i];
            for (int k = 0; k <= Dim::dim; ++k) {
                const Handle n = c->neighbor(k);
                if (!dt.is_infinite(n) || std::find(seen.begin(), seen.end(), n) != seen.end()) continue;
                if (!Dim::sees(dt, n, p)) continue;
                seen.push_back(n);
                const Handle f = n->neighbor(n->index(dt.infinite_vertex()));
                if (f->info() < best->info()) best = f;
            }
        }
        return best;
    }
    if (lt != Delaunay::VERTEX && lt != Delaunay::EDGE && !Dim::is_facet(lt)) {
        if (dt.is_infinite(s)) s = s->neighbor(s->index(dt.infinite_vertex()));
        return s;
    }
    scratch.clear();
    Dim::incident(dt, s, lt, li, lj, scratch);
    Handle best{};
    for (const Handle c : scratch)
        if (!dt.is_infinite(c) && (best == Handle{} || c->info() < best->info())) best = c;
    return best;
}

template <class Dim>
TriangulationResult triangulate_and_locate(std::span<const double> points, std::span<const NodeId> vertex_node,
                                           std::span<const NodeId> query_nodes, bool hilbert_order,
                                           const ProgressFn& locate_progress) {
    using Delaunay = typename Dim::Delaunay;
    using Point = typename Dim::Point;
    using Handle = typename Dim::Handle;
    constexpr int corners = Dim::dim + 1;
    TriangulationResult result;
    auto t0 = Clock::now();

    std::vector<std::pair<Point, std::int32_t>> vertices(vertex_node.size());
    for (std::size_t v = 0; v < vertex_node.size(); ++v)
        vertices[v] = {Dim::point_of(points, vertex_node[v]), static_cast<std::int32_t>(v)};
    // Range insertion with info: CGAL sorts spatially before inserting.
    const Delaunay dt(vertices.begin(), vertices.end());
    Dim::check_spans(dt, vertex_node.size());

    result.simplices.reserve(corners * Dim::finite_simplex_count(dt));
    std::int32_t next = 0;
    for (const Handle s : Dim::finite_simplices(dt)) {
        s->info() = next++;
        for (int k = 0; k < corners; ++k) result.simplices.push_back(s->vertex(k)->info());
    }
    result.timings.triangulate_seconds = seconds_since(t0);

    t0 = Clock::now();
    std::vector<Point> query(query_nodes.size());
    for (std::size_t i = 0; i < query.size(); ++i) query[i] = Dim::point_of(points, query_nodes[i]);
    std::vector<std::size_t> order(query.size());  // the property map's key type
    std::iota(order.begin(), order.end(), std::size_t{0});
    if (hilbert_order) {
        using Traits = typename Dim::SortTraits;
        CGAL::hilbert_sort(order.begin(), order.end(), Traits(CGAL::make_property_map(query)),
                           CGAL::Hilbert_sort_median_policy());
    }
    result.location.simplex.assign(query.size(), -1);
    const auto n = static_cast<std::int64_t>(order.size());
    const std::int64_t blocks = (n + locate_block_size - 1) / locate_block_size;
    std::vector<std::int64_t> outside(static_cast<std::size_t>(blocks), 0);
    ProgressCounter located(locate_progress, n);
    parallel_for(blocks, [&](std::int64_t b) {
        Handle hint;
        std::vector<Handle> scratch, seen;
        const std::int64_t end = std::min(n, (b + 1) * locate_block_size);
        for (std::int64_t j = b * locate_block_size; j < end; ++j) {
            const std::size_t q = order[j];
            typename Delaunay::Locate_type lt;
            int li = 0, lj = 0;
            const Handle s = Dim::locate(dt, query[q], lt, li, lj, hint);
            if (lt == Delaunay::OUTSIDE_CONVEX_HULL) ++outside[b];
            // Outside the hull (or on its boundary): a finite simplex across the hull's face.
            result.location.simplex[q] = canonical_simplex<Dim>(dt, query[q], s, lt, li, lj, scratch, seen)->info();
            hint = s;
        }
        located.add(end - b * locate_block_size);
    }, 1);  // each index is a block of thousands of walks: always worth a thread
    located.finish();
    result.location.outside_count = std::accumulate(outside.begin(), outside.end(), std::int64_t{0});
    result.timings.locate_seconds = seconds_since(t0);
    return result;
}

}  // namespace dgwarp::detail
