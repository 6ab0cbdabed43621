// Decomposed OpenFOAM cases (openfoam.hpp): the processors' polyMeshes read
// as one mesh, numbered as the reconstructed case through decomposePar's
// addressing files (pointProcAddressing, faceProcAddressing,
// cellProcAddressing), and each processor's point numbering kept for
// writing moved points back.
#include <algorithm>
#include <array>
#include <map>
#include <string>
#include <system_error>
#include <unordered_map>

#include "dgwarp/core/error.hpp"
#include "dgwarp/io/openfoam/openfoam.hpp"
#include "dgwarp/io/openfoam/openfoam_poly_mesh.hpp"
#include "dgwarp/io/text_reader.hpp"

namespace dgwarp {

namespace fs = std::filesystem;
using foam::is_folder;

namespace {

/// N when `name` is "processorN" (digits only), else -1.
long processor_number(const std::string& name, const char* prefix) {
    const std::string p = prefix;
    if (name.size() <= p.size() || name.compare(0, p.size(), p) != 0) return -1;
    const std::string digits = name.substr(p.size());
    if (digits.size() > 6 || !std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; }))
        return -1;
    return std::stol(digits);
}

/// One processor's files read.
struct ProcessorPart {
    foam::PolyMeshPart part;
    std::vector<std::int32_t> point_of, face_of, cell_of;  // the addressing files
};

std::string str(std::int64_t v) { return std::to_string(v); }

/// Addressing file `name` of processor dir `dir`: `count` labels from 0 to
/// below `limit` (faces: signed, 1-based).
std::vector<std::int32_t> read_addressing(const fs::path& dir, const char* name, std::int64_t count, bool signed_faces) {
    const std::string file = (dir / name).string();
    std::vector<std::int32_t> labels = foam::read_label_list_file(file, foam::read_mesh_file(dir, name));
    if (static_cast<std::int64_t>(labels.size()) != count)
        throw ParseError(file, 0, str(count) + " labels, one per " + (signed_faces ? "face" : name[0] == 'p' ? "point" : "cell") +
                                      " of the processor's polyMesh",
                         str(static_cast<std::int64_t>(labels.size())));
    for (std::size_t i = 0; i < labels.size(); ++i)
        if (signed_faces ? labels[i] == 0 : labels[i] < 0)
            throw ParseError(file, 0, std::string("label ") + str(static_cast<std::int64_t>(i)) +
                                          (signed_faces ? " other than 0 (faces are numbered from 1, signed by their turn)"
                                                        : " >= 0"),
                             str(labels[i]));
    return labels;
}

/// Cell c of a processor's mesh `m` with its corners as the case's points
/// (`point_of`: pointProcAddressing) in order_cell's canonical order, the
/// order the whole case's reader gives them. Two corners that are one point
/// of the case: a ParseError naming `addressing`.
foam::OrderedCell case_ordered_cell(const Mesh& m, std::size_t c, const std::vector<std::int32_t>& point_of,
                                    const fs::path& addressing) {
    const auto nodes = m.cells.nodes_of(c);
    const foam::FaceTable& t = foam::outward_faces(m.cells.types[c]);
    foam::CellFaces faces;
    faces.count = t.count;
    for (int k = 0; k < t.count; ++k) {
        faces.size[k] = t.size[k];
        for (int i = 0; i < t.size[k]; ++i)
            faces.node[k][i] = point_of[static_cast<std::size_t>(nodes[static_cast<std::size_t>(t.node[k][i])])];
    }
    const foam::OrderedCell oc = foam::order_cell(faces);
    if (oc.shape != foam::CellShape::ok)
        throw ParseError(addressing.string(), 0,
                         "distinct points of the case for the corners of cell " + str(static_cast<std::int64_t>(c)),
                         "a point twice");
    return oc;
}

}  // namespace

namespace {
/// The folders of `path` named `prefix` and a number (processor0, ...), by number.
std::map<long, fs::path> numbered_folders(const fs::path& path, const char* prefix) {
    std::map<long, fs::path> found;
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(path, ec))
        if (const long n = processor_number(entry.path().filename().string(), prefix); n >= 0 && is_folder(entry.path()))
            found[n] = entry.path();
    return found;
}
}  // namespace

