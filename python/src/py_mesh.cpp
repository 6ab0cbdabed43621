#include "py_mesh.hpp"

#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <array>
#include <iterator>

#include "arrays.hpp"
#include "dgwarp/core/error.hpp"
#include "dgwarp/io/mesh_io.hpp"
#include "dgwarp/io/openfoam/openfoam_frames.hpp"
#include "errors.hpp"
#include "progress_bridge.hpp"

namespace py = pybind11;

namespace dgwarp::python {

namespace {

std::optional<CellType> cell_type_from_name(std::string_view name) {
    for (CellType t : all_cell_types)
        if (cell_type_name(t) == name) return t;
    return std::nullopt;
}

std::string cell_type_names() {
    std::string s;
    for (CellType t : all_cell_types) s += (s.empty() ? "" : ", ") + std::string(cell_type_name(t));
    return s;
}

/// Whether every element of `list` has one type (then `list.nodes` is an n × k array).
bool uniform(const ElementList& list) {
    for (std::size_t i = 1; i < list.types.size(); ++i)
        if (list.types[i] != list.types[0]) return false;
    return true;
}

/// Elements per type, in list order within a type: type name → (n, k) int32
/// array; a read-only view of `list` when it holds one type, else copies.
py::dict elements_by_type(const ElementList& list, py::handle owner) {
    py::dict out;
    if (list.empty()) return out;
    if (uniform(list) && !has_any_node_count(list.types[0])) {
        const auto k = static_cast<py::ssize_t>(nodes_per_cell(list.types[0]));
        out[py::str(std::string(cell_type_name(list.types[0])))] =
            read_only_view(list.nodes.data(), {static_cast<py::ssize_t>(list.size()), k}, owner);
        return out;
    }
    const auto counts = count_by_type(list);
    for (CellType t : all_cell_types) {
        const auto count = counts[static_cast<std::size_t>(t)];
        if (count == 0) continue;
        if (t == CellType::polygon || t == CellType::polyhedron) {
            // Any number of nodes: a list of arrays (a polygon's nodes in
            // order), or of lists of face arrays (a polyhedron's, normals out).
            py::list items;
            for (std::size_t i = 0; i < list.size(); ++i) {
                if (list.types[i] != t) continue;
                if (t == CellType::polygon) {
                    const auto nodes = list.nodes_of(i);
                    items.append(py::array_t<NodeId>(static_cast<py::ssize_t>(nodes.size()), nodes.data()));
                    continue;
                }
                py::list faces;
                const auto [f0, f1] = list.faces_of(i);
                for (std::int64_t f = f0; f < f1; ++f) {
                    const auto ring = list.face_nodes_of(f);
                    faces.append(py::array_t<NodeId>(static_cast<py::ssize_t>(ring.size()), ring.data()));
                }
                items.append(faces);
            }
            out[py::str(std::string(cell_type_name(t)))] = items;
            continue;
        }
        const int k = nodes_per_cell(t);
        py::array_t<NodeId> a({static_cast<py::ssize_t>(count), static_cast<py::ssize_t>(k)});
        NodeId* d = a.mutable_data();
        for (std::size_t i = 0; i < list.size(); ++i)
            if (list.types[i] == t)
                for (NodeId n : list.nodes_of(i)) *d++ = n;
        out[py::str(std::string(cell_type_name(t)))] = a;
    }
    return out;
}

/// Type name → int64 array of the positions, in `list`, of its elements of that type.
py::dict indices_by_type(const ElementList& list) {
    py::dict out;
    const auto counts = count_by_type(list);
    for (CellType t : all_cell_types) {
        const auto count = counts[static_cast<std::size_t>(t)];
        if (count == 0) continue;
        py::array_t<std::int64_t> a(static_cast<py::ssize_t>(count));
        std::int64_t* d = a.mutable_data();
        for (std::size_t i = 0; i < list.size(); ++i)
            if (list.types[i] == t) *d++ = static_cast<std::int64_t>(i);
        out[py::str(std::string(cell_type_name(t)))] = a;
    }
    return out;
}

/// Appends to `list` the elements of one block: `type` (a name, or None to
/// infer it from the column count for boundary elements of a `dim` mesh) and
/// an (n, k) integer array.
void append_block(ElementList& list, py::handle type, py::handle array, const std::string& what, int boundary_dim) {
    std::optional<CellType> t;
    if (!type.is_none()) {
        const std::string name = py::str(type);
        t = cell_type_from_name(name);
        if (!t) throw py::value_error(what + ": unknown cell type '" + name + "'; dgwarp's are " + cell_type_names());
    }
    if (t && (*t == CellType::polygon || *t == CellType::polyhedron)) {
        // A sequence of polygons (node arrays) or of polyhedra (sequences of face node arrays).
        std::size_t i = 0;
        for (auto item : array) {
            const std::string where = what + "[" + std::to_string(i++) + "]";
            if (*t == CellType::polygon) {
                const std::vector<NodeId> ids = node_ids(item, where.c_str(), any_rows);
                if (ids.size() < 3) throw py::value_error(where + ": a polygon has at least 3 nodes");
                list.push_back(*t, ids);
                continue;
            }
            std::vector<NodeId> rings;
            std::vector<int> sizes;
            std::size_t k = 0;
            for (auto face : item) {
                const std::vector<NodeId> ids = node_ids(face, (where + "[" + std::to_string(k++) + "]").c_str(), any_rows);
                rings.insert(rings.end(), ids.begin(), ids.end());
                sizes.push_back(static_cast<int>(ids.size()));
            }
            list.push_polyhedron(rings, sizes);
        }
        return;
    }
    py::ssize_t rows = 0;
    std::vector<NodeId> ids;
    if (t) {
        ids = node_ids(array, what.c_str(), nodes_per_cell(*t), &rows);
    } else {
        // A bare array of boundary elements: the type follows from its width.
        py::array a = py::array::ensure(array);
        const py::ssize_t k = a && a.ndim() == 2 ? a.shape(1) : 0;
        if (boundary_dim == 1 && k == 2) t = CellType::line;
        if (boundary_dim == 2 && k == 3) t = CellType::triangle;
        if (boundary_dim == 2 && k == 4) t = CellType::quadrilateral;
        if (!t)
            throw py::value_error(what + ": cannot tell the element type of an array of shape " +
                                  (a ? shape_text(a) : std::string("?")) + " (boundary elements of a " +
                                  std::to_string(boundary_dim + 1) +
                                  "D mesh: lines (n, 2) in 2D, triangles (n, 3) or quadrilaterals (n, 4) in 3D); "
                                  "give a dict {type: array}");
        ids = node_ids(array, what.c_str(), k, &rows);
    }
    const auto k = static_cast<std::size_t>(nodes_per_cell(*t));
    list.reserve(list.size() + static_cast<std::size_t>(rows), static_cast<int>(k));
    for (py::ssize_t r = 0; r < rows; ++r) list.push_back(*t, {ids.data() + static_cast<std::size_t>(r) * k, k});
}

/// Elements from a dict {type: array} or a sequence of (type, array) pairs
/// (or, with `boundary_dim` >= 0, a bare array whose type follows from its width).
ElementList element_list(py::handle obj, const std::string& what, int boundary_dim) {
    ElementList list;
    if (py::isinstance<py::dict>(obj)) {
        for (auto item : py::reinterpret_borrow<py::dict>(obj))
            append_block(list, item.first, item.second, what + "['" + py::str(item.first).cast<std::string>() + "']",
                         boundary_dim);
    } else if (boundary_dim >= 0 && (py::isinstance<py::array>(obj) || py::isinstance<py::list>(obj)) &&
               !(py::len(obj) > 0 && py::isinstance<py::tuple>(obj[py::int_(0)]))) {
        append_block(list, py::none(), obj, what, boundary_dim);
    } else if (py::isinstance<py::sequence>(obj) && !py::isinstance<py::str>(obj)) {
        std::size_t i = 0;
        for (auto block : obj) {
            const std::string where = what + "[" + std::to_string(i++) + "]";
            if (!py::isinstance<py::sequence>(block) || py::len(block) != 2)
                throw py::type_error(where + " must be a (cell type, array) pair");
            append_block(list, block[py::int_(0)], block[py::int_(1)], where, boundary_dim);
        }
    } else {
        throw py::type_error(what + " must be a dict {cell type: array} or a list of (cell type, array) pairs, got " +
                             py::str(py::type::of(obj)).cast<std::string>());
    }
    return list;
}

struct MarkerView {
    std::string name;
    py::object nodes;
    py::dict elements;
};

std::string describe(const Mesh& mesh) {
    std::string s = "dgwarp.Mesh(" + std::to_string(mesh.dim) + "D, " + std::to_string(mesh.num_points()) +
                    " nodes, " + std::to_string(mesh.cells.size()) + " cells (";
    const auto counts = count_by_type(mesh.cells);
    bool first = true;
    for (CellType t : all_cell_types) {
        if (counts[static_cast<std::size_t>(t)] == 0) continue;
        s += (first ? "" : ", ") + std::to_string(counts[static_cast<std::size_t>(t)]) + " " +
             std::string(cell_type_name(t));
        first = false;
    }
    s += "), markers:";
    for (const Marker& marker : mesh.markers) s += " " + marker.name;
    return s + (mesh.markers.empty() ? " none)" : ")");
}

/// Named arrays with `count` rows (count × components values, row-major).
std::vector<Field> fields(py::handle obj, const char* what, std::size_t count) {
    std::vector<Field> out;
    if (obj.is_none()) return out;
    if (!py::isinstance<py::dict>(obj)) throw py::type_error(std::string(what) + " must be a dict {name: array}");
    for (auto item : py::reinterpret_borrow<py::dict>(obj)) {
        const std::string name = py::str(item.first);
        const std::string where = std::string(what) + "['" + name + "']";
        const py::array a = float_array(item.second, where.c_str());
        const py::ssize_t components = a.ndim() == 2 ? a.shape(1) : 1;
        const auto values = a.ndim() == 1 ? float_vector(a, where.c_str(), static_cast<py::ssize_t>(count))
                                          : float_matrix(a, where.c_str(), static_cast<py::ssize_t>(count),
                                                         components, 0, false);
        out.push_back({name, static_cast<int>(components), std::vector<double>(values.data(), values.data() + values.size())});
    }
    return out;
}

/// Refuses, before anything is written, what write() would do silently:
/// replace the file the mesh was read from (as the CLI refuses an output that
/// is its input), or drop point / cell data a format cannot hold.
void check_write_target(const PyMesh& p, const std::filesystem::path& path, const MeshFields& f) {
    std::error_code ec;
    if (!p.source.empty() && std::filesystem::exists(path, ec) && std::filesystem::equivalent(path, p.source, ec))
        throw py::value_error(path.string() + " is the file this mesh was read from (" + p.source +
                              "): it would be overwritten; write to another name");
    const std::string ext = lower_case_extension(path);
    if ((!f.point_data.empty() || !f.cell_data.empty()) && ext != ".vtu")
        throw py::value_error(std::string(f.point_data.empty() ? "cell_data" : "point_data") +
                              ": only .vtu files hold point and cell data; " + path.string() +
                              " would be written without it (write a .vtu, or leave the data out)");
}

/// `mesh`'s dimension and points from `points`, (n, 2) or (n, 3) float64 (copied).
void set_points(Mesh& mesh, py::handle points) {
    const py::array pa = float_array(points, "points");
    const py::ssize_t dim = pa.ndim() == 2 ? pa.shape(1) : 0;
    if (dim != 2 && dim != 3) throw py::value_error("points must have shape (n, 2) or (n, 3), got " + shape_text(pa));
    const auto xs = float_matrix(pa, "points", any_rows, dim);
    mesh.dim = static_cast<int>(dim);
    mesh.points.assign(xs.data(), xs.data() + xs.size());
}

}  // namespace

std::span<const double> mesh_points_arg(const PyMesh& m, py::handle points, const char* name, py::object& keep) {
    if (points.is_none()) return m.mesh.points;
    const auto a = float_matrix(points, name, static_cast<py::ssize_t>(m.mesh.num_points()), m.mesh.dim);
    keep = a;
    return {a.data(), static_cast<std::size_t>(a.size())};
}

void bind_mesh(py::module_& m) {
    py::class_<MarkerView>(m, "Marker", "A named boundary marker: its nodes and its boundary elements.")
        .def_readonly("name", &MarkerView::name, "The marker's name.")
        .def_readonly("nodes", &MarkerView::nodes, "Its node ids, sorted, without duplicates (int32).")
        .def_readonly("elements", &MarkerView::elements,
                      "Its boundary elements: cell type name -> (n, k) int32 array of node ids.")
        .def("__repr__", [](const MarkerView& v) {
            return "dgwarp.Marker('" + v.name + "', " + std::to_string(py::len(v.nodes)) + " nodes)";
        });

    py::class_<PyMesh, std::shared_ptr<PyMesh>>(
        m, "Mesh",
        "A mesh: points (num_points x dim, float64), cells by type, named boundary markers.\n\n"
        "Immutable: its arrays are read-only views of the mesh's own memory. Deformed\n"
        "coordinates live in arrays of their own (Plan.deform's result), and\n"
        "Mesh.write(path, points=...) writes the mesh with them.")
        .def_property_readonly("dim", [](const PyMesh& p) { return p.mesh.dim; }, "2 or 3.")
        .def_property_readonly("num_points", [](const PyMesh& p) { return p.mesh.num_points(); }, "The number of nodes.")
        .def_property_readonly("num_cells", [](const PyMesh& p) { return p.mesh.cells.size(); },
                               "The number of volume cells (triangles and quadrilaterals in 2D).")
        .def_property_readonly(
            "points",
            [](py::object self) {
                const auto& mesh = self.cast<const PyMesh&>().mesh;
                return read_only_view(mesh.points.data(),
                                      {static_cast<py::ssize_t>(mesh.num_points()), static_cast<py::ssize_t>(mesh.dim)},
                                      self);
            },
            "The coordinates, (num_points, dim) float64, row-major: a read-only view (no copy).")
        .def_property_readonly(
            "cells", [](py::object self) { return elements_by_type(self.cast<const PyMesh&>().mesh.cells, self); },
            "The volume cells by type: name ('triangle', 'quadrilateral', 'tetrahedron', 'hexahedron', 'prism',\n"
            "'pyramid') -> (n, k) int32 array of node ids (VTK's node order), in file order. A read-only view\n"
            "when the mesh has one cell type; copies otherwise (see cell_index for where each cell is).")
        .def_property_readonly(
            "cell_index", [](const PyMesh& p) { return indices_by_type(p.mesh.cells); },
            "Type name -> int64 array: the position of each cell of `cells[type]` in the mesh's cell order\n"
            "(the order of per-cell arrays such as quality(...).cells).")
        .def_property_readonly(
            "markers",
            [](py::object self) {
                const auto& mesh = self.cast<const PyMesh&>().mesh;
                py::dict out;
                for (const Marker& marker : mesh.markers) {
                    const std::vector<NodeId> nodes = marker_nodes(marker);
                    out[py::str(marker.name)] = MarkerView{
                        marker.name, copied_array<NodeId>(nodes, {static_cast<py::ssize_t>(nodes.size())}),
                        elements_by_type(marker.elements, self)};
                }
                return out;
            },
            "The boundary markers in file order: name -> Marker (nodes, elements).")
        .def_property_readonly(
            "marker_names",
            [](const PyMesh& p) {
                std::vector<std::string> names;
                for (const Marker& marker : p.mesh.markers) names.push_back(marker.name);
                return names;
            },
            "The markers' names, in file order.")
        .def_property_readonly("source", [](const PyMesh& p) { return p.source; },
                               "The file the mesh was read from ('' when built from arrays).")
        .def_static(
            "from_arrays",
            [](py::handle points, py::handle cells, py::handle markers) {
                auto p = std::make_shared<PyMesh>();
                set_points(p->mesh, points);
                const py::ssize_t dim = p->mesh.dim;
                p->mesh.cells = element_list(cells, "cells", -1);
                if (!markers.is_none()) {
                    if (!py::isinstance<py::dict>(markers))
                        throw py::type_error("markers must be a dict {name: elements}");
                    for (auto item : py::reinterpret_borrow<py::dict>(markers)) {
                        const std::string name = py::str(item.first);
                        p->mesh.markers.push_back(
                            {name, element_list(item.second, "markers['" + name + "']", static_cast<int>(dim) - 1)});
                    }
                }
                validate(p->mesh);
                return p;
            },
            py::arg("points"), py::arg("cells"), py::arg("markers") = py::none(),
            "A mesh from arrays (copied into the mesh):\n"
            "  points:  (n, 2) or (n, 3) float64;\n"
            "  cells:   {type: (m, k) integer node ids} or [(type, array), ...] (the order of the cells);\n"
            "  markers: {name: elements}, elements as cells, or one (m, k) array of boundary elements\n"
            "           (lines (m, 2) in 2D; triangles (m, 3) or quadrilaterals (m, 4) in 3D).\n"
            "Node ids are 0-based; node order within a cell is VTK's. Raises MeshError for an id out of\n"
            "range or a cell of the wrong dimension.")
        .def_static(
            "point_cloud",
            [](py::handle points, py::handle markers) {
                auto p = std::make_shared<PyMesh>();
                set_points(p->mesh, points);
                if (!py::isinstance<py::dict>(markers)) throw py::type_error("markers must be a dict {name: node ids}");
                for (auto item : py::reinterpret_borrow<py::dict>(markers)) {
                    const std::string name = py::str(item.first);
                    Marker marker{name, {}};
                    for (NodeId n : node_ids(item.second, ("markers['" + name + "']").c_str(), any_rows))
                        marker.elements.push_back(CellType::vertex, std::span<const NodeId>(&n, 1));
                    p->mesh.markers.push_back(std::move(marker));
                }
                validate_point_cloud(p->mesh);
                return p;
            },
            py::arg("points"), py::arg("markers"),
            "A point cloud: points (n, 2) or (n, 3) float64 and markers {name: node ids}, no cells. Its\n"
            "markers' nodes are the boundary: prepare() and Plan.deform move the other points as a mesh's\n"
            "volume nodes (every method but laplacian, which needs cells; dg-harmonic without its guard,\n"
            "which measures cells). Nothing measures a cloud's quality, and mesh files need cells: write\n"
            "its points yourself.")
        .def(
            "write",
            [](const PyMesh& p, const std::filesystem::path& path, py::handle points, py::handle point_data,
               py::handle cell_data, int gmsh_version) {
                py::object keep;
                const std::span<const double> xs = mesh_points_arg(p, points, "points", keep);
                MeshFields f;
                f.point_data = fields(point_data, "point_data", p.mesh.num_points());
                f.cell_data = fields(cell_data, "cell_data", p.mesh.cells.size());
                if (gmsh_version != 41 && gmsh_version != 22)
                    throw py::value_error("gmsh_version must be 41 or 22, got " + std::to_string(gmsh_version));
                check_write_target(p, path, f);
                WriteOptions options;
                options.gmsh_version = gmsh_version;
                options.extras = &p.extras;
                if (const std::string w = dropped_extras_warning(p.extras, p.source, path); !w.empty()) warn(w);
                py::gil_scoped_release release;
                if (points.is_none()) return write_mesh(path, p.mesh, f, options);
                Mesh moved{p.mesh.dim, std::vector<double>(xs.begin(), xs.end()), p.mesh.cells, p.mesh.markers};
                write_mesh(path, moved, f, options);
            },
            py::arg("path"), py::arg("points") = py::none(), py::arg("point_data") = py::none(),
            py::arg("cell_data") = py::none(), py::arg("gmsh_version") = 41,
            "Writes the mesh (format by extension: .su2, .msh, .vtu), atomically.\n"
            "  points:     other coordinates to write, (num_points, dim) float64 (e.g. deformed ones);\n"
            "  point_data: {name: (num_points,) or (num_points, k) array} (VTU only);\n"
            "  cell_data:  {name: (num_cells,) or (num_cells, k) array} (VTU only);\n"
            "  gmsh_version: 41 or 22 for .msh.\n"
            "An .su2 output keeps the other zones, FFD boxes and periodic data of the file the mesh was read\n"
            "from; other formats cannot hold them (a DgwarpWarning says what is dropped).")
        .def(
            "write_time",
            [](const PyMesh& p, const std::filesystem::path& case_folder, const std::string& time, py::handle points) {
                py::object keep;
                const std::span<const double> xs = mesh_points_arg(p, points, "points", keep);
                if (p.mesh.dim != 3)
                    throw py::value_error("OpenFOAM meshes are 3D: this mesh is " + std::to_string(p.mesh.dim) + "D");
                if (!is_openfoam_time_name(time))
                    throw py::value_error("time: '" + time +
                                          "' is not a time folder's name: give a number (0, 0.001, 1e-05) or 'constant'");
                std::vector<std::filesystem::path> inputs;
                if (!p.source.empty()) {
                    inputs = mesh_input_files(p.source);
                    inputs.emplace_back(p.source);
                }
                py::gil_scoped_release release;
                check_openfoam_frame_outputs(case_folder, {time}, p.source, inputs);
                write_openfoam_frame_base(case_folder, time, p.mesh, p.extras);
                return write_openfoam_frame_points(case_folder, time, xs, p.extras);
            },
            py::arg("case"), py::arg("time"), py::arg("points"),
            "Writes `points` ((num_points, 3) float64, e.g. a plan's deformed ones) as the OpenFOAM case folder\n"
            "`case`'s time `time` ('0.5', or 'constant'): case/<time>/polyMesh/points, as `dgwarp deform -o\n"
            "case/ --foam-time <time>` writes it, with the case's constant/polyMesh (a copy of the case this\n"
            "mesh was read from, unless it is that case; another format's mesh written whole); a decomposed\n"
            "case's processor folders each get their own points. Each file atomically; returns the points file\n"
            "(processor* for a decomposed case). Raises ValueError for a 2D mesh or a time that is no number,\n"
            "InputError for an output that is one of the mesh's files, IoError when it cannot be written.")
        .def(py::pickle([](const PyMesh& p) { return mesh_state(p); },
                        [](const py::tuple& state) { return mesh_from_state(state); }))
        .def("__repr__", [](const PyMesh& p) { return describe(p.mesh); });

    m.def(
        "read",
        [](const std::filesystem::path& path, std::optional<int> zone, py::object progress) {
            auto p = std::make_shared<PyMesh>();
            ReadOptions options;
            if (zone) {
                if (*zone < 1) throw py::value_error("zone must be 1 or more (SU2's IZONE), got " + std::to_string(*zone));
                options.zone = *zone;
            }
            p->source = path.string();
            ProgressBridge bridge(progress);
            bridge.run([&] { p->mesh = read_mesh(path, options, bridge.function(), p->extras); });
            return p;
        },
        py::arg("path"), py::arg("zone") = py::none(), py::arg("progress") = py::none(),
        "Reads a mesh; the format comes from the extension (.su2, .msh, .vtu).\n"
        "  zone: which zone of a multi-zone SU2 file (1-based; default 1);\n"
        "  progress: a callable taking the fraction of the file read (0..1).\n"
        "Raises IoError (OSError) when the file cannot be read, ParseError (ValueError) naming the file\n"
        "and line when it is malformed, FormatError for an unsupported extension, MeshError when its\n"
        "content is inconsistent.");
}

}  // namespace dgwarp::python
