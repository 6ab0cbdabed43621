#pragma once
// Internal: the one implementation of triangulate_and_locate_2d/_3d
// (triangulate_detail.hpp), a template over what differs between CGAL's 2D
// and 3D Delaunay triangulations. Included only by triangulate_2d.cpp and
// triangulate_3d.cpp, which define that part (the `Dim` below):
//
//   static constexpr int dim;                  2 or 3
//   using Kernel, Delaunay, Point, Handle;     Handle: a face (2D) or cell (3D) of Delaunay
//   static Point point_of(points, node);       node's coordinates
//   static Point point_at(const double* x);    the point with coordinates x[0..dim)
//   static bool positive(const Point* p);      whether simplex p[0..dim] is positively oriented (exact)
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

#include <algorithm>
#include <bit>
#include <cmath>
#include <memory>
#include <numeric>
#include <utility>
#include <vector>

#include "dgwarp/core/parallel_for.hpp"
#include "dgwarp/core/stopwatch.hpp"
#include "dgwarp/graph/triangulate_detail.hpp"

namespace dgwarp::detail {

// The graph is built on coordinates moved by a tiny deterministic amount
// (issue #13 item 1). Boundary nodes are often exactly cospherical (a sphere's
// nodes), cocircular or on a grid: then nearly every in-sphere test is a tie,
// which CGAL's filtered predicates hand to exact arithmetic, several times
// slower (826k sphere, 40,845 boundary points: 0.58 s against 0.14 s moved).
// Each coordinate moves by at most perturbation_fraction of the points'
// bounding-box diagonal, by an amount hashed from the point's own
// coordinates (so the graph does not depend on the node numbering). Points
// with a coordinate on a face of the bounding box (a box far field, symmetry
// planes) do not move: moving coplanar hull points would make flat simplices.
// Afterwards every simplex is checked with an exact orientation test on the
// original coordinates; the corners of any simplex not positively oriented
// there stop moving and the graph is rebuilt, at worst on the original
// coordinates. So the graph is always a valid triangulation of the original
// points, and its simplices' circumspheres hold no original point except
// within that tolerance (ties and near-ties are broken by the perturbation).
// In 2D the graph is built on the original coordinates: a 2D boundary has a
// few thousand nodes at most and its graph costs milliseconds, and CGAL's own
// tie-breaking (symbolic perturbation) is kept there.
inline constexpr double perturbation_fraction = 0x1p-40;  // about 9.1e-13
inline constexpr int perturbation_rounds = 3;            // the last on the original coordinates

// A number in [-1, 1) from the bits of a point's coordinates and an axis.
inline double perturbation_unit(const double* x, int dim, int axis) {
    std::uint64_t h = 0x9E3779B97F4A7C15ull * static_cast<std::uint64_t>(axis + 1);
    for (int d = 0; d < dim; ++d) {
        h ^= std::bit_cast<std::uint64_t>(x[d] == 0 ? 0.0 : x[d]) + 0x9E3779B97F4A7C15ull + (h << 6) + (h >> 2);
        h ^= h >> 30;
        h *= 0xBF58476D1CE4E5B9ull;
        h ^= h >> 27;
        h *= 0x94D049BB133111EBull;
        h ^= h >> 31;
    }
    return static_cast<double>(h >> 11) * 0x1p-52 - 1.0;
}

// The Delaunay triangulation of the points vertex_node[v] (info v), built as
// described above. `builds`: how many builds it took (1 when the first passed;
// always 1 in 2D).
template <class Dim>
std::unique_ptr<typename Dim::Delaunay> build_delaunay(std::span<const double> points,
                                                       std::span<const NodeId> vertex_node, int& builds) {
    using Delaunay = typename Dim::Delaunay;
    using Point = typename Dim::Point;
    constexpr int dim = Dim::dim;
    const std::size_t n = vertex_node.size();
    auto coords = [&](std::size_t v) { return points.data() + static_cast<std::size_t>(vertex_node[v]) * dim; };
    const BoundingBox box = bounding_box(dim, points, vertex_node);
    const double* lo = box.min.data();
    const double* hi = box.max.data();
    double diagonal2 = 0;
    for (int d = 0; d < dim; ++d) diagonal2 += (hi[d] - lo[d]) * (hi[d] - lo[d]);
    const double amplitude = perturbation_fraction * std::sqrt(diagonal2);
    std::vector<std::uint8_t> fixed(n, 0);
    for (std::size_t v = 0; v < n; ++v)
        for (int d = 0; d < dim; ++d) fixed[v] |= coords(v)[d] == lo[d] || coords(v)[d] == hi[d];

    std::vector<std::pair<Point, std::int32_t>> vertices(n);
    builds = 0;
    for (int round = dim == 3 ? 1 : perturbation_rounds;; ++round) {
        const bool last = round == perturbation_rounds;
        ++builds;
        for (std::size_t v = 0; v < n; ++v) {
            const double* x = coords(v);
            double y[3];
            for (int d = 0; d < dim; ++d)
                y[d] = last || fixed[v] ? x[d] : x[d] + amplitude * perturbation_unit(x, dim, d);
            vertices[v] = {Dim::point_at(y), static_cast<std::int32_t>(v)};
        }
        // Range insertion with info: CGAL sorts spatially before inserting.
        auto dt = std::make_unique<Delaunay>(vertices.begin(), vertices.end());
        if (last) return dt;
        if (dt->number_of_vertices() != n) {  // two points moved onto each other
            std::fill(fixed.begin(), fixed.end(), std::uint8_t{1});
            continue;
        }
        bool valid = dt->dimension() == dim;  // else coplanar / collinear points were moved apart
        if (valid)
            for (const auto s : Dim::finite_simplices(*dt)) {
                Point p[dim + 1];
                for (int k = 0; k <= dim; ++k) p[k] = Dim::point_at(coords(static_cast<std::size_t>(s->vertex(k)->info())));
                if (Dim::positive(p)) continue;
                valid = false;
                for (int k = 0; k <= dim; ++k) fixed[static_cast<std::size_t>(s->vertex(k)->info())] = 1;
            }
        if (valid) return dt;
        if (dt->dimension() != dim) std::fill(fixed.begin(), fixed.end(), std::uint8_t{1});
    }
}

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
                                           std::span<const NodeId> query_nodes,
                                           std::span<const std::uint32_t> visit_order,
                                           const ProgressFn& locate_progress) {
    using Delaunay = typename Dim::Delaunay;
    using Point = typename Dim::Point;
    using Handle = typename Dim::Handle;
    constexpr int corners = Dim::dim + 1;
    TriangulationResult result;
    auto t0 = Clock::now();

    int builds = 0;
    const std::unique_ptr<Delaunay> triangulation = build_delaunay<Dim>(points, vertex_node, builds);
    const Delaunay& dt = *triangulation;
    Dim::check_spans(dt, vertex_node.size());
    result.timings.triangulation_builds = builds;

    result.simplices.reserve(corners * Dim::finite_simplex_count(dt));
    std::int32_t next = 0;
    for (const Handle s : Dim::finite_simplices(dt)) {
        s->info() = next++;
        for (int k = 0; k < corners; ++k) result.simplices.push_back(s->vertex(k)->info());
    }
    result.timings.triangulate_seconds = seconds_since(t0);

    t0 = Clock::now();
    std::vector<std::uint32_t> given;
    if (visit_order.empty()) {
        given.resize(query_nodes.size());
        std::iota(given.begin(), given.end(), std::uint32_t{0});
    }
    const std::span<const std::uint32_t> order = visit_order.empty() ? std::span<const std::uint32_t>(given) : visit_order;
    // The query points in visiting order: the walks then read them in sequence.
    std::vector<Point> query(order.size());
    parallel_for(static_cast<std::int64_t>(order.size()),
                 [&](std::int64_t j) { query[j] = Dim::point_of(points, query_nodes[order[j]]); });
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
            typename Delaunay::Locate_type lt;
            int li = 0, lj = 0;
            const Handle s = Dim::locate(dt, query[j], lt, li, lj, hint);
            if (lt == Delaunay::OUTSIDE_CONVEX_HULL) ++outside[b];
            // Outside the hull (or on its boundary): a finite simplex across the hull's face.
            result.location.simplex[order[j]] = canonical_simplex<Dim>(dt, query[j], s, lt, li, lj, scratch, seen)->info();
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
