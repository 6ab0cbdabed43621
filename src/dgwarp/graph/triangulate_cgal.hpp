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

// A Delaunay triangulation and its finite simplices, numbered.
template <class Dim>
struct NumberedDelaunay {
    std::unique_ptr<typename Dim::Delaunay> dt;
    std::vector<std::int32_t> simplices;  // finite simplex s (info s) × (dim + 1): its vertices' infos
    int builds = 0;                       // how many builds it took (1 when the first passed; always 1 in 2D)
};

// Numbers dt's finite simplices (info) in CGAL's order and lists their vertices.
template <class Dim>
std::vector<std::int32_t> number_simplices(typename Dim::Delaunay& dt) {
    constexpr int corners = Dim::dim + 1;
    std::vector<std::int32_t> simplices;
    simplices.reserve(corners * Dim::finite_simplex_count(dt));
    std::int32_t next = 0;
    for (const auto s : Dim::finite_simplices(dt)) {
        s->info() = next++;
        for (int k = 0; k < corners; ++k) simplices.push_back(s->vertex(k)->info());
    }
    return simplices;
}

// The Delaunay triangulation of the points vertex_node[v] (info v), built as
// described above, with its simplices numbered: round after round, each
// build() followed by check() until one passes (the last round, on the
// original coordinates, needs no check). Split in two so that the serial
// build can run beside other work and the check then in parallel.
template <class Dim>
class DelaunayBuild {
public:
    using Delaunay = typename Dim::Delaunay;
    using Point = typename Dim::Point;
    static constexpr int dim = Dim::dim;
    static constexpr int corners = dim + 1;

    DelaunayBuild(std::span<const double> points, std::span<const NodeId> vertex_node)
        : points_(points), vertex_node_(vertex_node), fixed_(vertex_node.size(), 0), vertices_(vertex_node.size()) {
        const BoundingBox box = bounding_box(dim, points, vertex_node);
        double diagonal2 = 0;
        for (int d = 0; d < dim; ++d) diagonal2 += (box.max[d] - box.min[d]) * (box.max[d] - box.min[d]);
        amplitude_ = perturbation_fraction * std::sqrt(diagonal2);
        for (std::size_t v = 0; v < fixed_.size(); ++v)
            for (int d = 0; d < dim; ++d) fixed_[v] |= coords(v)[d] == box.min[d] || coords(v)[d] == box.max[d];
    }

    /// The next round's triangulation, numbered, into `out`. False when it must
    /// be built again at once (points moved onto each other or off their
    /// common plane / line: every point then stays put).
    bool build(NumberedDelaunay<Dim>& out) {
        ++round_;
        ++out.builds;
        const std::size_t n = vertex_node_.size();
        for (std::size_t v = 0; v < n; ++v) {
            const double* x = coords(v);
            double y[3];
            for (int d = 0; d < dim; ++d)
                y[d] = last() || fixed_[v] ? x[d] : x[d] + amplitude_ * perturbation_unit(x, dim, d);
            vertices_[v] = {Dim::point_at(y), static_cast<std::int32_t>(v)};
        }
        // Range insertion with info: CGAL sorts spatially before inserting.
        out.dt = std::make_unique<Delaunay>(vertices_.begin(), vertices_.end());
        out.simplices.clear();
        if (!last() && (out.dt->number_of_vertices() != n || out.dt->dimension() != dim)) {
            std::fill(fixed_.begin(), fixed_.end(), std::uint8_t{1});
            return false;
        }
        if (out.dt->dimension() == dim) out.simplices = number_simplices<Dim>(*out.dt);
        return true;
    }

    /// Whether `out` (from build) is the answer: the last round's always is;
    /// others when every simplex is positively oriented on the original
    /// coordinates (exact test, in parallel). Otherwise the corners of the
    /// inverted ones stay put in the next round.
    bool check(const NumberedDelaunay<Dim>& out) {
        if (last()) return true;
        const auto count = static_cast<std::int64_t>(out.simplices.size() / corners);
        std::vector<std::uint8_t> inverted(static_cast<std::size_t>(count), 0);
        parallel_for(count, [&](std::int64_t s) {
            Point p[corners];
            for (int k = 0; k < corners; ++k)
                p[k] = Dim::point_at(coords(static_cast<std::size_t>(out.simplices[s * corners + k])));
            inverted[s] = !Dim::positive(p);
        });
        bool valid = true;
        for (std::int64_t s = 0; s < count; ++s) {
            if (!inverted[s]) continue;
            valid = false;
            for (int k = 0; k < corners; ++k) fixed_[static_cast<std::size_t>(out.simplices[s * corners + k])] = 1;
        }
        return valid;
    }

