// random_scene: the layout of a random scene (bodies, motions, sizes), no Gmsh.
#include "dgwarp/cases/random_scene.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <sstream>

#include "dgwarp/core/error.hpp"
#include "dgwarp/graph/nearest_node.hpp"

namespace dgwarp {

namespace {

constexpr double pi = std::numbers::pi;

// Draws in a fixed order from one generator: U(a, b) as the header writes it.
// std::uniform_real_distribution is implementation-defined; this is not, so a
// seed gives the same scene with every standard library.
struct Draw {
    std::mt19937_64 rng;
    double u(double a, double b) { return a + (b - a) * (static_cast<double>(rng() >> 11) * 0x1.0p-53); }
    int integer(int a, int b) { return a + static_cast<int>(u(0, 1) * (b - a + 1)); }  // a .. b
};

// NACA 4-digit mean line and half thickness at x in [0, 1] (closed trailing edge).
double naca_camber(double x, double m, double p) {
    if (m <= 0) return 0;
    return x < p ? m / (p * p) * (2 * p * x - x * x) : m / ((1 - p) * (1 - p)) * ((1 - 2 * p) + 2 * p * x - x * x);
}
double naca_half_thickness(double x, double t) {
    return 5 * t * (0.2969 * std::sqrt(x) - 0.1260 * x - 0.3516 * x * x + 0.2843 * x * x * x - 0.1036 * x * x * x * x);
}

// The 2D outline in the body's frame (length 1 along x, centred), counter-clockwise, n points.
std::vector<std::array<double, 2>> outline_2d(const SceneBody& b, int n) {
    std::vector<std::array<double, 2>> p;
    const auto& q = b.parameters;
    switch (b.shape) {
        case SceneShape::ellipse:
        case SceneShape::circle: {
            const double ry = b.shape == SceneShape::circle ? 0.5 : 0.5 * q[0];
            for (int k = 0; k < n; ++k) p.push_back({0.5 * std::cos(2 * pi * k / n), ry * std::sin(2 * pi * k / n)});
            break;
        }
        case SceneShape::naca: {
            // From the trailing edge along the upper side to the leading edge and back
            // along the lower side (counter-clockwise), cosine spacing.
            const int half = std::max(n / 2, 8);
            for (int k = 0; k < 2 * half; ++k) {
                const bool upper = k < half;
                const double s = upper ? double(half - k) / half : double(k - half) / half;  // 1 at TE, 0 at LE
                const double x = 0.5 * (1 - std::cos(pi * s));
                const double yc = naca_camber(x, q[0], q[1]), yt = naca_half_thickness(x, q[2]);
                p.push_back({x - 0.5, upper ? yc + yt : yc - yt});
            }
            break;
        }
        case SceneShape::rounded_rectangle: {
            const double hx = 0.5, hy = 0.5 * q[0], r = q[1] * q[0] * 0.5;
            // The rectangle shrunk by r, its outline pushed out by r: corners are quarter circles.
            const double per = 4 * (hx - r) + 4 * (hy - r) + 2 * pi * r;
            const double corner[4][2] = {{hx - r, hy - r}, {-(hx - r), hy - r}, {-(hx - r), -(hy - r)}, {hx - r, -(hy - r)}};
            for (int k = 0; k < n; ++k) {
                double s = per * k / n;
                // Walk: right side up from the middle, top-right corner, top, ...
                const double sides[4] = {2 * (hy - r), 2 * (hx - r), 2 * (hy - r), 2 * (hx - r)};
                double x = hx, y = 0;
                s += hy - r;  // start at the middle of the right side: the first side's offset
                for (int c = 0;; c = (c + 1) % 4) {
                    if (s < sides[c]) {
                        const double t = s - sides[c] / 2;
                        const double along[4][2] = {{hx, t}, {-t, hy}, {-hx, -t}, {t, -hy}};
                        x = along[c][0];
                        y = along[c][1];
                        break;
                    }
                    s -= sides[c];
                    if (s < pi / 2 * r) {
                        const double a = pi / 2 * c + s / r;
                        x = corner[c][0] + r * std::cos(a);
                        y = corner[c][1] + r * std::sin(a);
                        break;
                    }
                    s -= pi / 2 * r;
                }
                p.push_back({x, y});
            }
            break;
        }
        default: throw Error("random scene: " + scene_shape_name(b.shape) + " is not a 2D shape");
    }
    return p;
}

// Fibonacci points on the unit sphere.
std::array<double, 3> sphere_point(int k, int n) {
    const double z = 1 - 2 * (k + 0.5) / n, r = std::sqrt(std::max(0.0, 1 - z * z));
    const double a = k * pi * (3 - std::sqrt(5.0));
    return {r * std::cos(a), r * std::sin(a), z};
}

// Points over the 3D surface in the body's frame (length 1 along x), about n of them.
std::vector<std::array<double, 3>> outline_3d(const SceneBody& b, int n) {
    std::vector<std::array<double, 3>> p;
    const auto& q = b.parameters;
    switch (b.shape) {
        case SceneShape::spheroid:
            for (int k = 0; k < n; ++k) {
                const auto s = sphere_point(k, n);
                p.push_back({0.5 * s[0], 0.5 * q[0] * s[1], 0.5 * q[0] * s[2]});
            }
            break;
        case SceneShape::capsule: {
            const double r = q[0], half = 0.5 - r;
            const int caps = n / 3, rings = std::max(4, (n - caps) / 24);
            for (int k = 0; k < caps; ++k) {
                const auto s = sphere_point(k, caps);
                p.push_back({(s[0] >= 0 ? half : -half) + r * s[0], r * s[1], r * s[2]});
            }
            for (int i = 0; i <= rings; ++i)
                for (int j = 0; j < 24; ++j)
                    p.push_back({-half + 2 * half * i / rings, r * std::cos(2 * pi * j / 24), r * std::sin(2 * pi * j / 24)});
            break;
        }
        case SceneShape::rounded_box: {
            // The box's faces on a grid (the rounded edges lie inside: a conservative outline).
            const double h[3] = {0.5, 0.5 * q[0], 0.5 * q[1]};
            const int m = std::max(4, static_cast<int>(std::sqrt(n / 6.0)));
            for (int axis = 0; axis < 3; ++axis)
                for (int side : {-1, 1})
                    for (int i = 0; i <= m; ++i)
                        for (int j = 0; j <= m; ++j) {
                            std::array<double, 3> x{};
                            const int a = (axis + 1) % 3, c = (axis + 2) % 3;
                            x[axis] = side * h[axis];
                            x[a] = -h[a] + 2 * h[a] * i / m;
                            x[c] = -h[c] + 2 * h[c] * j / m;
                            p.push_back(x);
                        }
            break;
        }
        case SceneShape::wing: {
            const double t = q[0], span = q[1];
            const int around = 48, stations = std::max(4, n / around);
            for (int i = 0; i <= stations; ++i)
                for (int k = 0; k < around; ++k) {
                    const double s = 2.0 * k / around;  // 0..2: lower then upper side
                    const double x = 0.5 * (1 - std::cos(pi * (s <= 1 ? s : 2 - s)));
                    const double y = naca_half_thickness(x, t) * (s <= 1 ? -1 : 1);
                    p.push_back({x - 0.5, y, -span / 2 + span * i / stations});
                }
            break;
        }
        default: throw Error("random scene: " + scene_shape_name(b.shape) + " is not a 3D shape");
    }
    return p;
}

// Whether point x (body frame) is inside the body, a little shrunk (so that
// the outline's own points are not inside).
bool inside_body_frame(const SceneBody& b, const std::array<double, 3>& x) {
    const auto& q = b.parameters;
    constexpr double in = 0.999;
    switch (b.shape) {
        case SceneShape::ellipse: return std::pow(x[0] / 0.5, 2) + std::pow(x[1] / (0.5 * q[0]), 2) < in;
        case SceneShape::circle: return std::hypot(x[0], x[1]) < 0.5 * in;
        case SceneShape::naca: {
            const double u = x[0] + 0.5;
            return u > 0 && u < 1 && std::abs(x[1] - naca_camber(u, q[0], q[1])) < in * naca_half_thickness(u, q[2]);
        }
        case SceneShape::rounded_rectangle: {
            const double hy = 0.5 * q[0], r = q[1] * q[0] * 0.5;
            const double dx = std::max(std::abs(x[0]) - (0.5 - r), 0.0), dy = std::max(std::abs(x[1]) - (hy - r), 0.0);
            return std::hypot(dx, dy) < r * in;
        }
        case SceneShape::spheroid:
            return std::pow(x[0] / 0.5, 2) + (x[1] * x[1] + x[2] * x[2]) / std::pow(0.5 * q[0], 2) < in;
        case SceneShape::capsule: {
            const double half = 0.5 - q[0], c = std::clamp(x[0], -half, half);
            return std::sqrt((x[0] - c) * (x[0] - c) + x[1] * x[1] + x[2] * x[2]) < q[0] * in;
        }
        case SceneShape::rounded_box:
            return std::abs(x[0]) < 0.5 * in && std::abs(x[1]) < 0.5 * q[0] * in && std::abs(x[2]) < 0.5 * q[1] * in;
        case SceneShape::wing: {
            const double u = x[0] + 0.5;
            return u > 0 && u < 1 && std::abs(x[2]) < q[1] / 2 * in && std::abs(x[1]) < in * naca_half_thickness(u, q[0]);
        }
    }
    return false;
}

// x' = c + R(w)(x - c) + t for the motion scaled by f (what apply_motion does).
std::array<double, 3> moved(const NodeMotion& m, double f, const std::array<double, 3>& x) {
    NodeMotion s = m;
    for (int d = 0; d < 3; ++d) {
        s.rotation[d] *= f;
        s.translation[d] *= f;
    }
    std::array<double, 3> y{};
    apply_motion(s, x, y);
    return y;
}

// Body frame -> world (before the motion) and back.
std::array<double, 3> to_world(const SceneBody& b, const std::array<double, 3>& x) {
    const auto r = rotation_matrix(b.orientation);
    std::array<double, 3> y{};
    for (int i = 0; i < 3; ++i) y[i] = b.centre[i] + b.length * (r[3 * i] * x[0] + r[3 * i + 1] * x[1] + r[3 * i + 2] * x[2]);
    return y;
}
std::array<double, 3> to_body(const SceneBody& b, double f, const std::array<double, 3>& world) {
    // Undo the motion at f: x = c + R(-f w)(x' - f t - c); then the placement.
    NodeMotion back;
    back.center = b.motion.center;
    for (int d = 0; d < 3; ++d) back.rotation[d] = -f * b.motion.rotation[d];
    std::array<double, 3> shifted{}, x{};
    for (int d = 0; d < 3; ++d) shifted[d] = world[d] - f * b.motion.translation[d];
    apply_motion(back, shifted, x);
    const auto r = rotation_matrix(b.orientation);
    std::array<double, 3> y{};
    for (int i = 0; i < 3; ++i)
        y[i] = (r[i] * (x[0] - b.centre[0]) + r[3 + i] * (x[1] - b.centre[1]) + r[6 + i] * (x[2] - b.centre[2])) / b.length;
    return y;
}

// A body placed and moved: its outline (world, at fraction f) for the gap checks.
struct Placed {
    const SceneBody* body;
    std::vector<std::array<double, 3>> points;  // 2D: polygon vertices (z = 0)
};

Placed place(const SceneBody& b, int dim, double f) {
    Placed p{&b, {}};
    const std::vector<double> o = body_outline(b, dim, dim == 2 ? 96 : 1500, f);
    for (std::size_t k = 0; k < o.size(); k += dim) p.points.push_back({o[k], o[k + 1], dim == 3 ? o[k + 2] : 0.0});
    return p;
}

double segment_distance(const std::array<double, 3>& x, const std::array<double, 3>& a, const std::array<double, 3>& b) {
    const double ex = b[0] - a[0], ey = b[1] - a[1], l2 = ex * ex + ey * ey;
    const double t = l2 > 0 ? std::clamp(((x[0] - a[0]) * ex + (x[1] - a[1]) * ey) / l2, 0.0, 1.0) : 0.0;
    return std::hypot(x[0] - a[0] - t * ex, x[1] - a[1] - t * ey);
}

// The gap between two placed bodies (0 when they overlap).
double gap(const Placed& a, const Placed& b, int dim, double fa, double fb) {
    for (const auto& x : a.points)
        if (inside_body_frame(*b.body, to_body(*b.body, fb, x))) return 0;
    for (const auto& x : b.points)
        if (inside_body_frame(*a.body, to_body(*a.body, fa, x))) return 0;
    double best = std::numeric_limits<double>::infinity();
    if (dim == 2) {
        const std::size_t nb = b.points.size();
        for (const auto& x : a.points)
            for (std::size_t k = 0; k < nb; ++k) best = std::min(best, segment_distance(x, b.points[k], b.points[(k + 1) % nb]));
        const std::size_t na = a.points.size();
        for (const auto& x : b.points)
            for (std::size_t k = 0; k < na; ++k) best = std::min(best, segment_distance(x, a.points[k], a.points[(k + 1) % na]));
        return best;
    }
    std::vector<double> coords;
    for (const auto& x : b.points) coords.insert(coords.end(), x.begin(), x.end());
    std::vector<NodeId> ids(b.points.size());
    for (std::size_t k = 0; k < ids.size(); ++k) ids[k] = static_cast<NodeId>(k);
    const NearestNode tree(3, coords, ids);
    for (const auto& x : a.points) best = std::min(best, tree.nearest(x.data()).distance);
    return best;
}

double wall_gap(const Placed& a, const Vec3& half, int dim) {
    double best = std::numeric_limits<double>::infinity();
    for (const auto& x : a.points)
        for (int d = 0; d < dim; ++d) best = std::min(best, half[d] - std::abs(x[d]));
    return std::max(best, 0.0);
}

Vec3 random_rotation(Draw& draw, int dim) {
    if (dim == 2) return {0, 0, draw.u(-pi, pi)};
    // A uniform random rotation: axis uniform on the sphere, angle with density (1 - cos a) / pi.
    const double z = draw.u(-1, 1), phi = draw.u(0, 2 * pi), r = std::sqrt(1 - z * z);
    double angle = 0;
    for (double target = draw.u(0, 1), lo = 0, hi = pi; hi - lo > 1e-9;) {
        angle = (lo + hi) / 2;
        ((angle - std::sin(angle)) / pi < target ? lo : hi) = angle;
    }
    return {angle * r * std::cos(phi), angle * r * std::sin(phi), angle * z};
}

SceneBody random_body(Draw& draw, int dim, int index) {
    SceneBody b;
    b.marker = "body" + std::to_string(index + 1);
    const int kind = draw.integer(0, 3);
    auto& q = b.parameters;
    if (dim == 2) {
        b.shape = std::array{SceneShape::ellipse, SceneShape::naca, SceneShape::rounded_rectangle, SceneShape::circle}[kind];
        if (b.shape == SceneShape::ellipse) q[0] = draw.u(0.25, 0.7);
        if (b.shape == SceneShape::naca) q = {draw.u(0, 0.06), draw.u(0.2, 0.6), draw.u(0.08, 0.2), 0};
        if (b.shape == SceneShape::rounded_rectangle) q = {draw.u(0.2, 0.6), draw.u(0.1, 0.45), 0, 0};
    } else {
        b.shape = std::array{SceneShape::spheroid, SceneShape::capsule, SceneShape::rounded_box, SceneShape::wing}[kind];
        if (b.shape == SceneShape::spheroid) q[0] = draw.u(0.3, 1.0);
        if (b.shape == SceneShape::capsule) q[0] = draw.u(0.1, 0.3);
        if (b.shape == SceneShape::rounded_box) q = {draw.u(0.3, 0.8), draw.u(0.3, 0.8), draw.u(0.05, 0.12), 0};
        if (b.shape == SceneShape::wing) q = {draw.u(0.1, 0.2), draw.u(1.0, 1.6), 0, 0};
    }
    b.length = draw.u(0.6, 1.2);
    b.orientation = random_rotation(draw, dim);
    return b;
}

// The smallest clearance of the moving bodies along the first s of their motions.
double clearance_along(const RandomScene& scene, double s) {
    const int dim = scene.dim;
    double best = std::numeric_limits<double>::infinity();
    for (int k = 0; k <= 32; ++k) {
        const double f = s * k / 32;
        std::vector<Placed> placed;
        for (const SceneBody& b : scene.bodies) placed.push_back(place(b, dim, b.moving ? f : 0));
        for (std::size_t i = 0; i < placed.size(); ++i) {
            if (!scene.bodies[i].moving) continue;
            best = std::min(best, wall_gap(placed[i], scene.box_half, dim));
            for (std::size_t j = 0; j < placed.size(); ++j)
                if (j != i && (j > i || !scene.bodies[j].moving))
                    best = std::min(best, gap(placed[i], placed[j], dim, f, scene.bodies[j].moving ? f : 0));
        }
    }
    return best;
}

}  // namespace

std::string scene_shape_name(SceneShape s) {
    switch (s) {
        case SceneShape::ellipse: return "ellipse";
        case SceneShape::naca: return "naca";
        case SceneShape::rounded_rectangle: return "rounded-rectangle";
        case SceneShape::circle: return "circle";
        case SceneShape::spheroid: return "spheroid";
        case SceneShape::capsule: return "capsule";
        case SceneShape::rounded_box: return "rounded-box";
        case SceneShape::wing: return "wing";
    }
    return "?";
}

std::vector<double> body_outline(const SceneBody& body, int dim, int points, double f) {
    std::vector<double> out;
    const auto add = [&](const std::array<double, 3>& local) {
        const auto y = moved(body.motion, f, to_world(body, local));
        out.insert(out.end(), y.begin(), y.begin() + dim);
    };
    if (dim == 2)
        for (const auto& p : outline_2d(body, points)) add({p[0], p[1], 0});
    else
        for (const auto& p : outline_3d(body, points)) add(p);
    return out;
}

RandomScene random_scene(int dim, std::uint64_t seed) {
    if (dim != 2 && dim != 3) throw Error("random scene: dim must be 2 or 3, got " + std::to_string(dim));
    RandomScene scene;
    scene.dim = dim;
    scene.seed = seed;
    Draw draw{std::mt19937_64(seed * 2 + static_cast<std::uint64_t>(dim - 2) + 0x5eedULL)};
    scene.box_half = {draw.u(2.5, 4), draw.u(2, 3), dim == 3 ? draw.u(2, 3) : 0.0};
    const int wanted = draw.integer(1, 4);
    // 3D: coarser (20k-150k nodes).
    scene.wall_size = dim == 2 ? draw.u(0.008, 0.02) : draw.u(0.035, 0.06);
    scene.growth = dim == 2 ? draw.u(0.1, 0.25) : draw.u(0.2, 0.35);
    scene.max_size = dim == 2 ? draw.u(0.12, 0.25) : draw.u(0.3, 0.5);
    scene.boundary_layers = dim == 2 && draw.integer(0, 2) == 0 ? draw.integer(4, 8) : 0;

    // Placement.
    std::vector<Placed> placed;
    scene.bodies.reserve(4);  // `placed` points into it
    double min_gap = std::numeric_limits<double>::infinity();
    for (int i = 0; i < wanted; ++i) {
        SceneBody b = random_body(draw, dim, static_cast<int>(scene.bodies.size()));
        bool ok = false;
        for (int attempt = 0; attempt < 400 && !ok; ++attempt) {
            for (int d = 0; d < dim; ++d) b.centre[d] = draw.u(-scene.box_half[d], scene.box_half[d]);
            const Placed p = place(b, dim, 0);
            double nearest = wall_gap(p, scene.box_half, dim), smallest = nearest;
            for (const Placed& other : placed) {
                const double g = gap(p, other, dim, 0, 0);
                nearest = std::min(nearest, g);
                smallest = std::min(smallest, g);
            }
            ok = smallest >= 0.05 * b.length && nearest <= 1.0 * b.length;
            if (ok) min_gap = std::min(min_gap, smallest);
        }
        if (!ok) continue;
        scene.bodies.push_back(b);
        placed.clear();
        for (const SceneBody& s : scene.bodies) placed.push_back(place(s, dim, 0));
    }
    if (scene.bodies.empty()) throw Error("random scene: no body could be placed (seed " + std::to_string(seed) + ")");
    scene.min_gap = min_gap;
    // At least three cells across the smallest gap, beside the boundary layers
    // (thickness 0.3 h_w (1.2^N - 1) / 0.2) of both sides.
    const double layers = scene.boundary_layers > 0 ? 1.5 * (std::pow(1.2, scene.boundary_layers) - 1) : 0;
    scene.wall_size = std::min(scene.wall_size, min_gap / (3 + 2 * layers));

    // Motions.
    const int n = static_cast<int>(scene.bodies.size());
    const int moving = n == 1 ? 1 : draw.integer(1, n - 1);
    std::vector<int> order(n);
    for (int i = 0; i < n; ++i) order[i] = i;
    for (int i = n - 1; i > 0; --i) std::swap(order[i], order[draw.integer(0, i)]);  // Fisher-Yates, our draws
    for (int k = 0; k < moving; ++k) {
        SceneBody& b = scene.bodies[order[k]];
        b.moving = true;
        const int kind = draw.integer(0, 2);  // 0 rotate, 1 translate, 2 both
        const double angle = draw.u(10, 90) * pi / 180 * (draw.u(0, 1) < 0.5 ? -1 : 1);
        const double along = draw.u(-0.3, 0.3);
        const Vec3 axis_dir = dim == 2 ? Vec3{0, 0, 1} : [&] {
            const double z = draw.u(-1, 1), phi = draw.u(0, 2 * pi), r = std::sqrt(1 - z * z);
            return Vec3{r * std::cos(phi), r * std::sin(phi), z};
        }();
        const double distance = draw.u(0.1, 0.5) * b.length;
        Vec3 direction{};
        if (dim == 2) {
            const double a = draw.u(0, 2 * pi);
            direction = {std::cos(a), std::sin(a), 0};
        } else {
            const double z = draw.u(-1, 1), phi = draw.u(0, 2 * pi), r = std::sqrt(1 - z * z);
            direction = {r * std::cos(phi), r * std::sin(phi), z};
        }
        b.motion.center = to_world(b, {along, 0, 0});
        if (kind != 1)
            for (int d = 0; d < 3; ++d) b.motion.rotation[d] = angle * axis_dir[d];
        if (kind != 0)
            for (int d = 0; d < dim; ++d) b.motion.translation[d] = distance * direction[d];
    }
    // Clipping: the largest s in {1, 0.95, ..., 0.05} with clearance >= 2 wall sizes.
    const std::vector<SceneBody> drawn = scene.bodies;
    scene.clip = 0;
    for (int k = 20; k >= 1; --k) {
        const double s = k / 20.0;
        if (clearance_along(scene, s) >= 2 * scene.wall_size) {
            scene.clip = s;
            break;
        }
    }
    for (SceneBody& b : scene.bodies)
        for (int d = 0; d < 3; ++d) {
            b.motion.rotation[d] *= scene.clip;
            b.motion.translation[d] *= scene.clip;
        }
    scene.min_clearance = clearance_along(scene, 1.0);
    return scene;
}

MotionSpec random_scene_motion(const RandomScene& scene) {
    MotionSpec spec;
    MotionFrame frame;
    for (const SceneBody& b : scene.bodies)
        frame.markers[b.marker] = b.moving ? MarkerMotion(RigidMotion{b.motion}) : MarkerMotion(FixedMotion{});
    frame.markers["walls"] = FixedMotion{};
    spec.frames.push_back(std::move(frame));
    return spec;
}

std::string describe_scene(const RandomScene& scene) {
    std::ostringstream s;
    s << "seed " << scene.seed << ", " << scene.dim << "D: " << scene.bodies.size() << " bod"
      << (scene.bodies.size() == 1 ? "y" : "ies") << " (";
    for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
        const SceneBody& b = scene.bodies[i];
        s << (i ? ", " : "") << b.marker << " " << scene_shape_name(b.shape);
        if (b.moving) {
            const double angle = std::sqrt(b.motion.rotation[0] * b.motion.rotation[0] +
                                           b.motion.rotation[1] * b.motion.rotation[1] +
                                           b.motion.rotation[2] * b.motion.rotation[2]) * 180 / pi;
            const double shift = std::sqrt(b.motion.translation[0] * b.motion.translation[0] +
                                           b.motion.translation[1] * b.motion.translation[1] +
                                           b.motion.translation[2] * b.motion.translation[2]);
            s.precision(3);
            s << " moving: turn " << angle << "°, shift " << shift;
        }
    }
    s.precision(3);
    s << "); smallest gap " << scene.min_gap << ", motion clipped to " << scene.clip << ", clearance "
      << scene.min_clearance << ", wall cell " << scene.wall_size
      << (scene.boundary_layers ? ", " + std::to_string(scene.boundary_layers) + " quadrilateral layers" : "");
    return s.str();
}

}  // namespace dgwarp
