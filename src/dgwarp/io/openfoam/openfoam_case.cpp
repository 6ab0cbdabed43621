// OpenFOAM case folders (openfoam.hpp): where the polyMesh files are, reading
// them (compressed too) and writing them.
#include <zlib.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <string>
#include <system_error>
#include <vector>

#include "dgwarp/core/atomic_write.hpp"
#include "dgwarp/core/error.hpp"
#include "dgwarp/io/openfoam/openfoam.hpp"
#include "dgwarp/io/openfoam/openfoam_poly_mesh.hpp"
#include "dgwarp/io/text_reader.hpp"

namespace dgwarp {

namespace fs = std::filesystem;

namespace {

bool is_file(const fs::path& p) {
    std::error_code ec;
    return fs::is_regular_file(p, ec);
}

/// `p` without a trailing separator ("case/" -> "case").
fs::path without_trailing_slash(fs::path p) {
    while (!p.empty() && p.filename().empty() && p.has_parent_path() && p.parent_path() != p) p = p.parent_path();
    return p;
}

bool has_mesh_file(const fs::path& dir, const char* name) {
    return is_file(dir / name) || is_file(dir / (std::string(name) + ".gz"));
}

/// The content of a gzip file, as OpenFOAM writes with writeCompression on.
std::string gunzip(const fs::path& path) {
    const std::string packed = read_file_text(path);
    // A deflate stream expands at most 1032 times; more is a damaged or hostile file.
    const std::size_t most = packed.size() * 1032 + 64;
    z_stream z{};
    if (inflateInit2(&z, 15 + 16) != Z_OK) throw IoError(path.string(), "cannot start zlib");
    z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(packed.data()));
    z.avail_in = static_cast<uInt>(packed.size());
    std::string out;
    std::vector<char> chunk(std::size_t{1} << 16);
    int rc = Z_OK;
    while (rc == Z_OK) {
        z.next_out = reinterpret_cast<Bytef*>(chunk.data());
        z.avail_out = static_cast<uInt>(chunk.size());
        rc = inflate(&z, Z_NO_FLUSH);  // Z_BUF_ERROR: no progress, the stream is truncated
        out.append(chunk.data(), chunk.size() - z.avail_out);
        if (out.size() > most) rc = Z_DATA_ERROR;
    }
    inflateEnd(&z);
    if (rc != Z_STREAM_END)
        throw ParseError(path.string(), 0, "a complete gzip stream",
                         rc == Z_OK || rc == Z_BUF_ERROR ? "a truncated one" : std::string("zlib error: ") + zError(rc));
    return out;
}

}  // namespace

bool foam::is_folder(const fs::path& p) {
    std::error_code ec;
    return fs::is_directory(p, ec);
}

using foam::is_folder;

std::string foam::read_mesh_file(const fs::path& dir, const char* name) {
    if (!is_file(dir / name) && is_file(dir / (std::string(name) + ".gz"))) return gunzip(dir / (std::string(name) + ".gz"));
    return read_file_text(dir / name);
}

fs::path find_poly_mesh(const fs::path& path) {
    if (!is_folder(path)) {
        std::error_code ec;
        throw IoError(path.string(), fs::exists(path, ec) ? "not a folder: an OpenFOAM mesh is a case or polyMesh folder"
                                                          : std::string("cannot read it: ") + std::strerror(ENOENT));
    }
    const fs::path constant = path / "constant" / "polyMesh";
    if (is_folder(constant)) {
        if (!has_mesh_file(constant, "faces"))
            throw FormatError(constant.string() + ": no faces file: this polyMesh folder holds no mesh (run blockMesh, "
                                                  "or another mesh generator, first)");
        return constant;
    }
    if (has_mesh_file(path, "faces") || has_mesh_file(path, "owner")) return path;
    // A time folder: its own polyMesh (after a topology change), or only its
    // points, with the case's constant/polyMesh.
    if (is_folder(path / "polyMesh")) {
        if (has_mesh_file(path / "polyMesh", "faces")) return path / "polyMesh";
        const fs::path case_constant =
            without_trailing_slash(fs::absolute(path).lexically_normal()).parent_path() / "constant" / "polyMesh";
        if (has_mesh_file(path / "polyMesh", "points") && has_mesh_file(case_constant, "faces")) return case_constant;
    }
    if (is_folder(path / "processor0"))
        throw FormatError(path.string() +
                          ": a decomposed case (processor* folders without constant/polyMesh): read_openfoam reads "
                          "it, find_poly_mesh finds one polyMesh");
    throw FormatError(path.string() +
                      ": not an OpenFOAM case (no constant/polyMesh folder) nor a polyMesh folder (no faces file); "
                      "dgwarp reads a folder as an OpenFOAM mesh");
}

