#pragma once
// OpenFOAM polyMesh folders (constant/polyMesh: points, faces, owner,
// neighbour, boundary), ascii and binary. What is read and written, and
// the limits: docs/OPENFOAM.md.
//
// Reading: the cells are rebuilt from the faces, owner and neighbour lists as
// tetrahedra, pyramids, prisms and hexahedra in VTK node order with positive
// orientation, any other cell (snappyHexMesh's split hexahedra, tetWedges) a
// polyhedron with its faces; cell i is OpenFOAM's cell i and point i
// OpenFOAM's point i. Every patch becomes a marker of the same name, its
// faces (triangles, quadrilaterals and polygons, in file order, nodes as
// written: their normals point out of the mesh) its elements.
// OpenFOAM meshes are 3D, also those of 2D cases (one cell thick): dim is 3.
//
// Writing: write_openfoam writes a whole polyMesh from any 3D Mesh; for a mesh
// read from a polyMesh, write_openfoam_points writes new points alone, in the
// format they were read in, leaving every other file as it is.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "dgwarp/core/progress.hpp"
#include "dgwarp/io/openfoam/foam_file.hpp"
#include "dgwarp/mesh/mesh.hpp"

namespace dgwarp {

/// A patch's dictionary in the boundary file, besides nFaces and startFace.
struct OpenFoamPatch {
    std::string type = "patch";  // "wall", "patch", "empty", "symmetryPlane", "cyclic", ...
    /// The other entries ("inGroups 1(wall);", "neighbourPatch right;"), one per
    /// line, as written (a cyclic patch needs them).
    std::vector<std::string> entries;

