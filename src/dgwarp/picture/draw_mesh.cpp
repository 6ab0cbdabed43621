// The mesh part of a picture: cell fills, cell edges, marker lines.
#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <cstdint>
#include <vector>

#include "dgwarp/picture/cairo_handles.hpp"
#include "dgwarp/picture/picture_parts.hpp"

namespace dgwarp::picture_detail {

namespace {

using Point = std::array<double, 2>;

struct Box {
    double x0, x1, y0, y1;
};

// A cell's outline in pixels: at most 4 nodes, and clipping a polygon to a box
// multiplies its vertex count by at most 1.5 per side (4 -> 19 for a bow-tie).
struct Polygon {
    std::vector<Point> p;  // any number: a polygon cell's, clipped
    int n = 0;
    void push(const Point& q) {
        p.push_back(q);
        ++n;
    }
};

// Sutherland–Hodgman clipping of `poly` to `box`.
Polygon clip_polygon(const Polygon& poly, const Box& box) {
    Polygon cur = poly;
    for (int side = 0; side < 4 && cur.n > 0; ++side) {
        const int axis = side / 2;
        const double bound = std::array{box.x0, box.x1, box.y0, box.y1}[side];
        auto inside = [&](const Point& q) { return side % 2 == 0 ? q[axis] >= bound : q[axis] <= bound; };
        Polygon next;
        for (int i = 0; i < cur.n; ++i) {
            const Point& a = cur.p[i];
            const Point& b = cur.p[(i + 1) % cur.n];
            const bool in_a = inside(a), in_b = inside(b);
            if (in_a) next.push(a);
            if (in_a != in_b) {
                const double t = (bound - a[axis]) / (b[axis] - a[axis]);
                next.push({a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])});
            }
        }
        cur = next;
    }
    return cur;
}

// Liang–Barsky clipping of the segment a-b to `box`; false when none of it is inside.
bool clip_segment(Point& a, Point& b, const Box& box) {
    const double dx = b[0] - a[0], dy = b[1] - a[1];
    const double p[] = {-dx, dx, -dy, dy};
    const double q[] = {a[0] - box.x0, box.x1 - a[0], a[1] - box.y0, box.y1 - a[1]};
    double t0 = 0, t1 = 1;
    for (int k = 0; k < 4; ++k) {
        if (p[k] == 0) {
            if (q[k] < 0) return false;
        } else if (p[k] < 0) {
            t0 = std::max(t0, q[k] / p[k]);
        } else {
            t1 = std::min(t1, q[k] / p[k]);
        }
    }
    if (t0 > t1) return false;
    const Point start = a;
    a = {start[0] + t0 * dx, start[1] + t0 * dy};
    b = {start[0] + t1 * dx, start[1] + t1 * dy};
    return true;
}

bool inside_box(const Point& q, const Box& box) {
    return q[0] >= box.x0 && q[0] <= box.x1 && q[1] >= box.y0 && q[1] <= box.y1;
}

struct MeshInPixels {
    const PictureLayout& layout;
    const Mesh& mesh;
    Box visible;  // the plot area
    // Cairo stores coordinates in 24.8 fixed point (about ±8 million pixels):
    // in a close-up a big cell can reach past that, so shapes are clipped to
    // this box, far enough outside the plot that the cuts are never seen.
    Box reach;

    Point node(NodeId n) const {
        const double* x = &mesh.points[static_cast<std::size_t>(n) * 2];
        return to_pixel(layout, x[0], x[1]);
    }

    // The cell's outline, or an empty polygon when the cell misses the plot.
    Polygon cell(std::size_t i) const {
        Polygon poly;
        double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
        bool within_reach = true;
        for (NodeId n : mesh.cells.nodes_of(i)) {
            const Point q = node(n);
            poly.push(q);
            x0 = std::min(x0, q[0]), x1 = std::max(x1, q[0]);
            y0 = std::min(y0, q[1]), y1 = std::max(y1, q[1]);
            within_reach = within_reach && inside_box(q, reach);
        }
        if (x1 < visible.x0 || x0 > visible.x1 || y1 < visible.y0 || y0 > visible.y1) return {};
        return within_reach ? poly : clip_polygon(poly, reach);
    }
};

void add_polygon(cairo_t* cr, const Polygon& poly) {
    if (poly.n == 0) return;
    cairo_move_to(cr, poly.p[0][0], poly.p[0][1]);
    for (int k = 1; k < poly.n; ++k) cairo_line_to(cr, poly.p[k][0], poly.p[k][1]);
    cairo_close_path(cr);
}

double area(const Polygon& poly) {
    double twice = 0;
    for (int k = 0; k < poly.n; ++k) {
        const Point& a = poly.p[k];
        const Point& b = poly.p[(k + 1) % poly.n];
        twice += a[0] * b[1] - a[1] * b[0];
    }
    return 0.5 * std::fabs(twice);
}

// Over coloured cells, edges fade out in eight steps as cells shrink from 8
// to 2 pixels across: in a whole-mesh view the boundary layer would otherwise
// be a black smear that hides the cells' colours. (Fewer steps show as bands.)
constexpr int edge_levels = 8;
int edge_level(const Polygon& poly) {
    const double size_px = std::sqrt(area(poly));
    return static_cast<int>(std::ceil(std::clamp((size_px - 2.0) / 6.0, 0.0, 1.0) * edge_levels));
}

constexpr Rgb edge_color{0.07, 0.07, 0.09};
constexpr double edge_alpha = 0.6;
constexpr Rgb marker_color{0, 0, 0};
constexpr Rgb frame_color{0.6, 0.6, 0.6};

