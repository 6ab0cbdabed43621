#pragma once
// Internal to the OpenFOAM reader and writer: OpenFOAM's face-based mesh as
// its polyMesh files hold it, and the conversions between it and the cells
// of the neutral Mesh (openfoam_cells.cpp: cells from faces; openfoam_faces.cpp: faces from cells).
//
// OpenFOAM's conventions (OpenFOAM user guide, "Mesh description"): a face is
// a list of point labels whose order makes its normal (right-hand rule) point
// out of its owner cell, into its neighbour; the internal faces come first,
// each with owner < neighbour; the boundary faces follow, grouped by patch.
#include <array>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "dgwarp/io/openfoam/openfoam.hpp"
#include "dgwarp/mesh/mesh.hpp"

namespace dgwarp::foam {

/// Whether `p` is an existing folder (false, not an exception, when it cannot
/// be looked at). Defined in openfoam_case.cpp.
bool is_folder(const std::filesystem::path& p);

/// One patch of the boundary file.
struct Patch {
    std::string name;
    OpenFoamPatch info;      // type and the other entries of its dictionary
    std::int64_t start = 0;  // startFace
    std::int64_t size = 0;   // nFaces
    std::size_t line = 0;    // line of its name in the boundary file (0 when written)
    bool processor = false;  // type processor or processorCyclic: faces shared with another processor
    /// processorCyclic: the cyclic patch its faces belong to (its referPatch);
    /// they are that patch's faces whose images are on another processor.
    std::string refer_patch;
};

struct PolyMesh {
    std::vector<double> points;                // num_points × 3, row-major
    std::vector<std::int64_t> face_offsets{0};  // face f: face_nodes[face_offsets[f] .. face_offsets[f+1])
    std::vector<NodeId> face_nodes;
    std::vector<std::int32_t> owner;      // one per face
    std::vector<std::int32_t> neighbour;  // one per internal face (the first ones)
    std::vector<Patch> patches;