std::vector<fs::path> openfoam_unread_processor_folders(const fs::path& path) {
    if (!is_folder(path) || !is_folder(path / "constant" / "polyMesh")) return {};
    std::vector<fs::path> folders;
    for (const auto& [n, folder] : numbered_folders(path, "processor")) folders.push_back(folder);
    return folders;
}

namespace {
/// openfoam_processor_meshes of a case folder (not of a time of one).
std::vector<fs::path> case_processor_meshes(const fs::path& path);
}  // namespace

std::optional<OpenFoamDecomposedTime> openfoam_decomposed_time(const fs::path& path) {
    fs::path p = path;
    if (p.filename().empty()) p = p.parent_path();
    if (p.empty() || !p.has_parent_path() || is_folder(p / "polyMesh") || is_folder(p / "constant")) return std::nullopt;
    const fs::path case_folder = p.parent_path();
    const std::string time = p.filename().string();
    if (time.empty() || time == "." || time == ".." || time == "constant" || !is_folder(case_folder / "processor0"))
        return std::nullopt;
    const fs::path points = case_folder / "processor0" / time / "polyMesh";
    std::error_code ec;
    if (!fs::exists(points / "points", ec) && !fs::exists(points / "points.gz", ec)) return std::nullopt;
    if (case_processor_meshes(case_folder).empty()) return std::nullopt;
    return OpenFoamDecomposedTime{case_folder, time};
}

std::vector<fs::path> openfoam_processor_meshes(const fs::path& path) {
    if (const auto t = openfoam_decomposed_time(path)) return case_processor_meshes(t->case_folder);
    return case_processor_meshes(path);
}

namespace {
std::vector<fs::path> case_processor_meshes(const fs::path& path) {
    if (!is_folder(path) || is_folder(path / "constant" / "polyMesh")) return {};
    if (const auto collated = numbered_folders(path, "processors"); !collated.empty())
        throw FormatError(collated.begin()->second.string() +
                          ": a collated decomposed case (one processors<N> folder); dgwarp reads the uncollated "
                          "layout (processor0, processor1, ...: decomposePar -fileHandler uncollated) or the "
                          "reconstructed case");
    const std::map<long, fs::path> found = numbered_folders(path, "processor");
    if (found.empty()) return {};
    std::vector<fs::path> meshes;
    for (const auto& [n, folder] : found) {
        const fs::path mesh = folder / "constant" / "polyMesh";
        if (n != static_cast<long>(meshes.size()))
            throw FormatError(path.string() + ": a decomposed case whose processor folders are not processor0 to processor" +
                              str(static_cast<std::int64_t>(found.size()) - 1) + " (processor" +
                              str(static_cast<std::int64_t>(meshes.size())) + " is missing)");
        if (!is_folder(mesh))
            throw FormatError(mesh.string() + ": missing: every processor folder of a decomposed case needs its polyMesh");
        meshes.push_back(mesh);
    }
    return meshes;
}
}  // namespace

std::vector<OpenFoamProcessor> read_processors_beside(const fs::path& path, std::size_t num_points) {
    std::vector<OpenFoamProcessor> processors;
    for (const fs::path& folder : openfoam_unread_processor_folders(path)) {
        const fs::path poly_mesh = folder / "constant" / "polyMesh";
        const OpenFoamProcessorMesh read = read_openfoam_processor(poly_mesh);
        OpenFoamProcessor p{poly_mesh, read.points_format, {}};
        for (std::int64_t id : read.point_ids) {
            if (id < 0 || static_cast<std::uint64_t>(id) >= num_points)
                throw ParseError((poly_mesh / "pointProcAddressing").string(), 0,
                                 "point labels below " + str(static_cast<std::int64_t>(num_points)) +
                                     " (the points of " + (path / "constant" / "polyMesh").string() + ")",
                                 str(id));
            p.points.push_back(static_cast<NodeId>(id));
        }
        processors.push_back(std::move(p));
    }
    return processors;
}

std::vector<double> processor_points(const OpenFoamProcessor& p, std::span<const double> points) {
    std::vector<double> out(p.points.size() * 3);
    for (std::size_t i = 0; i < p.points.size(); ++i)
        for (std::size_t d = 0; d < 3; ++d) out[3 * i + d] = points[3 * static_cast<std::size_t>(p.points[i]) + d];
    return out;
}