bool is_openfoam_input(const fs::path& path) { return is_folder(path) || openfoam_decomposed_time(path).has_value(); }

bool is_openfoam_output(const fs::path& path) {
    return is_folder(path) || (!path.empty() && path.filename().empty()) || path.extension().empty();
}

fs::path openfoam_output_poly_mesh(const fs::path& path) {
    const fs::path p = without_trailing_slash(path);
    return p.filename() == "polyMesh" ? p : p / "constant" / "polyMesh";
}

fs::path openfoam_points_folder(const fs::path& path) {
    const fs::path dir = find_poly_mesh(path);
    if (is_folder(path / "polyMesh") && has_mesh_file(path / "polyMesh", "points")) return path / "polyMesh";
    return dir;
}

Mesh read_openfoam(const fs::path& path, const ProgressFn& progress, OpenFoamSource* source) {
    if (const auto meshes = openfoam_processor_meshes(path); !meshes.empty()) {
        const auto time = openfoam_decomposed_time(path);
        return foam::read_openfoam_decomposed(meshes, progress, source, time ? time->time : std::string());
    }
    const fs::path dir = find_poly_mesh(path), points_dir = openfoam_points_folder(path);
    PolyMeshFiles files;
    std::string* parts[] = {&files.points, &files.faces, &files.owner, &files.neighbour, &files.boundary};
    // The share of the reading each file takes is its share of the bytes.
    std::uintmax_t total = 0, done = 0;
    std::error_code ec;
    for (int k = 0; k < 5; ++k) {
        const auto size = fs::file_size((k == 0 ? points_dir : dir) / poly_mesh_file_names[k], ec);
        total += ec ? 0 : size;
    }
    for (int k = 0; k < 5; ++k) {
        *parts[k] = foam::read_mesh_file(k == 0 ? points_dir : dir, poly_mesh_file_names[k]);
        done += parts[k]->size();
        if (progress && total > 0) progress(std::min(1.0, static_cast<double>(done) / static_cast<double>(total)));
    }
    // As read_openfoam_files, each file's text freed once parsed (a lower peak of memory).
    foam::PolyMeshPart part = foam::read_poly_mesh_part(dir, std::move(files), false);
    if (source) {
        source->points_format = part.points_format;
        source->patches.clear();
        for (const foam::Patch& patch : part.patches) source->patches.push_back(patch.info);
        source->poly_mesh = dir;
        source->zone_files.clear();
        for (const char* zone : {"cellZones", "faceZones", "pointZones"})
            for (const std::string& name : {std::string(zone), std::string(zone) + ".gz"})
                if (is_file(dir / name)) source->zone_files.push_back(name);
        source->num_points = part.mesh.num_points();
        source->num_cells = part.mesh.cells.size();
    }
    Mesh mesh = std::move(part.mesh);
    if (progress) progress(1.0);
    return mesh;
}