/// The cells drawn: their indices, in order, the inverted ones among them,
/// each one's edge level, and whether some cell reaches outside the plot.
struct DrawnCells {
    std::vector<std::int64_t> shown, inverted;
    std::vector<std::uint8_t> level;  // per shown cell
    bool cut = false;
};

// Fills without antialiasing: neighbouring antialiased fills let the
// background shine through their shared edges. Inverted cells go last so
// that overlapping neighbours never hide them.
DrawnCells fill_cells(cairo_t* cr, const PictureLayout& layout, const MeshInPixels& pixels,
                      std::span<const double> values) {
    DrawnCells drawn;
    cairo_set_antialias(cr, CAIRO_ANTIALIAS_NONE);
    for (std::size_t i = 0; i < pixels.mesh.cells.size(); ++i) {
        const Polygon poly = pixels.cell(i);
        if (poly.n == 0) continue;
        drawn.shown.push_back(static_cast<std::int64_t>(i));
        for (int k = 0; k < poly.n; ++k) drawn.cut = drawn.cut || !inside_box(poly.p[k], pixels.visible);
        drawn.level.push_back(static_cast<std::uint8_t>(layout.colored ? edge_level(poly) : edge_levels));
        if (layout.colored && !(values[i] > 0)) {
            drawn.inverted.push_back(static_cast<std::int64_t>(i));
            continue;
        }
        set_color(cr, layout.colored ? value_color(values[i]) : plain_cell_color);
        add_polygon(cr, poly);
        cairo_fill(cr);
    }
    set_color(cr, inverted_color);
    for (std::int64_t i : drawn.inverted) add_polygon(cr, pixels.cell(static_cast<std::size_t>(i)));
    cairo_fill(cr);
    cairo_set_antialias(cr, CAIRO_ANTIALIAS_DEFAULT);
    return drawn;
}

// Edges: one stroke per fading level, so an edge shared by two cells is not
// darkened twice. Inverted cells are outlined too, so that even one smaller
// than a pixel shows.
void stroke_cell_edges(cairo_t* cr, const MeshInPixels& pixels, const DrawnCells& drawn, double edge_width_px) {
    if (edge_width_px > 0) {
        cairo_set_line_width(cr, edge_width_px);
        for (int l = 1; l <= edge_levels; ++l) {
            for (std::size_t k = 0; k < drawn.shown.size(); ++k)
                if (drawn.level[k] == l) add_polygon(cr, pixels.cell(static_cast<std::size_t>(drawn.shown[k])));
            cairo_set_source_rgba(cr, edge_color.r, edge_color.g, edge_color.b, edge_alpha * l / edge_levels);
            cairo_stroke(cr);
        }
    }
    if (!drawn.inverted.empty()) {
        cairo_set_line_width(cr, std::max(1.5, 2 * edge_width_px));
        cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
        for (std::int64_t i : drawn.inverted) add_polygon(cr, pixels.cell(static_cast<std::size_t>(i)));
        set_color(cr, inverted_color);
        cairo_stroke(cr);
    }
}

// The markers' lines (2D markers hold line elements), over the cells.
void stroke_marker_lines(cairo_t* cr, const MeshInPixels& pixels, double edge_width_px) {
    const Box& visible = pixels.visible;
    cairo_set_line_width(cr, std::max(2.0, 3 * edge_width_px));
    cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
    cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
    set_color(cr, marker_color);
    for (const Marker& marker : pixels.mesh.markers)
        for (std::size_t e = 0; e < marker.elements.size(); ++e) {
            const auto nodes = marker.elements.nodes_of(e);
            if (nodes.size() != 2) continue;
            Point a = pixels.node(nodes[0]), b = pixels.node(nodes[1]);
            if (std::max(a[0], b[0]) < visible.x0 || std::min(a[0], b[0]) > visible.x1 ||
                std::max(a[1], b[1]) < visible.y0 || std::min(a[1], b[1]) > visible.y1)
                continue;
            if (!clip_segment(a, b, pixels.reach)) continue;
            cairo_move_to(cr, a[0], a[1]);
            cairo_line_to(cr, b[0], b[1]);
        }
    cairo_stroke(cr);
}

// A thin frame around the plot area, so that a close-up's cut-off cells end at a line.
void draw_plot_frame(cairo_t* cr, const std::array<double, 4>& plot) {
    cairo_save(cr);
    cairo_rectangle(cr, std::round(plot[0]) - 0.5, std::round(plot[1]) - 0.5, std::round(plot[2]) + 1,
                    std::round(plot[3]) + 1);
    set_color(cr, frame_color);
    cairo_set_line_width(cr, 1.0);
    cairo_stroke(cr);
    cairo_restore(cr);
}

}  // namespace

void draw_mesh(cairo_t* cr, const PictureLayout& layout, const Mesh& mesh, std::span<const double> values,
               double edge_width_px) {
    const auto& plot = layout.plot;
    const Box visible{plot[0], plot[0] + plot[2], plot[1], plot[1] + plot[3]};
    const double reach = 2.0 * std::max(plot[2], plot[3]) + 1000.0;
    const MeshInPixels pixels{layout, mesh, visible,
                              {visible.x0 - reach, visible.x1 + reach, visible.y0 - reach, visible.y1 + reach}};
    cairo_save(cr);
    cairo_rectangle(cr, plot[0], plot[1], plot[2], plot[3]);
    cairo_clip(cr);
    const DrawnCells drawn = fill_cells(cr, layout, pixels, values);
    stroke_cell_edges(cr, pixels, drawn, edge_width_px);
    stroke_marker_lines(cr, pixels, edge_width_px);
    cairo_restore(cr);
    if (drawn.cut) draw_plot_frame(cr, plot);
}

}  // namespace dgwarp::picture_detail