OpenFoamProcessorMesh read_openfoam_processor(const fs::path& dir) {
    PolyMeshFiles files;
    std::string* texts[] = {&files.points, &files.faces, &files.owner, &files.neighbour, &files.boundary};
    for (int k = 0; k < 5; ++k) *texts[k] = foam::read_mesh_file(dir, poly_mesh_file_names[k]);
    foam::PolyMeshPart part = foam::read_poly_mesh_part(dir, std::move(files), true);
    OpenFoamProcessorMesh out;
    const std::vector<std::int32_t> point_of =
        read_addressing(dir, "pointProcAddressing", static_cast<std::int64_t>(part.mesh.num_points()), false);
    const std::vector<std::int32_t> cell_of =
        read_addressing(dir, "cellProcAddressing", static_cast<std::int64_t>(part.mesh.cells.size()), false);
    out.point_ids.assign(point_of.begin(), point_of.end());
    out.cell_ids.assign(cell_of.begin(), cell_of.end());
    // Each cell's nodes in the order read_openfoam_decomposed gives them: the
    // canonical order of order_cell over the case's point ids.
    const Mesh& m = part.mesh;
    ElementList cells;
    cells.reserve(m.cells.size(), 8);
    for (std::size_t c = 0; c < m.cells.size(); ++c) {
        if (m.cells.types[c] == CellType::polyhedron) {
            // Ordered over the case's point ids, as read_openfoam_decomposed orders it.
            const auto [f0, f1] = m.cells.faces_of(c);
            std::vector<NodeId> rings;
            std::vector<int> sizes;
            for (std::int64_t f = f0; f < f1; ++f) {
                for (NodeId n : m.cells.face_nodes_of(f)) rings.push_back(point_of[static_cast<std::size_t>(n)]);
                sizes.push_back(static_cast<int>(m.cells.face_nodes_of(f).size()));
            }
            ElementList global;
            foam::push_canonical_polyhedron(rings, sizes, global);
            // Back to the processor's ids.
            std::unordered_map<NodeId, NodeId> local_of;
            for (NodeId n : m.cells.nodes_of(c)) local_of[point_of[static_cast<std::size_t>(n)]] = n;
            for_each_node_id(global, [&](NodeId& n) { n = local_of.at(n); });
            copy_element(global, 0, cells);
            continue;
        }
        const foam::OrderedCell oc = case_ordered_cell(m, c, point_of, dir / "pointProcAddressing");
        const auto nodes = m.cells.nodes_of(c);
        std::array<NodeId, 8> local{};
        const int n = nodes_per_cell(oc.type);
        for (int k = 0; k < n; ++k)
            for (NodeId node : nodes)
                if (point_of[static_cast<std::size_t>(node)] == oc.node[static_cast<std::size_t>(k)]) local[static_cast<std::size_t>(k)] = node;
        cells.push_back(oc.type, {local.data(), static_cast<std::size_t>(n)});
    }
    out.mesh = std::move(part.mesh);
    out.mesh.cells = std::move(cells);
    // A processorCyclic patch's faces are no marker of this part (each process
    // reads such a case whole: deforms_per_processor).
    std::vector<Marker> markers;
    for (std::size_t k = 0; k < out.mesh.markers.size(); ++k)
        if (!part.patches[part.marker_patch[k]].processor) markers.push_back(std::move(out.mesh.markers[k]));
    out.mesh.markers = std::move(markers);
    out.interface_nodes = std::move(part.processor_nodes);
    out.points_format = part.points_format;
    for (const foam::Patch& patch : part.patches)
        if (!patch.processor) out.patches.push_back(patch.info);
    return out;
}

