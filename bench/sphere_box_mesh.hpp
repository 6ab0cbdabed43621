#pragma once
// The paper's squeezed-sphere case (section 3, Tables 9-10): a unit sphere in
// a 10 × 10 × 10 box, tetrahedra graded from the sphere outwards, generated
// by the library's make_sphere_box (cases/sphere_box.hpp) and cached as a raw
// binary dump so reruns are fast.
#include <filesystem>
#include <string>
#include <vector>

#include "dgwarp/cases/sphere_box.hpp"
#include "dgwarp/mesh/mesh.hpp"

namespace dgwarp::bench {

/// One case: its name and the library generator's options (sphere_box_paper_size),
/// so the benchmark runs on exactly the mesh `dgwarp case squeezed-sphere` writes.
struct SphereBoxCase {
    std::string name;
    SphereBoxOptions options;
};

struct SphereBoxMesh {
    std::vector<double> points;          // num_points × 3
    std::vector<NodeId> sphere_nodes;    // sorted
    std::vector<NodeId> box_nodes;       // sorted
    double generate_seconds = 0;         // Gmsh time when it was generated
    std::size_t num_points() const { return points.size() / 3; }
};

/// The cached mesh of `c` in `cache_dir`, generating it first (in a child
/// process killed after `timeout_seconds`) when absent. Throws std::runtime_error.
SphereBoxMesh sphere_box_mesh(const SphereBoxCase& c, const std::filesystem::path& cache_dir, int timeout_seconds);

/// The same mesh with its nodes renumbered along a Hilbert curve (as solvers
/// renumber meshes for locality): Gmsh's 3D Delaunay numbers new nodes in
/// insertion order, which is spatially random, and a step's gathers follow the
/// node order.
SphereBoxMesh renumbered_along_hilbert_curve(const SphereBoxMesh& m);

}  // namespace dgwarp::bench
