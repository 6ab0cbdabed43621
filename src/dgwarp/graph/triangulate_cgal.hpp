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
//   static Handle locate(dt, point, lt, hint); the simplex holding point (may be infinite), its locate type
#include <CGAL/hilbert_sort.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <numeric>
#include <utility>

#include "dgwarp/core/parallel_for.hpp"
#include "dgwarp/core/stopwatch.hpp"
#include "dgwarp/graph/triangulate_detail.hpp"

namespace dgwarp::detail {

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
        const std::int64_t end = std::min(n, (b + 1) * locate_block_size);
        for (std::int64_t j = b * locate_block_size; j < end; ++j) {
            const std::size_t q = order[j];
            typename Delaunay::Locate_type lt;
            Handle s = Dim::locate(dt, query[q], lt, hint);
            if (dt.is_infinite(s)) {
                // Outside the hull (or on its boundary): the finite simplex across the hull's face.
                if (lt == Delaunay::OUTSIDE_CONVEX_HULL) ++outside[b];
                s = s->neighbor(s->index(dt.infinite_vertex()));
            }
            result.location.simplex[q] = s->info();
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
