#pragma once
// The boundary types mesh files give their markers, and which of them slide
// unless a motion file says otherwise (docs/MOTION.md "Sliding by type").
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "dgwarp/io/mesh_io.hpp"
#include "dgwarp/core/warning.hpp"
#include "dgwarp/mesh/mesh.hpp"
#include "dgwarp/mesh/planar_case.hpp"
#include "dgwarp/motion/motion_spec.hpp"

namespace dgwarp {

/// Per marker of `mesh` (read with `extras`): the type its file gives it, an
/// OpenFOAM patch's ("wall", "patch", "empty", "wedge", "symmetryPlane", ...)
/// or a CGNS BC's ("BCWall", "BCSymmetryPlane", ...); "" where the file gives
/// none (SU2, Gmsh and VTU files).
std::vector<std::string> marker_types(const Mesh& mesh, const MeshExtras& extras);

/// Whether a marker of `type` slides by default: OpenFOAM's empty, wedge,
/// symmetryPlane and symmetry patches, CGNS's BCSymmetryPlane.
bool slides_by_type(std::string_view type);

/// The markers of `mesh` that slide by their type, in mesh order.
std::vector<std::string> markers_sliding_by_type(const Mesh& mesh, const MeshExtras& extras);

/// What a mesh file's marker types make of a motion.
struct TypedMotion {
    std::vector<std::string> sliding;  // the markers made to slide by their type (slide_unless_named)
    /// Set when the mesh's `empty` markers all slide and it is one cell thick
    /// between them (mesh/planar_case.hpp): a 2D case, deformed as its 2D mesh.
    std::optional<PlanarCase> planar;
    /// When they all slide but are not such a case: why (they then slide in 3D).
    std::string not_planar;
    /// OpenFOAM cyclic (and cyclicSlip) patches and their neighbourPatch made
    /// each other's CyclicMotion (couple_unless_named): coupled, one pair each.
    std::vector<std::pair<std::string, std::string>> coupled;
    /// The markers of a cyclic type that are not coupled: cyclicAMI and
    /// cyclicACMI (their halves' nodes are not images of each other), and
    /// cyclic patches without a neighbourPatch in the mesh. They move as the
    /// motion says (fixed by default), each on its own; the caller warns.
    std::vector<std::string> uncoupled;
};

/// The partner an OpenFOAM patch's dictionary names (its neighbourPatch), or "".
std::string cyclic_neighbour(const OpenFoamPatch& patch);

/// Whether `type` is one of OpenFOAM's cyclic patch types (not processorCyclic).
bool is_cyclic_type(std::string_view type);

/// Makes the markers that slide by their type, and the cyclic pairs cyclic
/// (unless the motion names either half), and the markers `also` (an
/// SU2 configuration's MARKER_SYM: io/su2/su2_config.hpp; names of `mesh`'s
/// markers), slide in `spec` unless it names them, and finds the 2D case the
/// `empty` or `wedge` markers make, if any (the caller deforms planar->mesh
/// with planar_motion(*planar, mesh, spec)).
TypedMotion apply_marker_types(const Mesh& mesh, const MeshExtras& extras, MotionSpec& spec,
                               const std::vector<std::string>& also = {});

/// The warning a caller gives about TypedMotion::uncoupled (non-empty).
Warning uncoupled_cyclic_warning(const std::vector<std::string>& uncoupled);

}  // namespace dgwarp
