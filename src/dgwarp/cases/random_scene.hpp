#pragma once
// Random scenes for the robustness campaign (dgwarp bench --robustness,
// docs/ROBUSTNESS.md): bodies in a box, some fixed and some moving rigidly,
// deterministic per seed and dimension.
//
//   const RandomScene scene = random_scene(2, 17);      // geometry and motions, no Gmsh
//   const Mesh mesh = make_random_scene_mesh(scene);     // Gmsh
//   const MotionSpec motion = random_scene_motion(scene);
//
// The distribution (every draw from one std::mt19937_64 seeded by seed and
// dimension, through uniform_real in [a, b) written U(a, b); lengths in body
// lengths L = 1):
//  - the box: [-X, X] × [-Y, Y] (× [-Z, Z]) with X ~ U(2.5, 4), Y, Z ~ U(2, 3);
//  - 1 to 4 bodies (uniform), each of a shape drawn uniformly
//      2D: ellipse (thickness ratio U(0.25, 0.7)), NACA 4-digit airfoil
//          (camber U(0, 0.06) at U(0.2, 0.6), thickness U(0.08, 0.2)), rounded
//          rectangle (height U(0.2, 0.6), corner radius U(0.1, 0.45) × height),
//          circle;
//      3D: spheroid (thickness ratio U(0.3, 1)), capsule (radius U(0.1, 0.3)),
//          rounded box (sides U(0.3, 0.8), edge radius U(0.05, 0.12)),
//          short wing (NACA 00tt section, t U(0.1, 0.2), span U(1, 1.6) chords);
//    of length U(0.6, 1.2), turned at random (2D: an angle; 3D: a uniform
//    random rotation), placed at random so that its gap to the nearest other
//    body or wall is 0.05 to 1 of its length and to every other at least 0.05
//    (at most 400 tries a body: a scene may have fewer bodies than drawn);
//  - the moving bodies: one when there is one body, else 1 to (bodies - 1),
//    the others fixed; each moves rigidly: a rotation (angle U(10°, 90°), either
//    sign, about a point on its axis within 0.3 of its length of its centre),
//    a translation (U(0.1, 0.5) body lengths in a random direction), or both
//    (one kind in three each);
//  - clipping: the motions are scaled by the largest s in {1, 0.95, ..., 0.05}
//    for which every moved body keeps at least two wall cell sizes of
//    clearance from every other body and wall all along the way (32 positions
//    between none and s of the motion, with the bodies' outlines);
//  - the mesh: cell size h_w ~ U(0.008, 0.02) at the bodies, small enough for
//    three cells across the smallest gap beside the boundary layers of both
//    sides, growing by U(0.1, 0.25) per unit distance from the bodies to at
//    most U(0.12, 0.25), and at most a quarter of the distances to the
//    bodies and the box added (four cells across a gap to the box); triangles (tetrahedra in 3D); on one seed in three (2D),
//    U(4, 8) layers of quadrilaterals around the bodies (first 0.3 h_w thick,
//    ratio 1.2).
// Markers: body1 ... bodyN, walls (the box).
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "dgwarp/mesh/mesh.hpp"
#include "dgwarp/motion/motion_spec.hpp"

namespace dgwarp {

enum class SceneShape { ellipse, naca, rounded_rectangle, circle, spheroid, capsule, rounded_box, wing };

/// "ellipse", "naca", "rounded-rectangle", "circle", "spheroid", "capsule", "rounded-box", "wing".
std::string scene_shape_name(SceneShape s);

/// One body: its shape in its own frame (centred at the origin, length
/// along x), then turned by `orientation` (a rotation vector; 2D: z only) and
/// moved to `centre`.
struct SceneBody {
    SceneShape shape = SceneShape::ellipse;
    std::string marker;             // body1, body2, ...
    double length = 1;              // along x in its frame
    std::array<double, 4> parameters{};  // per shape: see random_scene.cpp's outline functions
    Vec3 centre{};
    Vec3 orientation{};             // rotation vector from its frame
    bool moving = false;
    NodeMotion motion;              // the rigid motion (after clipping); zero when fixed
};

struct RandomScene {
    int dim = 2;
    std::uint64_t seed = 0;
    Vec3 box_half{};                // the box is [-box_half, box_half]
    double wall_size = 0.02;        // cell size at the walls
    double growth = 0.2;            // size growth per unit distance
    double max_size = 0.3;          // largest cell size
    int boundary_layers = 0;        // 2D: quadrilateral layers around the bodies (0: none)
    double clip = 1;                // the fraction of the drawn motions kept
    double min_gap = 0;             // the smallest gap between two bodies or a body and a wall
    double min_clearance = 0;       // the smallest gap along the moves (>= 2 wall_size, when clip > 0)
    std::vector<SceneBody> bodies;
};

/// The scene of `seed` in `dim` (2 or 3) dimensions. Deterministic: the same
/// on every machine and run. Throws Error for another dim.
RandomScene random_scene(int dim, std::uint64_t seed);

/// A body's outline in world coordinates, before its motion: 2D a closed
/// counter-clockwise polygon of about `points` vertices (x, y pairs), 3D
/// points spread over its surface (x, y, z triples), moved by the fraction f
/// of its motion (f = 0: where it starts).
std::vector<double> body_outline(const SceneBody& body, int dim, int points, double f = 0);

/// Meshes the scene with Gmsh (triangles or tetrahedra, quadrilateral layers
/// when scene.boundary_layers > 0). Throws MeshError when Gmsh fails.
Mesh make_random_scene_mesh(const RandomScene& scene);

/// The scene's motion: one frame, each moving body's marker with its rigid
/// motion, every other marker fixed.
MotionSpec random_scene_motion(const RandomScene& scene);

/// One line describing the scene ("seed 17, 2D: 3 bodies (ellipse moving, ...), ...").
std::string describe_scene(const RandomScene& scene);

}  // namespace dgwarp
