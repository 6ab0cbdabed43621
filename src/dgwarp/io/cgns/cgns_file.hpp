#pragma once
// Internal to the CGNS reader and writer (cgns.hpp): a file open in libcgns,
// closed on every path, and the checks that turn libcgns's failures into
// dgwarp's errors naming the file.
#include <filesystem>
#include <mutex>
#include <string>

#include "dgwarp/mesh/cell_type.hpp"

namespace dgwarp::cgns {

/// A file open in libcgns (cg_open); closed by the destructor when close() was not called.
class OpenFile {
public:
    /// Opens `path` with `mode` (CG_MODE_READ, CG_MODE_WRITE, CG_MODE_MODIFY);
    /// errors name `shown_name` (the file the user gave). Throws IoError with
    /// libcgns's reason when the file cannot be opened.
    OpenFile(const std::filesystem::path& path, int mode, std::string shown_name);
    ~OpenFile();
    OpenFile(const OpenFile&) = delete;
    OpenFile& operator=(const OpenFile&) = delete;

    int id() const { return fn_; }
    const std::string& name() const { return name_; }

    /// Throws ParseError(name, 0, what, libcgns's message) unless status is CG_OK.
    void read_check(int status, const std::string& what) const;
    /// Throws IoError(name, "cannot write " + what + ": " + libcgns's message) unless status is CG_OK.
    void write_check(int status, const std::string& what) const;
    /// Closes the file, checking that libcgns wrote it out.
    void close();

private:
    /// libcgns keeps process-wide state (its table of open files, its last
    /// error): one file is open at a time in the process, whatever thread
    /// opens it (recursive: one thread may open a second, e.g. the input of
    /// an output it copies). Held from before the open to after the close.
    std::unique_lock<std::recursive_mutex> lock_;
    int fn_ = -1;
    std::string name_;
};

/// libcgns's message for its last failure.
std::string library_error();

/// libcgns's name of an element type ("TETRA_4").
std::string element_type_name(int type);

/// The CGNS ElementType_t of a linear CellType (TETRA_4, ...; NODE for vertex).
int element_type(CellType t);

/// The CellType of a CGNS element type, false for one dgwarp does not hold.
bool cell_type_of(int cgns_type, CellType& t);

/// Position in the CGNS element of each VTK-ordered node: CGNS orders its
/// linear elements as Gmsh does (a prism's first triangle turns the other way than VTK's).
int cgns_index_of_vtk_node(CellType t, int vtk_index);

}  // namespace dgwarp::cgns
