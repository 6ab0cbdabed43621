#pragma once
// Reading and writing meshes, with the format chosen by the file extension:
//   .su2  SU2 native ASCII (read, write)
//   .msh  Gmsh ASCII 4.1 or 2.2 (read both; write 4.1 by default)
//   .vtu  VTK XML unstructured grid (read: ascii, binary, appended, zlib; write:
//         binary, with markers and point and cell data; see vtu.hpp)
//   .cgns CGNS (HDF5 or ADF; read: unstructured zones of base 1, element
//         sections, BCs and families as markers; write: HDF5; see cgns.hpp)
//   a folder: an OpenFOAM case or polyMesh folder (read and write, ascii and
//         binary; see openfoam.hpp). A path without one of the extensions
//         above is one when it is a folder (input), or when it is a folder,
//         its name ends in '/' or has no extension (output).
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "dgwarp/core/progress.hpp"
#include "dgwarp/io/cgns/cgns.hpp"
#include "dgwarp/io/openfoam/openfoam.hpp"
#include "dgwarp/io/su2/su2.hpp"
#include "dgwarp/mesh/mesh.hpp"

namespace dgwarp {

struct ReadOptions {
    int zone = 1;  // SU2 multi-zone files: which zone (IZONE, 1-based) to read
};

/// A named array attached to points or cells: size() == count × components, row-major.
struct Field {
    std::string name;
    int components = 1;
    std::vector<double> values;
};

/// Extra data written by formats that can hold it (VTU); other formats ignore it.
struct MeshFields {
    std::vector<Field> point_data;  // count = mesh.num_points()
    std::vector<Field> cell_data;   // count = mesh.cells.size()
};

/// What a mesh file holds besides the mesh read from it, kept so that a
/// deformed copy in the same format keeps it too.
struct MeshExtras {
    /// An SU2 file's text around the zone read: other zones, FFD boxes,
    /// periodic data, comments (read_su2).
    std::optional<Su2Surroundings> su2;
    /// An OpenFOAM mesh's folder, points format and patch dictionaries (read_openfoam).
    std::optional<OpenFoamSource> openfoam;
    /// A CGNS file's path and zones (read_cgns): a .cgns output of a mesh with
    /// its points is a copy of that file with new coordinates (write_cgns_points).
    std::optional<CgnsSource> cgns;
};

struct WriteOptions {
    int gmsh_version = 41;  // 41 (MSH 4.1) or 22 (MSH 2.2)
    /// OpenFOAM output: ascii or binary; unset: the format of an OpenFOAM input
    /// (extras), else ascii.
    std::optional<foam::Format> foam_format;
    /// The input's extras: an SU2 output then keeps them around the mesh
    /// (write_su2 with surroundings), a CGNS output of a CGNS input is a copy
    /// of the input with the mesh's coordinates (write_cgns_points); other
    /// formats cannot hold them (dropped_extras says what is lost).
    const MeshExtras* extras = nullptr;
};

/// Reads a mesh; the format comes from the extension (a folder: OpenFOAM). Throws FormatError for
/// an unsupported extension or a zone other than 1 asked of a format without zones (not SU2), IoError when the file cannot be read, ParseError
/// (file, line, what was expected) when it is malformed, and MeshError when
/// its content is inconsistent.
/// `progress` (core/progress.hpp) gets the fraction of the file parsed
/// (bytes read / file size, every 1% or 1 MiB, whichever is more), ending at 1.
Mesh read_mesh(const std::filesystem::path& path, const ReadOptions& options = {},
               const ProgressFn& progress = {});

/// read_mesh, also filling `extras` with what the file holds besides the mesh.
Mesh read_mesh(const std::filesystem::path& path, const ReadOptions& options, const ProgressFn& progress,
               MeshExtras& extras);

/// What of `extras` a write_mesh to `path` (format by extension) with them
/// does not keep, for a warning: e.g. {"1 other zone (IZONE=)", "FFD_NBOX= 1"}
/// when an SU2 input's surroundings go to a .vtu, {"cellZones", "pointZones"}
/// when an OpenFOAM case's zones go to another format ("faceZones" to an
/// OpenFOAM case: write_openfoam keeps the others); empty when all is kept.
std::vector<std::string> dropped_extras(const MeshExtras& extras, const std::filesystem::path& path);

/// The warning for writing a mesh read from `input` with `extras` to
/// `output`, which cannot hold them (dropped_extras; "" when nothing is
/// dropped). The CLI and the Python package print it.
std::string dropped_extras_warning(const MeshExtras& extras, const std::string& input, const std::filesystem::path& output);

/// Throws the MeshError write_mesh(path, mesh, {}, options) would throw about
/// `mesh` itself (a marker name the format cannot store, such as " lead" in
/// SU2), naming `path`, without writing anything: for commands to check their
/// outputs before the work. A CGNS output copied from a CGNS input
/// (options.extras) keeps the input's names: nothing to check.
void check_mesh_writable(const std::filesystem::path& path, const Mesh& mesh, const WriteOptions& options = {});

/// Writes a mesh atomically (temporary file, then rename); the format comes
/// from the extension. An OpenFOAM case folder (is_openfoam_output) gets a
/// whole polyMesh (write_openfoam; each file atomically), with the patch
/// dictionaries of an OpenFOAM input whose markers it has (options.extras).
void write_mesh(const std::filesystem::path& path, const Mesh& mesh, const MeshFields& fields = {},
                const WriteOptions& options = {});

/// Whether write_mesh to `path` writes the MeshFields it is given (VTU);
/// the other formats ignore them, so a caller need not make them.
bool writes_fields(const std::filesystem::path& path);

/// The extension of `path` in lower case (".su2" for "WING.SU2"): formats
/// are chosen by it without regard to case.
std::string lower_case_extension(const std::filesystem::path& path);

/// True when read_mesh / write_mesh take `path` as an OpenFOAM case or
/// polyMesh folder (see above).
bool reads_openfoam(const std::filesystem::path& path);
bool writes_openfoam(const std::filesystem::path& path);

/// The files read_mesh(path) reads: an OpenFOAM case's polyMesh files (its
/// points perhaps a time folder's; each processor's of a decomposed case),
/// else `path` itself. For the check that no output is an input.
std::vector<std::filesystem::path> mesh_input_files(const std::filesystem::path& path);

/// Checks, before the work, that write_mesh(output) can write and destroys
/// no input (`inputs`, e.g. mesh_input_files): check_output_file
/// (core/output_checks.hpp) for a file; for an OpenFOAM case folder,
/// check_output for each file written there and that the nearest existing
/// folder on its path is writable (the case folder may not exist yet).
/// UsageError (an output is an input), IoError.
void check_mesh_output(const std::filesystem::path& output, const std::vector<std::filesystem::path>& inputs);

/// The extensions read_mesh / write_mesh accept, for help texts.
std::vector<std::string> readable_extensions();
std::vector<std::string> writable_extensions();

}  // namespace dgwarp
