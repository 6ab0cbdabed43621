// 2D stages of build_located_graph with CGAL's Delaunay_triangulation_2
// (the implementation shared with 3D is in triangulate_cgal.hpp).
#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <string>

#include "dgwarp/core/error.hpp"
#include "dgwarp/graph/triangulate_cgal.hpp"

namespace dgwarp::detail {

namespace {

struct Plane {
    static constexpr int dim = 2;
    using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
    using Vb = CGAL::Triangulation_vertex_base_with_info_2<std::int32_t, Kernel>;  // graph vertex id
    using Fb = CGAL::Triangulation_face_base_with_info_2<std::int32_t, Kernel>;    // graph simplex id
    using Delaunay = CGAL::Delaunay_triangulation_2<Kernel, CGAL::Triangulation_data_structure_2<Vb, Fb>>;
    using Point = Kernel::Point_2;
    using Handle = Delaunay::Face_handle;

    static Point point_of(std::span<const double> points, NodeId n) {
        return {points[2 * static_cast<std::size_t>(n)], points[2 * static_cast<std::size_t>(n) + 1]};
    }
    static Point point_at(const double* x) { return {x[0], x[1]}; }
    static bool positive(const Point* p) { return CGAL::orientation(p[0], p[1], p[2]) == CGAL::POSITIVE; }
    static void check_spans(const Delaunay& dt, std::size_t vertices) {
        if (dt.dimension() < 2)
            throw MeshError("the Delaunay graph needs boundary nodes that span the plane, but all " +
                            std::to_string(vertices) + " distinct boundary points are collinear");
    }
    static auto finite_simplices(const Delaunay& dt) { return dt.finite_face_handles(); }
    static std::size_t finite_simplex_count(const Delaunay& dt) { return dt.number_of_faces(); }
    static Handle locate(const Delaunay& dt, const Point& p, Delaunay::Locate_type& lt, int& li, int&, Handle hint) {
        return dt.locate(p, lt, li, hint);
    }
    static bool is_facet(Delaunay::Locate_type) { return false; }  // 2D: an edge is the facet
    static void incident(const Delaunay& dt, Handle s, Delaunay::Locate_type lt, int li, int,
                         std::vector<Handle>& out) {
        if (lt == Delaunay::EDGE) {
            out.push_back(s);
            out.push_back(s->neighbor(li));
            return;
        }
        auto f = dt.incident_faces(s->vertex(li)), done = f;  // VERTEX
        do out.push_back(f); while (++f != done);
    }
    static bool sees(const Delaunay& dt, Handle s, const Point& p) {
        const int i = s->index(dt.infinite_vertex());
        return dt.orientation(p, s->vertex(Delaunay::ccw(i))->point(), s->vertex(Delaunay::cw(i))->point()) !=
               CGAL::NEGATIVE;
    }
};

}  // namespace

TriangulationResult triangulate_and_locate_2d(std::span<const double> points,
                                              std::span<const NodeId> vertex_node,
                                              std::span<const NodeId> query_nodes,
                                              const VisitOrderFn& visit_order, const ProgressFn& locate_progress,
                                              const BesideLocateFn& beside_locate) {
    return triangulate_and_locate<Plane>(points, vertex_node, query_nodes, visit_order, locate_progress, beside_locate);
}

}  // namespace dgwarp::detail