    /// Builds and checks until a round passes.
    void finish(NumberedDelaunay<Dim>& out, bool built) {
        while (!(built && check(out))) built = build(out);
    }

private:
    const double* coords(std::size_t v) const {
        return points_.data() + static_cast<std::size_t>(vertex_node_[v]) * dim;
    }
    bool last() const { return round_ >= perturbation_rounds; }

    std::span<const double> points_;
    std::span<const NodeId> vertex_node_;
    std::vector<std::uint8_t> fixed_;
    std::vector<std::pair<Point, std::int32_t>> vertices_;
    double amplitude_ = 0;
    int round_ = dim == 3 ? 0 : perturbation_rounds - 1;  // 2D: only the last round
};

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
                                           const VisitOrderFn& visit_order,
                                           const ProgressFn& locate_progress, const BesideLocateFn& beside_locate) {
    using Delaunay = typename Dim::Delaunay;
    using Point = typename Dim::Point;
    using Handle = typename Dim::Handle;
    TriangulationResult result;
    // The triangulation is built on one thread (CGAL's sequential insertion);
    // beside it, the visiting order is computed and the query points gathered
    // in that order (the walks then read them in sequence).
    const auto t0 = Clock::now();
    DelaunayBuild<Dim> builder(points, vertex_node);
    NumberedDelaunay<Dim> built;
    bool first_built = false;
    double build_seconds = 0;
    std::vector<std::uint32_t> given;
    std::span<const std::uint32_t> order;
    std::vector<Point> query;
    run_concurrently(
        [&] {
            const auto t = Clock::now();
            first_built = builder.build(built);
            build_seconds = seconds_since(t);
        },
        [&] {
            order = visit_order();
            if (order.empty()) {
                given.resize(query_nodes.size());
                std::iota(given.begin(), given.end(), std::uint32_t{0});
                order = given;
            }
            query.resize(order.size());
            parallel_for(static_cast<std::int64_t>(order.size()),
                         [&](std::int64_t j) { query[j] = Dim::point_of(points, query_nodes[order[j]]); });
        });
    // The part of the concurrent stage the build did not cover counts as location.
    const double beside_seconds = std::max(0.0, seconds_since(t0) - build_seconds);
    const auto t_check = Clock::now();
    builder.finish(built, first_built);  // the check (in parallel), and further rounds if it fails
    build_seconds += seconds_since(t_check);
    const Delaunay& dt = *built.dt;
    Dim::check_spans(dt, vertex_node.size());
    result.timings.triangulation_builds = built.builds;
    result.simplices = std::move(built.simplices);
    result.timings.triangulate_seconds = build_seconds;

    const auto t1 = Clock::now();
    result.location.simplex.assign(query.size(), -1);
    const auto n = static_cast<std::int64_t>(order.size());
    const std::int64_t blocks = (n + locate_block_size - 1) / locate_block_size;
    std::vector<std::int64_t> outside(static_cast<std::size_t>(blocks), 0);
    ProgressCounter located(locate_progress, n);
    const auto locate = [&] { parallel_for(blocks, [&](std::int64_t b) {
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
    }, 1); };  // each index is a block of thousands of walks: always worth a thread
    double locate_seconds = 0;  // the location's own: not the wait for beside_locate
    const auto timed_locate = [&] {
        locate();
        locate_seconds = seconds_since(t1);
    };
    // The caller's work (DG-harmonic's factorisation: serial) on this thread,
    // the location beside it on a thread of its own: on two cores, one each.
    if (beside_locate)
        run_beside([&] { beside_locate(result.simplices); }, timed_locate);
    else
        timed_locate();
    located.finish();
    result.location.outside_count = std::accumulate(outside.begin(), outside.end(), std::int64_t{0});
    result.timings.locate_seconds = beside_seconds + locate_seconds;
    return result;
}

}  // namespace dgwarp::detail