    bool operator==(const OpenFoamPatch&) const = default;
};

/// One processor of a decomposed case read as one mesh.
struct OpenFoamProcessor {
    std::filesystem::path poly_mesh;                   // CASE/processorN/constant/polyMesh
    foam::Format points_format = foam::Format::ascii;  // the format of its points file
    std::vector<NodeId> points;                        // its pointProcAddressing: the mesh's id of each of its points
};

/// What read_openfoam keeps besides the mesh, so that its points can be
/// written back in place and a whole polyMesh written from it keeps its patches.
struct OpenFoamSource {
    std::filesystem::path poly_mesh;                   // the polyMesh folder read ("" when read from memory or decomposed)
    foam::Format points_format = foam::Format::ascii;  // the format of its points file (processor 0's)
    std::vector<OpenFoamPatch> patches;                // one per marker, in marker order
    std::vector<OpenFoamProcessor> processors;         // a decomposed case's, in order; empty for one polyMesh
    /// The zone files of the polyMesh folder read ("cellZones", "faceZones",
    /// "pointZones", or with ".gz"), as found there; a whole polyMesh written
    /// from a mesh of as many points and cells keeps the cell and point zones
    /// (write_openfoam), not the face zones (its faces are numbered anew).
    std::vector<std::string> zone_files;
    std::size_t num_points = 0, num_cells = 0;  // of the mesh read
};

/// The five files of a polyMesh, in memory.
struct PolyMeshFiles {
    std::string points, faces, owner, neighbour, boundary;
};

/// The names of those files, in that order.
inline constexpr const char* poly_mesh_file_names[] = {"points", "faces", "owner", "neighbour", "boundary"};

/// The polyMesh folder of `path`: path/constant/polyMesh for a case folder,
/// `path` itself when it holds the polyMesh files (faces, owner). Throws
/// FormatError for a decomposed case (processor* folders and no
/// constant/polyMesh: read_openfoam reads it, through
/// openfoam_processor_meshes) or a folder that is neither; IoError when
/// `path` is not a folder.
std::filesystem::path find_poly_mesh(const std::filesystem::path& path);

/// The folder the points of the mesh at `path` are read from: a time folder's
/// `polyMesh` when `path` is a time folder holding `polyMesh/points` (a
/// deformed mesh dgwarp or a solver wrote: CASE/0.5), else find_poly_mesh(path).
std::filesystem::path openfoam_points_folder(const std::filesystem::path& path);

/// The processors' polyMesh folders (CASE/processor0/constant/polyMesh,
/// processor1, ...) when `path` is a decomposed case: a case folder without
/// constant/polyMesh whose processorN folders, N = 0, 1, ... without a gap,
/// hold polyMeshes; empty for any other path. Throws FormatError for a
/// collated decomposition (one processors<N> folder).
/// For CASE/T, a time of a decomposed case (below), the case's processors.
std::vector<std::filesystem::path> openfoam_processor_meshes(const std::filesystem::path& path);

/// A time of a decomposed case, given as CASE/T: CASE is a decomposed case
/// (processor folders, no constant/polyMesh), CASE/T is no mesh folder (it
/// may not exist: decomposed times are processorN/T), and
/// CASE/processor0/T/polyMesh holds points (what `deform` and a parallel
/// moving-mesh run write). read_openfoam reads the processors' meshes with
/// their time T points.
struct OpenFoamDecomposedTime {
    std::filesystem::path case_folder;
    std::string time;
};
std::optional<OpenFoamDecomposedTime> openfoam_decomposed_time(const std::filesystem::path& path);

/// The processorN folders of a decomposed case in its usual layout: `path`
/// holds constant/polyMesh (which read_openfoam reads and deform writes) and
/// processor folders beside it (which a parallel OpenFOAM run reads), sorted
/// by N; empty when `path` has no constant/polyMesh or no processor folder.
std::vector<std::filesystem::path> openfoam_unread_processor_folders(const std::filesystem::path& path);

/// One processor of a decomposed case, read alone (under mpirun each process
/// reads its own: docs/MPI.md). `mesh` is its polyMesh as read_openfoam reads
/// a polyMesh, in the processor's numbering: its markers are the patches
/// other than processor patches (every processor has every patch, maybe with
/// no face), and each cell's nodes are in the order that reading the whole
/// decomposed case gives the cell (so that per-cell quality has the same
/// bits).
struct OpenFoamProcessorMesh {
    Mesh mesh;
    std::vector<std::int64_t> point_ids;  // pointProcAddressing: the case's id of each point
    std::vector<std::int64_t> cell_ids;   // cellProcAddressing: the case's id of each cell
    std::vector<NodeId> interface_nodes;  // the points on processor patches (held by other processors too), sorted
    foam::Format points_format = foam::Format::ascii;  // of its points file
    std::vector<OpenFoamPatch> patches;                // one per marker
};

/// Reads the processor polyMesh folder `poly_mesh`
/// (CASE/processorN/constant/polyMesh) and its pointProcAddressing and
/// cellProcAddressing. Errors as read_openfoam's, naming the processor's files.
OpenFoamProcessorMesh read_openfoam_processor(const std::filesystem::path& poly_mesh);

/// The decomposition's files read besides the five polyMesh files, in each
/// processor's polyMesh folder.
inline constexpr const char* processor_addressing_file_names[] = {"pointProcAddressing", "faceProcAddressing",
                                                                  "cellProcAddressing"};

/// A patch's name and type, as a polyMesh's boundary file gives them.
struct OpenFoamPatchType {
    std::string name, type;
};

/// The patches of the boundary file in the polyMesh folder `poly_mesh`,
/// scanned for their names and types only (no check of their faces: a quick
/// look, e.g. at one processor of a decomposed case before deciding how to
/// read it); empty when the file cannot be read.
std::vector<OpenFoamPatchType> openfoam_patch_types(const std::filesystem::path& poly_mesh);

/// The processor folders beside constant/polyMesh in the case `path`
/// (decomposePar's usual layout: openfoam_unread_processor_folders) as
/// processors of the mesh read from constant/polyMesh, of `num_points`
/// points: each one's polyMesh folder, points format and pointProcAddressing
/// (each processor's polyMesh is read). Throws as read_openfoam_processor,
/// and ParseError naming the addressing file for a point label not below
/// `num_points` (a decomposition of another mesh).
std::vector<OpenFoamProcessor> read_processors_beside(const std::filesystem::path& path, std::size_t num_points);

/// Processor p's points (its num_points × 3, row-major) taken from the
/// whole mesh's `points` (num_points × 3) through p.points.
std::vector<double> processor_points(const OpenFoamProcessor& p, std::span<const double> points);

/// True when `path` is a folder or a time of a decomposed case
/// (openfoam_decomposed_time): read_mesh reads it as an OpenFOAM case.
bool is_openfoam_input(const std::filesystem::path& path);

/// True when write_mesh writes `path` as an OpenFOAM case folder: it is a
/// folder, its name ends in '/', or it has no extension.
bool is_openfoam_output(const std::filesystem::path& path);

/// Where write_openfoam puts the polyMesh of `path`: `path` itself when its
/// last name is "polyMesh", else path/constant/polyMesh.
std::filesystem::path openfoam_output_poly_mesh(const std::filesystem::path& path);

/// Reads the polyMesh of the case or polyMesh folder `path` (find_poly_mesh),
/// or the processors of a decomposed case (openfoam_processor_meshes) as one
/// mesh: point i and cell i are the reconstructed case's (pointProcAddressing,
/// cellProcAddressing), the markers are the patches other than processor
/// patches, their faces in the reconstructed case's order (faceProcAddressing);
/// the result equals reading the reconstructed case. ParseError when the
/// processors disagree (a shared point at two places, a cell or point missing
/// or given twice, different patches).
/// Fills `source` (when given) with what a write back needs.
/// Throws IoError when a file cannot be read (compressed files, `points.gz`,
/// are read too); ParseError naming the file and line for malformed content:
/// a truncated file, counts that do not match (owner's size is not the
/// number of faces, patches that do not cover the boundary faces in order), a
/// face with fewer than 3 points or a point index out of range, an owner or
/// neighbour out of range, a cell whose faces do not close it; FormatError for
/// binary files of another label or scalar size; MeshError when
/// the result fails validate(). `progress` gets the fraction of the bytes read.
Mesh read_openfoam(const std::filesystem::path& path, const ProgressFn& progress = {},
                   OpenFoamSource* source = nullptr);

/// The same from the files' bytes in memory; errors name dir/points, dir/faces, ...
Mesh read_openfoam_files(const std::filesystem::path& dir, const PolyMeshFiles& files,
                         OpenFoamSource* source = nullptr);

struct OpenFoamWriteOptions {
    foam::Format format = foam::Format::ascii;
    /// A source whose patches are the mesh's markers (same count): their
    /// types and entries are written instead of "type patch;".
    const OpenFoamSource* source = nullptr;
};

/// A polyMesh of a 3D mesh: points in order (ascii in shortest exact form,
/// binary as 64-bit little-endian), faces (ascii: faceList; binary:
/// faceCompactList), owner, neighbour, boundary. Faces: see
/// faces_from_cells in openfoam_poly_mesh.hpp (upper-triangular order, one patch
/// per marker, "defaultFaces" for boundary faces in no marker). Reading it back
/// gives the mesh with each cell's nodes in the reader's order and each marker
/// element turned to point out of the mesh (docs/OPENFOAM.md). Throws
/// MeshError, before writing anything, for a 2D mesh or one that no polyMesh
/// can hold (see faces_from_cells).
PolyMeshFiles write_openfoam_files(const Mesh& mesh, const OpenFoamWriteOptions& options = {});

/// write_openfoam_files into openfoam_output_poly_mesh(path), creating the
/// folders; each file is written atomically (write_file_atomically).
void write_openfoam(const std::filesystem::path& path, const Mesh& mesh, const OpenFoamWriteOptions& options = {});

/// A points file: num_points × 3 coordinates (row-major) in `format`;
/// `location` is the header's ("constant/polyMesh", "0.5/polyMesh").
std::string openfoam_points_text(std::span<const double> points, foam::Format format, const std::string& location);

/// openfoam_points_text written atomically to `file`, creating its folder.
void write_openfoam_points(const std::filesystem::path& file, std::span<const double> points, foam::Format format,
                           const std::string& location);

/// Where moved points go in the case folder `out` at time `time` (a time
/// folder's name, or "constant"): out/<time>/polyMesh/points (OpenFOAM reads
/// a time folder's points with constant/polyMesh's faces), or
/// out/constant/polyMesh/points; out/points when `out` is a polyMesh folder
/// (its name is polyMesh). `location` is the points file's header entry.
struct OpenFoamPointsFile {
    std::filesystem::path file;
    std::string location;
};
OpenFoamPointsFile openfoam_points_file(const std::filesystem::path& out, const std::string& time);

/// OpenFOAM's points of a patch (PrimitivePatch::meshPoints): each node of
/// `marker`'s elements once, in the order the elements, in order and each
/// from its first node, first name it. A point field's value on a patch lists
/// one entry per point in this order.
std::vector<NodeId> openfoam_patch_points(const Marker& marker);

/// The text of the pointVectorField file `pointDisplacement` at `location`
/// (a time folder's name, e.g. "0") that OpenFOAM's displacement motion
/// solvers read: dimensions of length, internalField uniform (0 0 0), and one
/// patch per marker of `mesh`, which must be a mesh read from the polyMesh
/// the field is for (read_openfoam: its markers are the patches, their faces
/// as the faces file has them, so that openfoam_patch_points is OpenFOAM's
/// order). A patch whose type in `patches` (one per marker, or empty: every
/// patch "patch") is a constraint type (empty, wedge, symmetryPlane, symmetry,
/// cyclic, cyclicAMI, cyclicACMI, cyclicSlip, nonuniformTransformCyclic,
/// processor, processorCyclic) gets that type; every other patch is
/// `fixedValue` with `displacement` (num_points × 3, row-major) at its
/// points: `uniform` when they are all the same, else `nonuniform
/// List<vector>` in openfoam_patch_points order (numbers in the shortest form
/// that reads back exactly). Ascii. Throws MeshError for a 2D mesh, a
/// displacement of another size, or patches of another count than the markers.
std::string openfoam_point_displacement_text(const Mesh& mesh, std::span<const double> displacement,
                                             const std::vector<OpenFoamPatch>& patches, const std::string& location);

/// Copies the regular files of the polyMesh folder `from` (points, faces,
/// owner, neighbour, boundary, zones, ...) into `to`, creating it, byte for
/// byte, each atomically; files named in `except` are left out. Sub-folders
/// (sets) are not copied.
void copy_poly_mesh(const std::filesystem::path& from, const std::filesystem::path& to,
                    const std::vector<std::string>& except = {});

}  // namespace dgwarp
