// Writer of OpenFOAM polyMesh files (openfoam.hpp), laid out as OpenFOAM
// writes them (blockMesh for ascii, foamFormatConvert for binary).
#include <sstream>
#include <string>

#include "dgwarp/core/error.hpp"
#include "dgwarp/io/openfoam/foam_file.hpp"
#include "dgwarp/io/number_text.hpp"
#include "dgwarp/io/marker_names.hpp"
#include "dgwarp/io/openfoam/openfoam.hpp"
#include "dgwarp/io/text_rows.hpp"
#include "dgwarp/io/openfoam/openfoam_poly_mesh.hpp"

namespace dgwarp {

namespace {

using foam::Format;

constexpr const char* poly_mesh_location = "constant/polyMesh";

void write_label(std::ostream& out, std::int64_t v) { write_number(out, static_cast<long long>(v)); }

/// A labelList's body: `N`, then `(` one label a line `)` (ascii) or the raw labels.
void write_labels(std::ostream& out, std::span<const std::int32_t> labels, Format format) {
    write_label(out, static_cast<std::int64_t>(labels.size()));
    if (format == Format::binary) {
        out << "\n(";
        for (std::int32_t v : labels) foam::put_binary_label(out, v);
        out << ")";
        return;
    }
    out << "\n(\n";
    for (std::int32_t v : labels) {
        write_label(out, v);
        out.put('\n');
    }
    out << ")";
}

std::string label_list_text(std::span<const std::int32_t> labels, Format format, std::string_view object,
                            const std::string& note) {
    std::ostringstream out;
    foam::write_header(out, format, "labelList", poly_mesh_location, object, note);
    write_labels(out, labels, format);
    foam::write_footer(out);
    return std::move(out).str();
}

std::string faces_text(const foam::PolyMesh& pm, Format format) {
    std::ostringstream out;
    if (format == Format::binary) {
        // faceCompactList: the N + 1 offsets, then every face's point labels.
        foam::write_header(out, format, "faceCompactList", poly_mesh_location, "faces");
        // In range: faces_from_cells checks them (check_label_size).
        std::vector<std::int32_t> offsets(pm.face_offsets.begin(), pm.face_offsets.end());
        write_labels(out, offsets, format);
        out << "\n\n";
        write_labels(out, pm.face_nodes, format);
    } else {
        foam::write_header(out, format, "faceList", poly_mesh_location, "faces");
        write_label(out, static_cast<std::int64_t>(pm.num_faces()));
        out << "\n(\n";
        for (std::size_t f = 0; f < pm.num_faces(); ++f) {
            write_label(out, pm.face_offsets[f + 1] - pm.face_offsets[f]);
            out.put('(');
            for (std::int64_t k = pm.face_offsets[f]; k < pm.face_offsets[f + 1]; ++k) {
                if (k > pm.face_offsets[f]) out.put(' ');
                write_label(out, pm.face_nodes[static_cast<std::size_t>(k)]);
            }
            out << ")\n";
        }
        out << ")";
    }
    foam::write_footer(out);
    return std::move(out).str();
}

std::string boundary_text(const foam::PolyMesh& pm, const Mesh& mesh, const OpenFoamWriteOptions& options) {
    const bool kept = options.source && options.source->patches.size() == mesh.markers.size();
    std::ostringstream out;
    foam::write_header(out, Format::ascii, "polyBoundaryMesh", poly_mesh_location, "boundary");
    out << pm.patches.size() << "\n(\n";
    for (std::size_t p = 0; p < pm.patches.size(); ++p) {
        const foam::Patch& patch = pm.patches[p];
        const OpenFoamPatch info = kept && p < mesh.markers.size() ? options.source->patches[p] : OpenFoamPatch{};
        out << "    " << patch.name << "\n    {\n        type            " << info.type << ";\n";
        for (const std::string& entry : info.entries) out << "        " << entry << "\n";
        out << "        nFaces          " << patch.size << ";\n        startFace       " << patch.start << ";\n    }\n";
    }
    out << ")";
    foam::write_footer(out);
    return std::move(out).str();
}

/// A patch name must be one OpenFOAM word: no blanks, no ( ) { } ; " / and not empty.
void check_patch_names(const foam::PolyMesh& pm) {
    for (const foam::Patch& patch : pm.patches) {
        if (!is_openfoam_word(patch.name))
            throw MeshError("marker '" + patch.name +
                                "' cannot name an OpenFOAM patch (a patch name is one word: not empty, without "
                                "blanks, quotes, slashes or any of ( ) { } ;)",
                            patch.name);
    }
}

}  // namespace

std::string openfoam_points_text(std::span<const double> points, Format format, const std::string& location) {
    std::ostringstream out;
    foam::write_header(out, format, "vectorField", location, "points");
    const std::size_t n = points.size() / 3;
    write_label(out, static_cast<std::int64_t>(n));
    if (format == Format::binary) {
        out << "\n(";
        for (double x : points) foam::put_binary_scalar(out, x);
        out << ")";
    } else {
        out << "\n(\n";
        write_rows(out, static_cast<std::int64_t>(n), [&](std::int64_t i, RowText& text) {
            text.push_back('(');
            for (std::size_t d = 0; d < 3; ++d) {
                if (d) text.push_back(' ');
                append_number(text, points[3 * static_cast<std::size_t>(i) + d]);
            }
            text.append(")\n");
        });
        out << ")";
    }
    foam::write_footer(out);
    return std::move(out).str();
}

PolyMeshFiles write_openfoam_files(const Mesh& mesh, const OpenFoamWriteOptions& options) {
    const foam::PolyMesh pm = foam::faces_from_cells(mesh);
    check_patch_names(pm);
    for (std::size_t p = 0; p < pm.patches.size(); ++p)
        for (std::size_t q = 0; q < p; ++q)
            if (pm.patches[p].name == pm.patches[q].name)
                throw MeshError("two patches would be called '" + pm.patches[p].name +
                                    "' (OpenFOAM needs distinct names; dgwarp calls boundary faces in no marker "
                                    "defaultFaces)",
                                pm.patches[p].name);
    const std::string note = "nPoints:" + std::to_string(mesh.num_points()) +
                             "  nCells:" + std::to_string(mesh.cells.size()) +
                             "  nFaces:" + std::to_string(pm.num_faces()) +
                             "  nInternalFaces:" + std::to_string(pm.neighbour.size());
    PolyMeshFiles files;
    files.points = openfoam_points_text(mesh.points, options.format, poly_mesh_location);
    files.faces = faces_text(pm, options.format);
    files.owner = label_list_text(pm.owner, options.format, "owner", note);
    files.neighbour = label_list_text(pm.neighbour, options.format, "neighbour", note);
    files.boundary = boundary_text(pm, mesh, options);
    return files;
}

}  // namespace dgwarp
