#include "dgwarp/io/cgns/cgns_file.hpp"

#include <cgns_io.h>
#include <cgnslib.h>

#include <cstdio>
#include <fstream>
#include <system_error>
#include <utility>
#include <vector>

#include "dgwarp/core/error.hpp"
#include "dgwarp/io/gmsh/gmsh_element_types.hpp"

namespace dgwarp::cgns {

namespace {

/// libcgns prints its warnings (and, without a handler, its errors) on the
/// terminal; dgwarp reports failures through exceptions with cg_get_error's
/// message instead.
void quiet_handler(int, char*) {}

void install_quiet_handler() {
    static const bool installed = [] {
        cg_configure(CG_CONFIG_ERROR, reinterpret_cast<void*>(&quiet_handler));
        return true;
    }();
    (void)installed;
}

/// libcgns takes any file that is not HDF5 for ADF, and its ADF layer asserts
/// (aborting the program) on some damaged headers; it also reads an ADF file
/// cut short as zeros where its data was. So a file reaches libcgns only when
/// it begins with HDF5's signature (at 0 or a user block of 512, 1024, ...
/// bytes), or with an ADF header whose tags are in place and whose end of file
/// (after "AdF4": the root node's and the end's block and offset, in
/// hexadecimal) the file reaches, and whose format bytes are IEEE's.
void check_file_kind(const std::filesystem::path& path, const std::string& name) {
    std::error_code ec;
    const std::uintmax_t size = std::filesystem::file_size(path, ec);
    std::ifstream in(path, std::ios::binary);
    char header[256] = {};
    in.read(header, sizeof header);
    const std::string text(header, static_cast<std::size_t>(in.gcount()));
    static const std::string hdf5_signature("\x89HDF\r\n\x1a\n", 8);
    for (std::uintmax_t at = 0; at + 8 <= size && at <= (std::uintmax_t{1} << 40); at = at ? 2 * at : 512) {
        std::string signature(8, '\0');
        in.clear();
        in.seekg(static_cast<std::streamoff>(at));
        in.read(signature.data(), 8);
        if (in.gcount() == 8 && signature == hdf5_signature) return;
    }
    const auto not_cgns = [&](const std::string& why) {
        return IoError(name, "cannot open as a CGNS file: " + why);
    };
    if (text.find("ADF Database Version") != 4) throw not_cgns("it is neither an HDF5 nor an ADF file");
    std::size_t at = 0;
    for (const char* tag : {"AdF0", "AdF1", "AdF2", "AdF3", "AdF4", "AdF5"}) {
        at = text.find(tag, at);
        if (at == std::string::npos) throw not_cgns(std::string("its ADF header is damaged (no ") + tag + ")");
    }
    // Bytes 100 and 101: the numeric format (IEEE big or little endian) and
    // the pointer size (64 or 32 bits), 'B' or 'L' each. ADF asserts (aborting
    // the program) that neither is 0, and any other value would read the file
    // in a format it was not written in.
    const auto ieee = [](char c) { return c == 'B' || c == 'L'; };
    if (text.size() < 102 || !ieee(text[100]) || !ieee(text[101]))
        throw not_cgns("its ADF header is damaged (its numeric format and pointer size are not 'B' or 'L')");
    const std::size_t pointers = text.find("AdF4") + 4;
    if (pointers + 48 > text.size() ||
        text.substr(pointers, 48).find_first_not_of("0123456789abcdefABCDEF") != std::string::npos)
        throw not_cgns("its ADF header is damaged (its node pointers are not hexadecimal)");
    const std::uintmax_t block = std::stoull(text.substr(pointers + 12, 8), nullptr, 16);
    const std::uintmax_t offset = std::stoull(text.substr(pointers + 20, 4), nullptr, 16);
    const std::uintmax_t end = block * 4096 + offset;
    if (!ec && size <= end)
        throw not_cgns("it is cut short (its ADF header says it ends at byte " + std::to_string(end + 1) + ", it has " +
                       std::to_string(size) + ")");
}

/// A node's name or data type as read from a (maybe damaged) file, for a message.
std::string printable(const char* text) {
    std::string s(text);
    for (char& c : s)
        if (static_cast<unsigned char>(c) < 32 || static_cast<unsigned char>(c) > 126) c = '?';
    return s;
}

/// libcgns 3.4 reads a node's data (cgi_read_node) into a buffer it allocates
/// only for these data types, spelled exactly so; for any other (a damaged
/// "c1", ADF's "B1", "U4", "X4", ...) it reads the data through a pointer it
/// never set, which may be memory it freed just before (a heap
/// use-after-free, e.g. through the BC type's string while reading a BC's
/// GridLocation). A valid file holds no other type (CGNS 3.4's DataType_t).
bool libcgns_reads_data_type(const std::string& type) {
    for (const char* known : {"MT", "I4", "I8", "R4", "R8", "C1"})
        if (type == known) return true;
    return false;
}

/// libcgns allocates, while opening a file, as many values as a node's
/// header says its children or data hold, and ends the process (exit) when
/// the allocation fails: a damaged header (a child count of 2^31) would end
/// the program instead of raising an error. So the file's tree is walked
/// first through libcgns's lower layer (cgio), refusing a node with more
/// children or data values than the file could hold (`most`), or of a data
/// type libcgns cannot read (above). Errors name the node's path.
void check_tree(const std::filesystem::path& path, const std::string& name, std::uintmax_t file_size) {
    const std::int64_t most = 64 * static_cast<std::int64_t>(file_size) + 4096;
    int cgio = 0;
    if (cgio_open_file(path.c_str(), CGIO_MODE_READ, CGIO_FILE_NONE, &cgio) != CG_OK) {
        char message[CGIO_MAX_ERROR_LENGTH + 1] = {};
        cgio_error_message(message);
        throw IoError(name, std::string("cannot open as a CGNS file: ") + message);
    }
    struct Closer {
        int cgio;
        ~Closer() { cgio_close_file(cgio); }
    } closer{cgio};
    auto damaged = [&](const std::string& node, const std::string& what) {
        return IoError(name, "cannot open as a CGNS file: it is damaged (" + (node.empty() ? "/" : node) + ": " + what + ")");
    };
    double root = 0;
    if (cgio_get_root_id(cgio, &root) != CG_OK) throw damaged("", "no root node");
    struct Node {
        double id;
        int depth;
        std::string path;  // "/Base/Zone/ZoneBC/wall"; "" for the root
    };
    std::vector<Node> stack{{root, 0, ""}};
    std::int64_t visited = 0;
    while (!stack.empty()) {
        const Node node = std::move(stack.back());
        stack.pop_back();
        const double id = node.id;
        if (++visited > most / 16 || node.depth > 64)
            throw damaged(node.path, "more nodes than the file can hold, or a loop");
        // ADF returns up to 32 characters (and a terminator) for a data type.
        char type[CGIO_MAX_NAME_LENGTH + 1] = {};
        if (cgio_get_data_type(cgio, id, type) == CG_OK && !libcgns_reads_data_type(type))
            throw damaged(node.path, "data of type '" + printable(type) + "'; CGNS's types are MT, I4, I8, R4, R8 and C1");
        int ndims = 0;
        cgsize_t dims[CGIO_MAX_DIMENSIONS] = {};
        if (cgio_get_dimensions(cgio, id, &ndims, dims) == CG_OK) {
            if (ndims < 0 || ndims > CGIO_MAX_DIMENSIONS)
                throw damaged(node.path, "data of " + std::to_string(ndims) + " dimensions");
            std::int64_t values = ndims > 0 ? 1 : 0;
            for (int d = 0; d < ndims; ++d) {
                if (dims[d] < 0 || (dims[d] > 0 && values > most / dims[d]))
                    throw damaged(node.path, "data larger than the file");
                values *= dims[d];
            }
            if (values > most) throw damaged(node.path, "data larger than the file");
        }
        int children = 0;
        if (cgio_number_children(cgio, id, &children) != CG_OK) throw damaged(node.path, "its children cannot be counted");
        if (children < 0 || children > most / 16)
            throw damaged(node.path, std::to_string(children) + " children");
        std::vector<double> ids(static_cast<std::size_t>(children));
        int got = 0;
        if (children > 0 && (cgio_children_ids(cgio, id, 1, children, &got, ids.data()) != CG_OK || got != children))
            throw damaged(node.path, "its children cannot be read");
        for (double child : ids) {
            char child_name[CGIO_MAX_NAME_LENGTH + 1] = {};
            if (cgio_get_name(cgio, child, child_name) != CG_OK) throw damaged(node.path, "a child's name cannot be read");
            stack.push_back({child, node.depth + 1, node.path + "/" + printable(child_name)});
        }
        if (id != root) cgio_release_id(cgio, id);
    }
}

}  // namespace

std::string library_error() {
    const char* m = cg_get_error();
    return m && *m ? m : "unknown libcgns error";
}

namespace {
std::recursive_mutex& library_mutex() {
    static std::recursive_mutex m;
    return m;
}
}  // namespace

OpenFile::OpenFile(const std::filesystem::path& path, int mode, std::string shown_name)
    : lock_(library_mutex()), name_(std::move(shown_name)) {
    install_quiet_handler();
    if (mode == CG_MODE_READ || mode == CG_MODE_MODIFY) {
        std::error_code ec;
        if (!std::filesystem::exists(path, ec)) throw IoError(name_, "No such file or directory");
        if (!std::filesystem::is_regular_file(path, ec)) throw IoError(name_, "is not a regular file");
        // libcgns opens an empty file in modify mode as a new one: refuse it here.
        if (std::filesystem::file_size(path, ec) == 0) throw IoError(name_, "is empty, not a CGNS file");
    }
    if (mode != CG_MODE_WRITE) {
        check_file_kind(path, name_);
        std::error_code ec;
        check_tree(path, name_, std::filesystem::file_size(path, ec));
    }
    int fn = -1;
    if (cg_open(path.c_str(), mode, &fn) != CG_OK) {
        const std::string reason = library_error();
        // libcgns numbers the file before reading it and leaves it open when
        // reading its tree fails; cg_close would then free the half-read tree
        // (and crashes on some damaged files), so only the file itself is
        // closed (else libcgns's table of open files fills up). The half-read
        // tree is lost memory (tests/lsan.supp).
        int cgio = 0;
        if (fn >= 0 && cg_get_cgio(fn, &cgio) == CG_OK && cgio > 0) cgio_close_file(cgio);
        throw IoError(name_, (mode == CG_MODE_WRITE ? "cannot create a CGNS file: " : "cannot open as a CGNS file: ") +
                                 reason);
    }
    fn_ = fn;
}

OpenFile::~OpenFile() {
    if (fn_ >= 0) cg_close(fn_);
}

void OpenFile::close() {
    const int fn = fn_;
    fn_ = -1;
    if (cg_close(fn) != CG_OK) throw IoError(name_, "cannot close the CGNS file: " + library_error());
}

void OpenFile::read_check(int status, const std::string& what) const {
    if (status != CG_OK) throw ParseError(name_, 0, what, library_error());
}

void OpenFile::write_check(int status, const std::string& what) const {
    if (status != CG_OK) throw IoError(name_, "cannot write " + what + ": " + library_error());
}

std::string element_type_name(int type) {
    if (type < 0 || type > CGNS_ENUMV(NFACE_n) + 1) return "element type " + std::to_string(type);
    return cg_ElementTypeName(static_cast<CGNS_ENUMT(ElementType_t)>(type));
}

int element_type(CellType t) {
    switch (t) {
        case CellType::vertex: return CGNS_ENUMV(NODE);
        case CellType::line: return CGNS_ENUMV(BAR_2);
        case CellType::triangle: return CGNS_ENUMV(TRI_3);
        case CellType::quadrilateral: return CGNS_ENUMV(QUAD_4);
        case CellType::tetrahedron: return CGNS_ENUMV(TETRA_4);
        case CellType::hexahedron: return CGNS_ENUMV(HEXA_8);
        case CellType::prism: return CGNS_ENUMV(PENTA_6);
        case CellType::pyramid: return CGNS_ENUMV(PYRA_5);
        case CellType::polygon: return CGNS_ENUMV(NGON_n);
        case CellType::polyhedron: return CGNS_ENUMV(NFACE_n);
    }
    return CGNS_ENUMV(ElementTypeNull);
}

bool cell_type_of(int cgns_type, CellType& t) {
    for (CellType c : all_cell_types)  // the fixed types: NGON_n and NFACE_n are sections of their own
        if (!has_any_node_count(c) && element_type(c) == cgns_type) {
            t = c;
            return true;
        }
    return false;
}

int cgns_index_of_vtk_node(CellType t, int vtk_index) {
    return msh::gmsh_index_of_vtk_node(t)[static_cast<std::size_t>(vtk_index)];
}

}  // namespace dgwarp::cgns