    std::size_t num_faces() const { return face_offsets.size() - 1; }
};

/// Where the faces of a PolyMesh read from files are, for errors about cells.
struct FaceLines {
    std::string faces_file, owner_file;
    std::vector<std::uint32_t> line;  // per face: its line in the faces file
};

/// One polyMesh folder's files read (read_openfoam_files is its mesh): the
/// mesh, whose markers are the patches other than processor patches, and
/// every patch. `processor_patches`: whether processor patches are accepted
/// (one processor's part of a decomposed case) or refused (FormatError).
struct PolyMeshPart {
    Mesh mesh;
    std::vector<Patch> patches;
    Format points_format = Format::ascii;
    std::int64_t num_faces = 0;
    std::vector<NodeId> processor_nodes;  // the nodes of the processor patches' faces, sorted, each once
    /// Per marker of `mesh`: its patch (an index into `patches`). Every patch
    /// but the processor ones is a marker; so is each processorCyclic patch,
    /// under its own name (read_openfoam_decomposed puts its faces back into
    /// its referPatch).
    std::vector<std::size_t> marker_patch;
};
PolyMeshPart read_poly_mesh_part(const std::filesystem::path& dir, const PolyMeshFiles& files, bool processor_patches);
/// The same, freeing each file's text once it is parsed (the faces, the
/// largest, before the cells are built): a lower peak of memory.
PolyMeshPart read_poly_mesh_part(const std::filesystem::path& dir, PolyMeshFiles&& files, bool processor_patches);

/// The PolyMeshPart of a polyMesh in memory (what read_poly_mesh_part does
/// once its files are parsed; the OpenFOAM motion solver gives OpenFOAM's own
/// arrays): cells_from_faces (errors name `where`'s files and lines, or line 0
/// when where.line is empty), a marker per patch other than the processor
/// patches, and the processor patches' nodes. Throws MeshError from validate.
PolyMeshPart poly_mesh_part(PolyMesh&& pm, std::int64_t num_cells, const FaceLines& where, Format points_format);

/// The file dir/name, or dir/name.gz uncompressed (IoError when neither can be read).
std::string read_mesh_file(const std::filesystem::path& dir, const char* name);

/// read_openfoam of a decomposed case whose processors' polyMesh folders
/// are `meshes` (openfoam_processor_meshes).
/// With `time`, each processor's points are its time folder's
/// (processorN/<time>/polyMesh/points; IoError naming a missing one).
Mesh read_openfoam_decomposed(const std::vector<std::filesystem::path>& meshes, const ProgressFn& progress,
                              OpenFoamSource* source, const std::string& time = {});

/// A labelList file (a decomposed case's pointProcAddressing, ...).
std::vector<std::int32_t> read_label_list_file(const std::string& file, std::string_view content);

/// The outward faces of a cell of the neutral Mesh in VTK node order with
/// positive orientation (cell_orientation +1): node positions within the cell,
/// each face's normal (right-hand rule) pointing out of the cell.
struct FaceTable {
    int count = 0;
    std::array<int, 6> size{};
    std::array<std::array<int, 4>, 6> node{};
};
const FaceTable& outward_faces(CellType type);

/// True when the n nodes `b` are the n nodes `a` rotated (the same cycle).
bool same_cycle(const NodeId* a, const NodeId* b, int n);

/// A cell given by its outward faces (at most 6 faces of at most 4 nodes).
struct CellFaces {
    int count = 0;
    std::array<int, 6> size{};
    std::array<std::array<NodeId, 4>, 6> node{};
};

/// Why order_cell found no cell.
enum class CellShape : std::uint8_t { ok, polyhedron, not_closed };

/// A cell of the neutral Mesh from its outward faces.
struct OrderedCell {
    CellShape shape = CellShape::polyhedron;
    CellType type = CellType::tetrahedron;
    std::array<NodeId, 8> node{};
};

/// The tetrahedron, pyramid, prism or hexahedron whose outward faces are
/// `faces`, in VTK node order with positive orientation and a canonical
/// first node (docs/OPENFOAM.md): tetrahedron and hexahedron start at their
/// smallest node id, followed by its smallest neighbour; a prism starts at its
/// smallest node id, its first triangle being the one holding that node; a
/// pyramid's base starts at the base's smallest node id. The result depends
/// only on the faces as cycles, not on their order nor on their first nodes.
/// `polyhedron` when the faces' count and sizes are not those of one of the
/// four types; `not_closed` when they are but do not close such a cell.
OrderedCell order_cell(const CellFaces& faces);

/// Appends the polyhedron of outward faces `rings` (sizes: their node counts)
/// in a canonical form that depends only on its faces as cycles: each face
/// starts at its smallest node id, and the faces are sorted (as sequences of
/// node ids). A polyMesh written from it and read back gives it again, and a
/// decomposed case's processors give the serial case's cells.
void push_canonical_polyhedron(std::span<const NodeId> rings, std::span<const int> sizes, ElementList& out);

/// Appends the cell whose outward faces are `rings`: the tetrahedron,
/// pyramid, prism or hexahedron order_cell makes of them, else (other faces,
/// or faces that do not close such a cell) push_canonical_polyhedron's.
void push_cell_from_faces(std::span<const NodeId> rings, std::span<const int> sizes, ElementList& out);

/// The Mesh's cells from the polyMesh (cell c: the faces that c owns or
/// neighbours): tetrahedra, pyramids, prisms and hexahedra (order_cell), any
/// other cell a polyhedron with its faces pointing out of it
/// (push_canonical_polyhedron). Throws ParseError naming a line of one of its
/// faces when a cell's faces do not close it.
ElementList cells_from_faces(const PolyMesh& mesh, std::int64_t num_cells, const FaceLines& where);

/// The polyMesh of a 3D Mesh: internal faces from the cells (owner < neighbour,
/// sorted by owner then neighbour, oriented out of the owner), then one patch
/// per marker (its elements in order, each oriented out of the mesh and
/// starting at the element's first node), then the patch "defaultFaces" when
/// some boundary faces are in no marker. Throws MeshError for a 2D mesh, a face
/// shared by more than two cells, two cells sharing a face with the same
/// orientation (one of them is inverted), a marker element that is not a
/// boundary face of the cells, or a boundary face in two markers.
/// Also throws MeshError when the polyMesh does not fit check_label_size.
PolyMesh faces_from_cells(const Mesh& mesh);

/// The polyMesh files dgwarp writes hold 32-bit labels (Debian's OpenFOAM,
/// WM_LABEL_SIZE=32): cell numbers in owner and neighbour, and in a binary
/// faces file the offsets of its faceCompactList. Throws MeshError, naming
/// the count, when `cells` or `face_node_entries` exceeds 2^31 - 1.
void check_label_size(std::int64_t cells, std::int64_t face_node_entries);

}  // namespace dgwarp::foam