void write_openfoam(const fs::path& path, const Mesh& mesh, const OpenFoamWriteOptions& options) {
    const PolyMeshFiles files = write_openfoam_files(mesh, options);  // throws before anything is written
    const fs::path dir = openfoam_output_poly_mesh(path);
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec) throw IoError(dir.string(), "cannot create this folder: " + ec.message());
    const std::string* parts[] = {&files.points, &files.faces, &files.owner, &files.neighbour, &files.boundary};
    for (int k = 0; k < 5; ++k)
        write_file_atomically(dir / poly_mesh_file_names[k], [&](std::ostream& out) { out << *parts[k]; });
    // The source's cell and point zones hold for a mesh of its cells and points (not its face zones).
    const OpenFoamSource* source = options.source;
    if (!source || source->poly_mesh.empty() || source->num_points != mesh.num_points() ||
        source->num_cells != mesh.cells.size() || fs::equivalent(source->poly_mesh, dir, ec))
        return;
    for (const std::string& name : source->zone_files) {
        if (name.starts_with("faceZones")) continue;
        const std::string bytes = read_file_text(source->poly_mesh / name);
        write_file_atomically(dir / name, [&](std::ostream& out) { out << bytes; });
    }
}

void write_openfoam_points(const fs::path& file, std::span<const double> points, foam::Format format,
                           const std::string& location) {
    const std::string text = openfoam_points_text(points, format, location);
    std::error_code ec;
    fs::create_directories(file.parent_path(), ec);
    if (ec) throw IoError(file.parent_path().string(), "cannot create this folder: " + ec.message());
    write_file_atomically(file, [&](std::ostream& out) { out << text; });
}

OpenFoamPointsFile openfoam_points_file(const fs::path& out, const std::string& time) {
    const fs::path p = without_trailing_slash(out);
    if (p.filename() == "polyMesh") {
        const std::string parent = p.parent_path().filename().string();
        return {p / "points", (parent.empty() ? std::string("constant") : parent) + "/polyMesh"};
    }
    return {p / time / "polyMesh" / "points", time + "/polyMesh"};
}

void copy_poly_mesh(const fs::path& from, const fs::path& to, const std::vector<std::string>& except) {
    std::error_code ec;
    fs::create_directories(to, ec);
    if (ec) throw IoError(to.string(), "cannot create this folder: " + ec.message());
    std::vector<fs::path> files;
    for (const auto& entry : fs::directory_iterator(from, ec))
        if (entry.is_regular_file() &&
            std::find(except.begin(), except.end(), entry.path().filename().string()) == except.end())
            files.push_back(entry.path());
    if (ec) throw IoError(from.string(), "cannot list this folder: " + ec.message());
    std::sort(files.begin(), files.end());
    for (const fs::path& file : files) {
        const std::string bytes = read_file_text(file);
        write_file_atomically(to / file.filename(), [&](std::ostream& out) { out << bytes; });
    }
}

}  // namespace dgwarp

namespace dgwarp {

std::vector<OpenFoamPatchType> openfoam_patch_types(const std::filesystem::path& poly_mesh) {
    std::string text;
    try {
        text = foam::read_mesh_file(poly_mesh, "boundary");
    } catch (const Error&) {
        return {};
    }
    // Words and the characters { } ; outside comments; a word before '{' at
    // the top level names a dictionary (FoamFile, or a patch), "type" in it
    // gives the patch's type.
    std::vector<OpenFoamPatchType> patches;
    std::string word, last_word;
    int depth = 0;
    bool after_type = false;
    const auto flush = [&] {
        if (word.empty()) return;
        if (depth == 1 && after_type && !patches.empty()) patches.back().type = word;
        after_type = depth == 1 && word == "type";
        last_word = std::move(word);
        word.clear();
    };
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (c == '/' && i + 1 < text.size() && text[i + 1] == '/') {
            flush();
            while (i < text.size() && text[i] != '\n') ++i;
        } else if (c == '/' && i + 1 < text.size() && text[i + 1] == '*') {
            flush();
            const std::size_t end = text.find("*/", i + 2);
            i = end == std::string::npos ? text.size() : end + 1;
        } else if (c == '{') {
            flush();
            if (depth++ == 0 && last_word != "FoamFile") patches.push_back({last_word, ""});
        } else if (c == '}') {
            flush();
            depth = std::max(0, depth - 1);
        } else if (c == ';' || std::isspace(static_cast<unsigned char>(c)) || c == '(' || c == ')') {
            flush();
            if (c == ';') after_type = false;
        } else {
            word += c;
        }
    }
    return patches;
}

}  // namespace dgwarp