Mesh foam::read_openfoam_decomposed(const std::vector<fs::path>& meshes, const ProgressFn& progress,
                                    OpenFoamSource* source, const std::string& time) {
    std::vector<ProcessorPart> parts;
    std::int64_t num_points = 0, num_cells = 0, local_points = 0;
    for (std::size_t p = 0; p < meshes.size(); ++p) {
        const fs::path& dir = meshes[p];
        PolyMeshFiles files;
        std::string* texts[] = {&files.points, &files.faces, &files.owner, &files.neighbour, &files.boundary};
        // A time's points (processorN/T/polyMesh/points), every processor's, else constant's.
        const fs::path points_dir = time.empty() ? dir : dir.parent_path().parent_path() / time / "polyMesh";
        for (int k = 0; k < 5; ++k) *texts[k] = foam::read_mesh_file(k == 0 ? points_dir : dir, poly_mesh_file_names[k]);
        ProcessorPart part{foam::read_poly_mesh_part(dir, std::move(files), true), {}, {}, {}};
        const Mesh& m = part.part.mesh;
        part.point_of = read_addressing(dir, "pointProcAddressing", static_cast<std::int64_t>(m.num_points()), false);
        part.face_of = read_addressing(dir, "faceProcAddressing", part.part.num_faces, true);
        part.cell_of = read_addressing(dir, "cellProcAddressing", static_cast<std::int64_t>(m.cells.size()), false);
        for (std::int32_t g : part.point_of) num_points = std::max<std::int64_t>(num_points, g + std::int64_t{1});
        num_cells += static_cast<std::int64_t>(m.cells.size());
        local_points += static_cast<std::int64_t>(m.num_points());
        parts.push_back(std::move(part));
        if (progress) progress(0.9 * static_cast<double>(p + 1) / static_cast<double>(meshes.size()));
    }

    // Each point of the case is some processor's: a larger number is a damaged label
    // (checked before the points are allocated).
    if (num_points > local_points)
        throw ParseError((meshes[0] / "pointProcAddressing").string(), 0,
                         "point numbers below " + str(local_points) + " (the processors have that many points)",
                         str(num_points - 1));

    Mesh mesh;
    mesh.dim = 3;
    // Points: each one from the processors that hold it, at the same place in each.
    mesh.points.assign(static_cast<std::size_t>(num_points) * 3, 0.0);
    std::vector<int> from(static_cast<std::size_t>(num_points), -1);
    for (std::size_t p = 0; p < parts.size(); ++p) {
        const Mesh& m = parts[p].part.mesh;
        for (std::size_t i = 0; i < m.num_points(); ++i) {
            const auto g = static_cast<std::size_t>(parts[p].point_of[i]);
            const bool seen = from[g] >= 0;
            for (std::size_t d = 0; d < 3; ++d) {
                if (seen && mesh.points[3 * g + d] != m.points[3 * i + d])
                    throw ParseError((meshes[p] / "points").string(), 0,
                                     "point " + str(static_cast<std::int64_t>(i)) + " (point " + str(static_cast<std::int64_t>(g)) +
                                         " of the case, pointProcAddressing) where processor " + str(from[g]) + " has it",
                                     "another place");
                mesh.points[3 * g + d] = m.points[3 * i + d];
            }
            from[g] = static_cast<int>(p);
        }
    }
    if (const auto it = std::find(from.begin(), from.end(), -1); it != from.end())
        throw ParseError((meshes[0] / "pointProcAddressing").string(), 0,
                         "every point from 0 to " + str(num_points - 1) + " in some processor's pointProcAddressing",
                         "no point " + str(it - from.begin()));

    // Cells in the case's order, each renumbered and put back in the reader's
    // node order (a polyhedron: renumbered, its faces in its processor's order).
    struct Cell {
        CellType type = CellType::tetrahedron;
        std::array<NodeId, 8> node{};
        std::int32_t part = -1;  // the processor of a polyhedron, its cell there in `local`
        std::int64_t local = 0;
        bool set = false;
    };
    std::vector<Cell> cells(static_cast<std::size_t>(num_cells));
    for (std::size_t p = 0; p < parts.size(); ++p) {
        const Mesh& m = parts[p].part.mesh;
        for (std::size_t c = 0; c < m.cells.size(); ++c) {
            const std::int64_t g = parts[p].cell_of[c];
            if (g >= num_cells || cells[static_cast<std::size_t>(g)].set)
                throw ParseError((meshes[p] / "cellProcAddressing").string(), 0,
                                 "each cell of the case from 0 to " + str(num_cells - 1) + " once over the processors",
                                 "cell " + str(g) + (g < num_cells ? " again" : ""));
            Cell& cell = cells[static_cast<std::size_t>(g)];
            cell.set = true;
            if (m.cells.types[c] == CellType::polyhedron) {
                cell.type = CellType::polyhedron;
                cell.part = static_cast<std::int32_t>(p);
                cell.local = static_cast<std::int64_t>(c);
                continue;
            }
            const foam::OrderedCell oc =
                case_ordered_cell(m, c, parts[p].point_of, meshes[p] / "pointProcAddressing");
            cell.type = oc.type;
            cell.node = oc.node;
        }
    }
    mesh.cells.reserve(cells.size(), 8);
    for (const Cell& c : cells) {
        if (c.type != CellType::polyhedron) {
            mesh.cells.push_back(c.type, {c.node.data(), static_cast<std::size_t>(nodes_per_cell(c.type))});
            continue;
        }
        const ProcessorPart& part = parts[static_cast<std::size_t>(c.part)];
        const ElementList& from = part.part.mesh.cells;
        const auto [f0, f1] = from.faces_of(static_cast<std::size_t>(c.local));
        std::vector<NodeId> rings;
        std::vector<int> sizes;
        for (std::int64_t f = f0; f < f1; ++f) {
            for (NodeId n : from.face_nodes_of(f)) rings.push_back(part.point_of[static_cast<std::size_t>(n)]);
            sizes.push_back(static_cast<int>(from.face_nodes_of(f).size()));
        }
        foam::push_canonical_polyhedron(rings, sizes, mesh.cells);
    }

    // Markers: processor 0's patches (not the processor ones); every processor has the same.
    const auto patch_names = [](const foam::PolyMeshPart& part) {
        std::vector<std::string> names;
        for (const foam::Patch& patch : part.patches)
            if (!patch.processor) names.push_back(patch.name);
        return names;
    };
    const std::vector<std::string> names = patch_names(parts[0].part);
    for (std::size_t p = 1; p < parts.size(); ++p)
        if (patch_names(parts[p].part) != names)
            throw ParseError((meshes[p] / "boundary").string(), 0,
                             "the patches of processor 0, in the same order (decomposePar writes every patch to every "
                             "processor)",
                             "other patches");
    // Per marker of the case, (face of the case, element) from every
    // processor; a processorCyclic patch's faces go to its referPatch.
    std::vector<std::vector<std::pair<std::int64_t, std::vector<NodeId>>>> marker_faces(names.size());
    for (std::size_t p = 0; p < parts.size(); ++p) {
        const foam::PolyMeshPart& part = parts[p].part;
        for (std::size_t k = 0; k < part.mesh.markers.size(); ++k) {
            const foam::Patch& patch = part.patches[part.marker_patch[k]];
            const std::string& target = patch.refer_patch.empty() ? patch.name : patch.refer_patch;
            const auto m = static_cast<std::size_t>(std::find(names.begin(), names.end(), target) - names.begin());
            if (m == names.size())
                throw ParseError((meshes[p] / "boundary").string(), patch.line,
                                 "a referPatch that is a patch of the case in processorCyclic patch '" + patch.name + "'",
                                 target);
            const ElementList& elements = part.mesh.markers[k].elements;
            for (std::size_t e = 0; e < elements.size(); ++e) {
                const std::int32_t signed_face = parts[p].face_of[static_cast<std::size_t>(patch.start) + e];
                std::vector<NodeId> nodes;
                for (NodeId n : elements.nodes_of(e)) nodes.push_back(parts[p].point_of[static_cast<std::size_t>(n)]);
                if (signed_face < 0) std::reverse(nodes.begin() + 1, nodes.end());  // turned in the processor
                marker_faces[m].emplace_back(signed_face < 0 ? -std::int64_t{signed_face} : signed_face, std::move(nodes));
            }
        }
    }
    for (std::size_t m = 0; m < names.size(); ++m) {
        auto& faces = marker_faces[m];
        std::stable_sort(faces.begin(), faces.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
        Marker marker{names[m], {}};
        marker.elements.reserve(faces.size(), 4);
        for (const auto& [face, nodes] : faces)
            marker.elements.push_back(polygon_type(nodes.size()), nodes);
        mesh.markers.push_back(std::move(marker));
    }
    validate(mesh);
    if (source) {
        *source = {};
        source->points_format = parts[0].part.points_format;
        for (const foam::Patch& patch : parts[0].part.patches)
            if (!patch.processor) source->patches.push_back(patch.info);
        for (std::size_t p = 0; p < parts.size(); ++p)
            source->processors.push_back({meshes[p], parts[p].part.points_format,
                                          std::vector<NodeId>(parts[p].point_of.begin(), parts[p].point_of.end())});
    }
    if (progress) progress(1.0);
    return mesh;
}

}  // namespace dgwarp
