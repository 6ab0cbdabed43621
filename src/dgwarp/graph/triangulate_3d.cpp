// 3D stages of build_located_graph with CGAL's Delaunay_triangulation_3
// (the implementation shared with 2D is in triangulate_cgal.hpp).
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Delaunay_triangulation_cell_base_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_cell_base_with_info_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include <string>

#include "dgwarp/core/error.hpp"
#include "dgwarp/graph/triangulate_cgal.hpp"

namespace dgwarp::detail {

namespace {

struct Space {
    static constexpr int dim = 3;
    using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
    using Vb = CGAL::Triangulation_vertex_base_with_info_3<std::int32_t, Kernel>;  // graph vertex id
    using Cb = CGAL::Triangulation_cell_base_with_info_3<std::int32_t, Kernel,     // graph simplex id
                                                         CGAL::Delaunay_triangulation_cell_base_3<Kernel>>;
    using Delaunay = CGAL::Delaunay_triangulation_3<Kernel, CGAL::Triangulation_data_structure_3<Vb, Cb>>;
    using Point = Kernel::Point_3;
    using Handle = Delaunay::Cell_handle;

    static Point point_of(std::span<const double> points, NodeId n) {
        const double* p = points.data() + 3 * static_cast<std::size_t>(n);
        return {p[0], p[1], p[2]};
    }
    static Point point_at(const double* x) { return {x[0], x[1], x[2]}; }
    static bool positive(const Point* p) { return CGAL::orientation(p[0], p[1], p[2], p[3]) == CGAL::POSITIVE; }
    static void check_spans(const Delaunay& dt, std::size_t vertices) {
        if (dt.dimension() < 3)
            throw MeshError("the Delaunay graph needs boundary nodes that span space, but all " +
                            std::to_string(vertices) + " distinct boundary points are " +
                            (dt.dimension() == 2 ? "coplanar" : "collinear"));
    }
    static auto finite_simplices(const Delaunay& dt) { return dt.finite_cell_handles(); }
    static std::size_t finite_simplex_count(const Delaunay& dt) { return dt.number_of_finite_cells(); }
    static Handle locate(const Delaunay& dt, const Point& p, Delaunay::Locate_type& lt, int& li, int& lj,
                         Handle hint) {
        return dt.locate(p, lt, li, lj, hint);
    }
    static bool is_facet(Delaunay::Locate_type lt) { return lt == Delaunay::FACET; }
    static void incident(const Delaunay& dt, Handle s, Delaunay::Locate_type lt, int li, int lj,
                         std::vector<Handle>& out) {
        if (lt == Delaunay::FACET) {
            out.push_back(s);
            out.push_back(s->neighbor(li));
        } else if (lt == Delaunay::EDGE) {
            auto c = dt.incident_cells(s, li, lj), done = c;
            do out.push_back(c); while (++c != done);
        } else {  // VERTEX
            dt.incident_cells(s->vertex(li), std::back_inserter(out));
        }
    }
    static bool sees(const Delaunay& dt, Handle s, const Point& p) {
        const int i = s->index(dt.infinite_vertex());
        const Point* q[4];
        for (int k = 0; k < 4; ++k) q[k] = k == i ? &p : &s->vertex(k)->point();
        return dt.orientation(*q[0], *q[1], *q[2], *q[3]) != CGAL::NEGATIVE;
    }
};

}  // namespace

TriangulationResult triangulate_and_locate_3d(std::span<const double> points,
                                              std::span<const NodeId> vertex_node,
                                              std::span<const NodeId> query_nodes,
                                              const VisitOrderFn& visit_order, const ProgressFn& locate_progress,
                                              const BesideLocateFn& beside_locate) {
    return triangulate_and_locate<Space>(points, vertex_node, query_nodes, visit_order, locate_progress, beside_locate);
}

}  // namespace dgwarp::detail
