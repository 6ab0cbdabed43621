// Pickling dgwarp.Mesh (docs/PYTHON.md, "Pickling"): the mesh's arrays as
// bytes (points, and each element list's types, offsets and node ids), its
// markers, the file it was read from, and what that file held besides the
// mesh (MeshExtras: an SU2 file's other zones, an OpenFOAM case's patches and
// processors, a CGNS file's zones), so that an unpickled mesh writes what the
// original writes. The paths in the extras name the files read: an OpenFOAM
// or CGNS output written in place needs them, as the original mesh does.
#include <pybind11/stl.h>

#include <cstring>
#include <type_traits>

#include "py_mesh.hpp"

namespace py = pybind11;

namespace dgwarp::python {

namespace {

constexpr const char* mesh_state_tag = "dgwarp.Mesh";
constexpr int mesh_state_version = 1;

template <class T>
py::bytes to_bytes(const std::vector<T>& v) {
    static_assert(std::is_trivially_copyable_v<T>);
    return py::bytes(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(T));
}

template <class T>
std::vector<T> from_bytes(py::handle obj, const char* what) {
    const std::string raw = obj.cast<std::string>();
    if (raw.size() % sizeof(T) != 0)
        throw py::value_error(std::string("a pickled dgwarp.Mesh: ") + what + " holds " + std::to_string(raw.size()) +
                              " bytes, not a whole number of values");
    std::vector<T> v(raw.size() / sizeof(T));
    if (!raw.empty()) std::memcpy(v.data(), raw.data(), raw.size());
    return v;
}

py::tuple elements_state(const ElementList& e) {
    if (!e.has_faces()) return py::make_tuple(to_bytes(e.types), to_bytes(e.offsets), to_bytes(e.nodes));
    return py::make_tuple(to_bytes(e.types), to_bytes(e.offsets), to_bytes(e.nodes), to_bytes(e.face_first),
                          to_bytes(e.face_offsets), to_bytes(e.face_nodes));
}

ElementList elements_from_state(py::handle obj, const char* what) {
    const auto t = obj.cast<py::tuple>();
    if (t.size() != 3 && t.size() != 6) throw py::value_error(std::string("a pickled dgwarp.Mesh: bad ") + what);
    ElementList e;
    e.types = from_bytes<CellType>(t[0], what);
    e.offsets = from_bytes<std::int64_t>(t[1], what);
    e.nodes = from_bytes<NodeId>(t[2], what);
    if (t.size() == 6) {  // polyhedra's faces
        e.face_first = from_bytes<std::int64_t>(t[3], what);
        e.face_offsets = from_bytes<std::int64_t>(t[4], what);
        e.face_nodes = from_bytes<NodeId>(t[5], what);
    }
    // validate() reads the elements through their offsets: check those first.
    const auto increasing = [](const std::vector<std::int64_t>& v, std::size_t size, std::int64_t last) {
        if (v.size() != size + 1 || v.front() != 0 || v.back() != last) return false;
        for (std::size_t i = 0; i < size; ++i)
            if (v[i] > v[i + 1]) return false;
        return true;
    };
    bool ok = increasing(e.offsets, e.types.size(), static_cast<std::int64_t>(e.nodes.size()));
    for (std::size_t i = 0; ok && i < e.types.size(); ++i)
        ok = static_cast<std::uint8_t>(e.types[i]) <= static_cast<std::uint8_t>(CellType::polyhedron);
    if (ok && t.size() == 6)
        ok = !e.face_offsets.empty() &&
             increasing(e.face_offsets, e.face_offsets.size() - 1, static_cast<std::int64_t>(e.face_nodes.size())) &&
             increasing(e.face_first, e.types.size(), static_cast<std::int64_t>(e.face_offsets.size()) - 1);
    if (!ok) throw py::value_error(std::string("a pickled dgwarp.Mesh: inconsistent ") + what);
    return e;
}

py::object su2_state(const std::optional<Su2Surroundings>& s) {
    if (!s) return py::none();
    return py::make_tuple(py::bytes(s->before), py::bytes(s->after), s->zone_has_ndime, s->num_points, s->num_cells,
                          s->zones, s->contents);
}

std::optional<Su2Surroundings> su2_from_state(py::handle obj) {
    if (obj.is_none()) return std::nullopt;
    const auto t = obj.cast<py::tuple>();
    Su2Surroundings s;
    s.before = t[0].cast<std::string>();
    s.after = t[1].cast<std::string>();
    s.zone_has_ndime = t[2].cast<bool>();
    s.num_points = t[3].cast<std::int64_t>();
    s.num_cells = t[4].cast<std::int64_t>();
    s.zones = t[5].cast<std::int64_t>();
    s.contents = t[6].cast<std::vector<std::string>>();
    return s;
}

py::object openfoam_state(const std::optional<OpenFoamSource>& s) {
    if (!s) return py::none();
    py::list patches, processors;
    for (const OpenFoamPatch& p : s->patches) patches.append(py::make_tuple(p.type, p.entries));
    for (const OpenFoamProcessor& p : s->processors)
        processors.append(py::make_tuple(p.poly_mesh.string(), static_cast<int>(p.points_format), to_bytes(p.points)));
    return py::make_tuple(s->poly_mesh.string(), static_cast<int>(s->points_format), patches, processors);
}

foam::Format format_from_state(py::handle obj) {
    const int f = obj.cast<int>();
    if (f != static_cast<int>(foam::Format::ascii) && f != static_cast<int>(foam::Format::binary))
        throw py::value_error("a pickled dgwarp.Mesh: bad OpenFOAM format " + std::to_string(f));
    return static_cast<foam::Format>(f);
}

std::optional<OpenFoamSource> openfoam_from_state(py::handle obj) {
    if (obj.is_none()) return std::nullopt;
    const auto t = obj.cast<py::tuple>();
    OpenFoamSource s;
    s.poly_mesh = t[0].cast<std::string>();
    s.points_format = format_from_state(t[1]);
    for (auto item : t[2].cast<py::list>()) {
        const auto p = item.cast<py::tuple>();
        s.patches.push_back({p[0].cast<std::string>(), p[1].cast<std::vector<std::string>>()});
    }
    for (auto item : t[3].cast<py::list>()) {
        const auto p = item.cast<py::tuple>();
        s.processors.push_back({p[0].cast<std::string>(), format_from_state(p[1]),
                                from_bytes<NodeId>(p[2], "an OpenFOAM processor's points")});
    }
    return s;
}

py::object cgns_state(const std::optional<CgnsSource>& s) {
    if (!s) return py::none();
    py::list zones;
    for (const CgnsZone& z : s->zones) zones.append(py::make_tuple(z.name, to_bytes(z.points)));
    // Its markers' BC types too: they make markers slide (io/marker_types.hpp).
    return py::make_tuple(s->file.string(), zones, s->num_points, s->dim, s->marker_types, s->exterior_marker);
}

std::optional<CgnsSource> cgns_from_state(py::handle obj) {
    if (obj.is_none()) return std::nullopt;
    const auto t = obj.cast<py::tuple>();
    CgnsSource s;
    s.file = t[0].cast<std::string>();
    for (auto item : t[1].cast<py::list>()) {
        const auto z = item.cast<py::tuple>();
        s.zones.push_back({z[0].cast<std::string>(), from_bytes<NodeId>(z[1], "a CGNS zone's points")});
    }
    s.num_points = t[2].cast<std::size_t>();
    s.dim = t[3].cast<int>();
    if (t.size() >= 6) {  // (pickles from before the BC types have four entries)
        s.marker_types = t[4].cast<std::vector<std::string>>();
        s.exterior_marker = t[5].cast<bool>();
    }
    return s;
}

}  // namespace

py::tuple mesh_state(const PyMesh& p) {
    py::list markers;
    for (const Marker& m : p.mesh.markers) markers.append(py::make_tuple(m.name, elements_state(m.elements)));
    return py::make_tuple(mesh_state_tag, mesh_state_version, p.mesh.dim, to_bytes(p.mesh.points),
                          elements_state(p.mesh.cells), markers, p.source, su2_state(p.extras.su2),
                          openfoam_state(p.extras.openfoam), cgns_state(p.extras.cgns));
}

std::shared_ptr<PyMesh> mesh_from_state(const py::tuple& t) {
    if (t.size() != 10 || !py::isinstance<py::str>(t[0]) || t[0].cast<std::string>() != mesh_state_tag)
        throw py::value_error("not the pickled state of a dgwarp.Mesh");
    if (t[1].cast<int>() != mesh_state_version)
        throw py::value_error("a dgwarp.Mesh pickled by another version of dgwarp (state version " +
                              py::str(t[1]).cast<std::string>() + ", this one reads " +
                              std::to_string(mesh_state_version) + ")");
    auto p = std::make_shared<PyMesh>();
    p->mesh.dim = t[2].cast<int>();
    if (p->mesh.dim != 2 && p->mesh.dim != 3) throw py::value_error("a pickled dgwarp.Mesh: dim is not 2 or 3");
    p->mesh.points = from_bytes<double>(t[3], "points");
    if (p->mesh.points.size() % static_cast<std::size_t>(p->mesh.dim) != 0)
        throw py::value_error("a pickled dgwarp.Mesh: points are not whole rows");
    p->mesh.cells = elements_from_state(t[4], "cells");
    for (auto item : t[5].cast<py::list>()) {
        const auto m = item.cast<py::tuple>();
        p->mesh.markers.push_back({m[0].cast<std::string>(), elements_from_state(m[1], "marker elements")});
    }
    p->source = t[6].cast<std::string>();
    p->extras.su2 = su2_from_state(t[7]);
    p->extras.openfoam = openfoam_from_state(t[8]);
    p->extras.cgns = cgns_from_state(t[9]);
    // MeshError for node ids out of range, cells of another dimension, ...
    if (p->mesh.cells.empty()) validate_point_cloud(p->mesh);
    else validate(p->mesh);
    return p;
}

}  // namespace dgwarp::python
