#pragma once
// View windows of mesh pictures, in mesh coordinates: {xmin, xmax, ymin, ymax}.
#include <array>
#include <span>

#include "dgwarp/mesh/mesh.hpp"

namespace dgwarp {

/// `window` enlarged about its centre, in x or in y, until width / height
/// equals `aspect` (> 0). A window of zero width and height stays a point.
std::array<double, 4> enlarge_to_aspect(const std::array<double, 4>& window, double aspect);

/// A close-up window: the bounding box of `nodes` (0-based ids into
/// mesh.points, e.g. the nodes of an airfoil's trailing-edge region, from
/// marker_nodes or the caller's own choice) scaled about its centre by
/// `margin_factor` (>= 1 leaves room around them), then enlarged to `aspect`
/// (width / height of the picture's drawing area; the default fits a
/// 1600 × 1200 picture). When the nodes' box is a single point, its size is
/// taken as 1% of the mesh's bounding box so the window is not empty.
/// Throws MeshError when `nodes` is empty or holds an id out of range (the
/// error's index is the position in `nodes`), and Error when margin_factor or
/// aspect is not finite and positive.
std::array<double, 4> window_around(const Mesh& mesh, std::span<const NodeId> nodes,
                                    double margin_factor, double aspect = 4.0 / 3.0);

}  // namespace dgwarp
