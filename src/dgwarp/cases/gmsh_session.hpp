#pragma once
// Internal to the case generators: a Gmsh library session (initialise,
// General.Terminal 0, finalise on every exit path) and the conversion of the
// current Gmsh model's mesh to a dgwarp Mesh.
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "dgwarp/mesh/mesh.hpp"

namespace dgwarp::detail {

/// Runs `build` between gmsh::initialize() and gmsh::finalize() (General.Terminal
/// 0, General.NumThreads `threads`). Gmsh errors come back as MeshError naming
/// `what`. Gmsh keeps global state, so sessions must not overlap (one thread).
void with_gmsh(const std::string& what, int threads, const std::function<void()>& build);

/// The mesh of the current Gmsh model as a dgwarp Mesh of dimension `dim`
/// (2: triangles and quadrilaterals, z dropped; 3: tetrahedra). Nodes are renumbered 0.. in
/// Gmsh's node order; every marker (name, curve/surface entity tags) collects
/// the line (2D) or triangle (3D) elements of its entities. Cells are made
/// positively oriented (counter-clockwise in 2D, positive volume in 3D).
Mesh mesh_from_gmsh(int dim, const std::vector<std::pair<std::string, std::vector<int>>>& markers);

}  // namespace dgwarp::detail
