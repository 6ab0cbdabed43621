// Reader of OpenFOAM polyMesh files (openfoam.hpp): the five files are
// parsed into a PolyMesh (openfoam_poly_mesh.hpp), checked against each other,
// then the cells are rebuilt from the faces (openfoam_cells.cpp).
//
// Every list's size is checked against the bytes left in its file before
// anything is allocated for it (an ascii label takes at least 2 bytes, a
// point 8, a face 9; binary items their exact size), so a damaged count
// cannot make us allocate much more than the files' size.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "dgwarp/core/error.hpp"
#include "dgwarp/io/openfoam/foam_file.hpp"
#include "dgwarp/io/openfoam/openfoam.hpp"
#include "dgwarp/io/openfoam/openfoam_poly_mesh.hpp"
#include "dgwarp/io/text_reader.hpp"

namespace dgwarp {

namespace {

using foam::Scanner;

constexpr std::int64_t max_label = std::numeric_limits<std::int32_t>::max();

std::string str(std::int64_t v) { return std::to_string(v); }

/// The start of a list: its size, whether it is uniform (`N{item}`), where it began.
struct ListStart {
    std::int64_t size = 0;
    bool uniform = false;
    std::size_t line = 0;
    std::string what;  // "the 40 points of the list on line 19"

    /// "point 5 (0-based) of the 40 of the list on line 19"
    std::string item(std::string_view name, std::int64_t i) const {
        return std::string(name) + " " + str(i) + " (0-based) of the " + str(size) + " of the list on line " +
               str(static_cast<std::int64_t>(line));
    }
};

/// `N (` or `N {`; `what` names the list ("points"). In binary format the
/// next byte is the first byte of the data.
ListStart open_list(Scanner& s, const std::string& what, std::size_t min_ascii_bytes, std::size_t binary_bytes) {
    ListStart l;
    s.peek();
    l.line = s.line();
    l.what = what;
    l.size = s.list_size(what, s.binary() && binary_bytes ? binary_bytes : min_ascii_bytes);
    const char c = s.peek();
    if (c == '{') l.uniform = true;
    else if (c != '(') s.fail("'(' opening the list of " + str(l.size) + " " + what, c ? std::string(1, c) : "end of file");
    s.expect(c, "'('");
    return l;
}

void close_list(Scanner& s, const ListStart& l) {
    s.expect(l.uniform ? '}' : ')', std::string(l.uniform ? "'}'" : "')'") + " ending the list of " + str(l.size) +
                                        " " + l.what + " begun on line " + str(static_cast<std::int64_t>(l.line)));
}

/// A labelList (owner, neighbour, faceCompactList's parts); `check(i, value,
/// line)` is called on each label (line 0 for binary data).
template <class Check>
std::vector<std::int32_t> read_labels(Scanner& s, const std::string& what, Check check) {
    const ListStart l = open_list(s, what, 2, Scanner::label_bytes);
    std::vector<std::int32_t> out(static_cast<std::size_t>(l.uniform ? 0 : l.size));
    const auto put = [&](std::int64_t i, std::int64_t v, std::size_t line) {
        if (v < std::numeric_limits<std::int32_t>::min() || v > max_label)
            s.fail_at(line, l.item("label", i) + " within 32 bits", str(v));
        check(i, v, line);
        return static_cast<std::int32_t>(v);
    };
    if (l.uniform) {
        const std::size_t line = s.line();
        const std::int64_t v = s.binary() ? foam::binary_label(s.raw(Scanner::label_bytes, "a label").data())
                                          : s.integer("the value of the uniform list of " + what);
        out.resize(static_cast<std::size_t>(l.size));
        for (std::int64_t i = 0; i < l.size; ++i) out[static_cast<std::size_t>(i)] = put(i, v, line);
    } else if (s.binary()) {
        const std::string_view data = s.raw(static_cast<std::size_t>(l.size) * Scanner::label_bytes, what);
        for (std::int64_t i = 0; i < l.size; ++i)
            out[static_cast<std::size_t>(i)] = put(i, foam::binary_label(data.data() + i * Scanner::label_bytes), l.line);
    } else {
        for (std::int64_t i = 0; i < l.size; ++i) {
            s.peek();
            const std::size_t line = s.line();
            std::int64_t v = 0;
            if (!s.try_integer(v)) {  // the error, in words (built only here: lists are long)
                if (s.peek() == ')') s.fail(l.item("label", i), ")");
                s.integer(l.item("label", i));
            }
            out[static_cast<std::size_t>(i)] = put(i, v, line);
        }
    }
    close_list(s, l);
    return out;
}

/// The points file: a vectorField.
std::vector<double> read_points(Scanner& s) {
    const ListStart l = open_list(s, "points", 8, 3 * Scanner::scalar_bytes);
    std::vector<double> points(static_cast<std::size_t>(l.uniform ? 1 : l.size) * 3);
    if (s.binary()) {
        const std::int64_t n = l.uniform ? 1 : l.size;
        const std::string_view data = s.raw(static_cast<std::size_t>(n) * 3 * Scanner::scalar_bytes, "points");
        for (std::size_t i = 0; i < points.size(); ++i) {
            points[i] = foam::binary_scalar(data.data() + i * Scanner::scalar_bytes);
            if (!std::isfinite(points[i]))
                s.fail_at(l.line, "finite coordinates in " + l.item("point", static_cast<std::int64_t>(i / 3)),
                          std::to_string(points[i]));
        }
    } else {
        for (std::int64_t i = 0; i < (l.uniform ? 1 : l.size); ++i) {
            // The error messages are built only on an error: lists are long.
            if (!s.try_char('(')) s.expect('(', "'(' opening " + l.item("point", i));
            for (int d = 0; d < 3; ++d) {
                double& x = points[static_cast<std::size_t>(i) * 3 + static_cast<std::size_t>(d)];
                if (!s.try_number(x)) x = s.number("coordinate " + str(d + 1) + " of 3 of " + l.item("point", i));
            }
            if (!s.try_char(')')) s.expect(')', "')' ending " + l.item("point", i) + " (3 coordinates)");
        }
    }
    close_list(s, l);
    if (l.uniform) {
        std::vector<double> all;
        for (std::int64_t i = 0; i < l.size; ++i) all.insert(all.end(), points.begin(), points.end());
        points = std::move(all);
    }
    return points;
}

/// Appends one face's point labels, checked against the point count.
struct FaceSink {
    foam::PolyMesh& mesh;
    foam::FaceLines& where;
    std::int64_t num_points;
};

/// The faces file, class faceList: `N ( k(a b c ...) ... )`, binary or ascii.
void read_face_list(Scanner& s, FaceSink& sink) {
    const ListStart l = open_list(s, "faces", 9, 0);
    if (l.uniform) s.fail_at(l.line, "'(' opening the list of faces (a uniform list of faces is no mesh)", "{");
    sink.mesh.face_offsets.reserve(static_cast<std::size_t>(l.size) + 1);
    sink.where.line.reserve(static_cast<std::size_t>(l.size));
    const std::size_t label_text = s.binary() ? Scanner::label_bytes : 2;  // the fewest bytes a label takes
    sink.mesh.face_nodes.reserve(static_cast<std::size_t>(l.size) * 4);
    // The error messages are built only on an error: lists are long.
    for (std::int64_t f = 0; f < l.size; ++f) {
        s.peek();
        const std::size_t line = s.line();
        std::int64_t k = 0;
        if (!s.try_integer(k)) {
            if (s.peek() == ')') s.fail(l.item("face", f), ")");
            s.integer("the size of " + l.item("face", f));
        }
        if (k < 3) s.fail_at(line, l.item("face", f) + " with at least 3 points", str(k));
        if (static_cast<std::uint64_t>(k) > s.remaining() / label_text)
            s.fail_at(line, "a size of " + l.item("face", f) + " that the rest of the file can hold", str(k));
        if (!s.try_char('(')) s.expect('(', "'(' opening the points of " + l.item("face", f));
        const std::string_view data = s.binary() ? s.raw(static_cast<std::size_t>(k) * Scanner::label_bytes, "the point labels of a face")
                                                 : std::string_view();
        for (std::int64_t i = 0; i < k; ++i) {
            const std::size_t at = s.binary() ? line : (s.peek(), s.line());
            std::int64_t p = 0;
            if (s.binary()) p = foam::binary_label(data.data() + i * Scanner::label_bytes);
            else if (!s.try_integer(p)) s.integer("point " + str(i) + " of " + l.item("face", f));
            if (p < 0 || p >= sink.num_points)
                s.fail_at(at, "point labels of " + l.item("face", f) + " from 0 to " + str(sink.num_points - 1) +
                                  " (the points file has " + str(sink.num_points) + ")",
                          str(p));
            sink.mesh.face_nodes.push_back(static_cast<NodeId>(p));
        }
        if (!s.try_char(')')) s.expect(')', "')' ending the " + str(k) + " points of " + l.item("face", f));
        sink.mesh.face_offsets.push_back(static_cast<std::int64_t>(sink.mesh.face_nodes.size()));
        sink.where.line.push_back(static_cast<std::uint32_t>(line));
    }
    close_list(s, l);
}

/// The faces file, class faceCompactList: a labelList of N + 1 offsets, then
/// a labelList of the faces' point labels.
void read_face_compact_list(Scanner& s, FaceSink& sink) {
    std::int64_t previous = 0;
    std::vector<std::uint32_t> offset_lines;
    const std::vector<std::int32_t> offsets =
        read_labels(s, "face offsets", [&](std::int64_t i, std::int64_t v, std::size_t line) {
            if (i == 0 && v != 0) s.fail_at(line, "0 as the first face offset", str(v));
            if (i > 0 && v - previous < 3)
                s.fail_at(line, "face offset " + str(i) + " at least 3 above the previous one (" + str(previous) +
                                    "): faces have at least 3 points",
                          str(v));
            previous = v;
            offset_lines.push_back(static_cast<std::uint32_t>(line));
        });
    if (offsets.empty()) s.fail("at least one face offset (0, for no faces)", "an empty list");
    const std::size_t labels_line = (s.peek(), s.line());
    const std::vector<std::int32_t> labels =
        read_labels(s, "face point labels", [&](std::int64_t i, std::int64_t p, std::size_t line) {
            if (p < 0 || p >= sink.num_points)
                s.fail_at(line, "point label " + str(i) + " of the faces from 0 to " + str(sink.num_points - 1) +
                                    " (the points file has " + str(sink.num_points) + ")",
                          str(p));
        });
    if (static_cast<std::int64_t>(labels.size()) != offsets.back())
        s.fail_at(labels_line,
                  "as many face point labels as the last face offset says (" + str(offsets.back()) + ")",
                  str(static_cast<std::int64_t>(labels.size())));
    sink.mesh.face_offsets.assign(offsets.begin(), offsets.end());
    sink.mesh.face_nodes.assign(labels.begin(), labels.end());
    // A face's line: where its offset is (in binary, the list's line).
    sink.where.line.assign(offset_lines.begin(), offset_lines.end() - 1);
}

/// Reads a file's header and checks its class is one of `classes`.
foam::Header open_file(Scanner& s, std::initializer_list<std::string_view> classes) {
    const foam::Header h = s.read_header();
    std::string list;
    for (std::string_view c : classes) {
        if (h.class_name == c) return h;
        list += (list.empty() ? "" : " or ") + std::string(c);
    }
    s.fail_at(h.class_line, "class " + list + " in the FoamFile header", h.class_name.empty() ? "none" : h.class_name);
}

void expect_end(Scanner& s) {
    if (!s.at_end()) s.fail("nothing more than comments after the list", std::string(1, s.peek()));
}

/// The boundary file: `N ( name { type ...; nFaces n; startFace s; ... } ... )`.
std::vector<foam::Patch> read_boundary(Scanner& s, std::int64_t num_internal, std::int64_t num_faces,
                                       bool processor_patches) {
    open_file(s, {"polyBoundaryMesh"});
    const ListStart l = open_list(s, "patches", 8, 0);
    if (l.uniform) s.fail_at(l.line, "'(' opening the list of patches", "{");
    std::vector<foam::Patch> patches;
    std::int64_t next = num_internal;
    for (std::int64_t p = 0; p < l.size; ++p) {
        foam::Patch patch;
        s.peek();
        patch.line = s.line();
        if (s.peek() == ')') s.fail(l.item("patch", p), ")");
        patch.name = std::string(s.word("the name of " + l.item("patch", p)));
        for (const foam::Patch& other : patches)
            if (other.name == patch.name)
                s.fail_at(patch.line, "a patch name not used before (line " + str(static_cast<std::int64_t>(other.line)) + ")",
                          patch.name);
        s.expect('{', "'{' opening the dictionary of patch '" + patch.name + "'");
        bool has_type = false, has_size = false, has_start = false;
        while (s.peek() != '}') {
            s.peek();
            const std::size_t line = s.line();
            const std::string key(s.word("an entry of patch '" + patch.name + "' or '}'"));
            const std::string value(s.entry_value(key));
            std::int64_t v = 0;
            const auto number = [&](std::string_view what) {
                if (!parse_int(value, v) || v < 0)
                    s.fail_at(line, "a number >= 0 after " + key + " in patch '" + patch.name + "' (" + std::string(what) + ")",
                              value);
            };
            if (key == "type") {
                patch.info.type = value;
                has_type = true;
                patch.processor = value == "processor" || value == "processorCyclic";
                if (patch.processor && !processor_patches)
                    throw FormatError(s.file() + ":" + str(static_cast<std::int64_t>(line)) + ": patch '" + patch.name +
                                      "' is of type " + value +
                                      ": this is one processor's part of a decomposed case; read the case folder "
                                      "(dgwarp reads its processor folders as one mesh) or reconstruct it "
                                      "(reconstructParMesh -constant)");
            } else if (key == "nFaces") {
                number("its face count");
                patch.size = v;
                has_size = true;
            } else if (key == "startFace") {
                number("its first face");
                patch.start = v;
                has_start = true;
            } else {
                if (key == "referPatch") patch.refer_patch = value;
                patch.info.entries.push_back(key + " " + value + (value.front() == '{' ? "" : ";"));
            }
        }
        s.expect('}', "'}'");
        // A cyclic patch's faces on a processor boundary: read as the faces of
        // the cyclic patch they belong to, else they would be lost from it.
        if (patch.info.type == "processorCyclic" && patch.refer_patch.empty())
            s.fail_at(patch.line, "referPatch (the cyclic patch its faces belong to) in processorCyclic patch '" + patch.name + "'",
                      "none");
        if (patch.info.type != "processorCyclic") patch.refer_patch.clear();
        if (!has_type || !has_size || !has_start)
            s.fail_at(patch.line, "type, nFaces and startFace in patch '" + patch.name + "'",
                      !has_type ? "no type" : !has_size ? "no nFaces" : "no startFace");
        if (patch.start != next)
            s.fail_at(patch.line,
                      "startFace " + str(next) + " in patch '" + patch.name + "' (" +
                          (p == 0 ? "the number of internal faces: the neighbour file's size"
                                  : "the end of patch '" + patches.back().name + "'") +
                          ")",
                      str(patch.start));
        if (patch.size > num_faces - next)
            s.fail_at(patch.line,
                      "at most " + str(num_faces - next) + " faces in patch '" + patch.name + "' (the faces file has " +
                          str(num_faces) + ")",
                      str(patch.size));
        next += patch.size;
        patches.push_back(std::move(patch));
    }
    close_list(s, l);
    expect_end(s);
    if (next != num_faces)
        s.fail_at(l.line,
                  "patches covering the boundary faces " + str(num_internal) + " to " + str(num_faces - 1) +
                      " (the faces file has " + str(num_faces) + " faces, the neighbour file " + str(num_internal) +
                      " internal ones)",
                  "patches ending at face " + str(next - 1));
    return patches;
}

}  // namespace

std::vector<std::int32_t> foam::read_label_list_file(const std::string& file, std::string_view content) {
    Scanner s(file, content);
    open_file(s, {"labelList"});
    std::vector<std::int32_t> labels = read_labels(s, "labels", [](std::int64_t, std::int64_t, std::size_t) {});
    expect_end(s);
    return labels;
}

namespace {

/// Clears `text` and gives its memory back.
void release_text(std::string* text) {
    if (text) std::string().swap(*text);
}

/// read_poly_mesh_part; with `release` (the same files as `files`), each
/// file's text is freed once parsed.
foam::PolyMeshPart read_part(const std::filesystem::path& dir, const PolyMeshFiles& files, PolyMeshFiles* release,
                             bool processor_patches) {
    const auto name = [&](const char* file) { return (dir / file).string(); };
    foam::PolyMesh pm;
    foam::FaceLines where{name("faces"), name("owner"), {}};

    Scanner points(name("points"), files.points);
    const foam::Header points_header = open_file(points, {"vectorField", "pointField"});
    pm.points = read_points(points);
    expect_end(points);
    const auto num_points = static_cast<std::int64_t>(pm.points.size() / 3);
    if (num_points > max_label)
        points.fail("at most " + str(max_label) + " points", str(num_points));
    release_text(release ? &release->points : nullptr);

    Scanner faces(name("faces"), files.faces);
    const foam::Header faces_header = open_file(faces, {"faceList", "faceCompactList"});
    FaceSink sink{pm, where, num_points};
    if (faces_header.class_name == "faceList") read_face_list(faces, sink);
    else read_face_compact_list(faces, sink);
    expect_end(faces);
    const auto num_faces = static_cast<std::int64_t>(pm.num_faces());
    release_text(release ? &release->faces : nullptr);  // the largest: freed before the cells are built

    Scanner owner(name("owner"), files.owner);
    open_file(owner, {"labelList"});
    std::int64_t num_cells = 0;
    struct {
        std::int64_t cells = 0;  // the largest cell number + 1, and where it is
        std::size_t line = 0;
        bool in_neighbour = false;
    } largest;
    owner.peek();
    const std::size_t owner_line = owner.line();
    pm.owner = read_labels(owner, "owners", [&](std::int64_t i, std::int64_t c, std::size_t line) {
        if (i >= num_faces)
            owner.fail_at(owner_line, "one owner per face: " + str(num_faces) + " (the faces file has them)",
                          "more");
        if (c < 0) owner.fail_at(line, "the owner of face " + str(i) + " (a cell number >= 0)", str(c));
        if (c + 1 > num_cells) largest = {c + 1, line, false};
        num_cells = std::max(num_cells, c + 1);
    });
    if (static_cast<std::int64_t>(pm.owner.size()) != num_faces)
        owner.fail_at(owner_line, "one owner per face: " + str(num_faces) + " (the faces file has them)",
                      str(static_cast<std::int64_t>(pm.owner.size())));
    expect_end(owner);

    Scanner neighbour(name("neighbour"), files.neighbour);
    open_file(neighbour, {"labelList"});
    const std::size_t neighbour_line = (neighbour.peek(), neighbour.line());
    pm.neighbour = read_labels(neighbour, "neighbours", [&](std::int64_t i, std::int64_t c, std::size_t line) {
        if (i >= num_faces)
            neighbour.fail_at(neighbour_line, "at most one neighbour per face (" + str(num_faces) + ")", "more");
        if (c < 0) neighbour.fail_at(line, "the neighbour of face " + str(i) + " (a cell number >= 0)", str(c));
        if (c == pm.owner[static_cast<std::size_t>(i)])
            neighbour.fail_at(line, "a neighbour of face " + str(i) + " other than its owner", str(c));
        if (c + 1 > num_cells) largest = {c + 1, line, true};
        num_cells = std::max(num_cells, c + 1);
    });
    expect_end(neighbour);
    // Every cell has at least 4 faces and a face at most 2 cells: more cells
    // than that is a damaged label (checked before the cells are allocated).
    const auto most_cells = static_cast<std::int64_t>((pm.owner.size() + pm.neighbour.size()) / 4);
    if (num_cells > most_cells)
        (largest.in_neighbour ? neighbour : owner)
            .fail_at(largest.line,
                     "cell numbers below " + str(most_cells) + " (the " + str(num_faces) + " faces, " +
                         str(static_cast<std::int64_t>(pm.neighbour.size())) +
                         " of them internal, can bound no more cells of 4 faces or more)",
                     str(largest.cells - 1));
    release_text(release ? &release->owner : nullptr);
    release_text(release ? &release->neighbour : nullptr);

    Scanner boundary(name("boundary"), files.boundary);
    pm.patches = read_boundary(boundary, static_cast<std::int64_t>(pm.neighbour.size()), num_faces, processor_patches);

    return foam::poly_mesh_part(std::move(pm), num_cells, where, points_header.format);
}

}  // namespace

foam::PolyMeshPart foam::poly_mesh_part(PolyMesh&& pm, std::int64_t num_cells, const FaceLines& where,
                                        Format points_format) {
    const auto num_faces = static_cast<std::int64_t>(pm.num_faces());
    Mesh mesh;
    mesh.dim = 3;
    mesh.cells = foam::cells_from_faces(pm, num_cells, where);
    mesh.points = std::move(pm.points);
    std::vector<NodeId> processor_nodes;
    std::vector<std::size_t> marker_patch;
    for (std::size_t p = 0; p < pm.patches.size(); ++p) {
        const foam::Patch& patch = pm.patches[p];
        if (patch.processor && patch.refer_patch.empty()) {  // faces another processor shares: inner faces of the whole mesh
            processor_nodes.insert(processor_nodes.end(), pm.face_nodes.begin() + pm.face_offsets[patch.start],
                                   pm.face_nodes.begin() + pm.face_offsets[patch.start + patch.size]);
            continue;
        }
        Marker marker{patch.name, {}};
        marker.elements.reserve(static_cast<std::size_t>(patch.size), 4);
        for (std::int64_t f = patch.start; f < patch.start + patch.size; ++f) {
            const std::span<const NodeId> nodes(pm.face_nodes.data() + pm.face_offsets[f],
                                                static_cast<std::size_t>(pm.face_offsets[f + 1] - pm.face_offsets[f]));
            // A boundary face: a triangle, a quadrilateral or (a polyhedron's) a polygon.
            marker.elements.push_back(polygon_type(nodes.size()), nodes);
        }
        mesh.markers.push_back(std::move(marker));
        marker_patch.push_back(p);
    }
    validate(mesh);
    std::sort(processor_nodes.begin(), processor_nodes.end());
    processor_nodes.erase(std::unique(processor_nodes.begin(), processor_nodes.end()), processor_nodes.end());
    return {std::move(mesh), std::move(pm.patches), points_format, num_faces, std::move(processor_nodes),
            std::move(marker_patch)};
}

foam::PolyMeshPart foam::read_poly_mesh_part(const std::filesystem::path& dir, const PolyMeshFiles& files,
                                             bool processor_patches) {
    return read_part(dir, files, nullptr, processor_patches);
}

foam::PolyMeshPart foam::read_poly_mesh_part(const std::filesystem::path& dir, PolyMeshFiles&& files,
                                             bool processor_patches) {
    return read_part(dir, files, &files, processor_patches);
}

Mesh read_openfoam_files(const std::filesystem::path& dir, const PolyMeshFiles& files, OpenFoamSource* source) {
    foam::PolyMeshPart part = foam::read_poly_mesh_part(dir, files, false);
    if (source) {
        source->points_format = part.points_format;
        source->patches.clear();
        for (const foam::Patch& patch : part.patches) source->patches.push_back(patch.info);
    }
    return std::move(part.mesh);
}

}  // namespace dgwarp
