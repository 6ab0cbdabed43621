// 3D stages of build_located_graph with CGAL's Delaunay_triangulation_3.
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Delaunay_triangulation_cell_base_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Spatial_sort_traits_adapter_3.h>
#include <CGAL/Triangulation_cell_base_with_info_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>
#include <CGAL/hilbert_sort.h>
#include <CGAL/property_map.h>

#include <numeric>

#include "dgwarp/core/error.hpp"
#include "dgwarp/core/parallel_for.hpp"
#include "dgwarp/core/stopwatch.hpp"
#include "dgwarp/graph/triangulate_detail.hpp"

namespace dgwarp::detail {

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vb = CGAL::Triangulation_vertex_base_with_info_3<std::int32_t, K>;  // graph vertex id
using Cb = CGAL::Triangulation_cell_base_with_info_3<std::int32_t, K,    // graph simplex id
                                                     CGAL::Delaunay_triangulation_cell_base_3<K>>;
using Tds = CGAL::Triangulation_data_structure_3<Vb, Cb>;
using Delaunay = CGAL::Delaunay_triangulation_3<K, Tds>;
using Point = K::Point_3;

Point point_of(std::span<const double> points, NodeId n) {
    const double* p = points.data() + 3 * static_cast<std::size_t>(n);
    return {p[0], p[1], p[2]};
}

}  // namespace

TriangulationResult triangulate_and_locate_3d(std::span<const double> points,
                                              std::span<const NodeId> vertex_node,
                                              std::span<const NodeId> query_nodes,
                                              bool hilbert_order, const ProgressFn& locate_progress) {
    TriangulationResult result;
    auto t0 = Clock::now();

    std::vector<std::pair<Point, std::int32_t>> vertices(vertex_node.size());
    for (std::size_t v = 0; v < vertex_node.size(); ++v)
        vertices[v] = {point_of(points, vertex_node[v]), static_cast<std::int32_t>(v)};
    // Range insertion with info: CGAL sorts spatially before inserting.
    const Delaunay dt(vertices.begin(), vertices.end());
    if (dt.dimension() < 3)
        throw MeshError("the Delaunay graph needs boundary nodes that span space, but all " +
                        std::to_string(vertex_node.size()) + " distinct boundary points are " +
                        (dt.dimension() == 2 ? "coplanar" : "collinear"));

    result.simplices.reserve(4 * static_cast<std::size_t>(dt.number_of_finite_cells()));
    std::int32_t next = 0;
    for (auto c = dt.finite_cells_begin(); c != dt.finite_cells_end(); ++c) {
        c->info() = next++;
        for (int k = 0; k < 4; ++k) result.simplices.push_back(c->vertex(k)->info());
    }
    result.timings.triangulate_seconds = seconds_since(t0);

    t0 = Clock::now();
    std::vector<Point> query(query_nodes.size());
    for (std::size_t i = 0; i < query.size(); ++i) query[i] = point_of(points, query_nodes[i]);
    std::vector<std::size_t> order(query.size());  // the property map's key type
    std::iota(order.begin(), order.end(), std::size_t{0});
    if (hilbert_order) {
        using Traits = CGAL::Spatial_sort_traits_adapter_3<K, CGAL::Pointer_property_map<Point>::type>;
        CGAL::hilbert_sort(order.begin(), order.end(), Traits(CGAL::make_property_map(query)),
                           CGAL::Hilbert_sort_median_policy());
    }
    result.location.simplex.assign(query.size(), -1);
    const auto n = static_cast<std::int64_t>(order.size());
    const std::int64_t blocks = (n + locate_block_size - 1) / locate_block_size;
    std::vector<std::int64_t> outside(static_cast<std::size_t>(blocks), 0);
    ProgressCounter located(locate_progress, n);
    parallel_for(blocks, [&](std::int64_t b) {
        Delaunay::Cell_handle hint;
        const std::int64_t end = std::min(n, (b + 1) * locate_block_size);
        for (std::int64_t j = b * locate_block_size; j < end; ++j) {
            const std::size_t q = order[j];
            Delaunay::Locate_type lt;
            int li, lj;
            Delaunay::Cell_handle c = dt.locate(query[q], lt, li, lj, hint);
            if (dt.is_infinite(c)) {
                // Outside the hull (or on a hull facet): the finite cell across the hull facet.
                if (lt == Delaunay::OUTSIDE_CONVEX_HULL) ++outside[b];
                c = c->neighbor(c->index(dt.infinite_vertex()));
            }
            result.location.simplex[q] = c->info();
            hint = c;
        }
        located.add(end - b * locate_block_size);
    }, 1);  // each index is a block of thousands of walks: always worth a thread
    located.finish();
    result.location.outside_count = std::accumulate(outside.begin(), outside.end(), std::int64_t{0});
    result.timings.locate_seconds = seconds_since(t0);
    return result;
}

}  // namespace dgwarp::detail
