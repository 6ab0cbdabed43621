// dgwarp.quality: Knupp's shape quality per cell and its summary, as
// `dgwarp quality MESH [--reference ORIGINAL]` computes them.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "arrays.hpp"
#include "bindings.hpp"
#include "dgwarp/core/error.hpp"
#include "dgwarp/quality/mesh_quality.hpp"
#include "py_mesh.hpp"

namespace py = pybind11;

namespace dgwarp::python {

namespace {

struct QualityResult {
    py::array_t<double> cells;
    QualitySummary summary;
    py::object ratio = py::none();
    std::optional<RatioSummary> ratio_summary;
};

template <class T>
py::array_t<T> moved_array(std::vector<T>&& v) {
    auto* owned = new std::vector<T>(std::move(v));
    py::capsule free_when_done(owned, [](void* p) { delete static_cast<std::vector<T>*>(p); });
    return py::array_t<T>(static_cast<py::ssize_t>(owned->size()), owned->data(), free_when_done);
}

}  // namespace

void bind_quality(py::module_& m) {
    py::class_<QualityResult>(m, "Quality",
                              "Knupp's shape quality of every cell (1 ideal, <= 0 inverted; docs/QUALITY.md) and its "
                              "summary.")
        .def_readonly("cells", &QualityResult::cells, "Per-cell quality, float64, in the mesh's cell order.")
        .def_property_readonly("min", [](const QualityResult& q) { return q.summary.min; }, "The smallest quality.")
        .def_property_readonly("mean", [](const QualityResult& q) { return q.summary.mean; },
                               "The mean quality (a compensated sum in cell order: deterministic).")
        .def_property_readonly("inverted", [](const QualityResult& q) { return q.summary.inverted; },
                               "Cells with quality <= 0.")
        .def_property_readonly("worst_cell", [](const QualityResult& q) { return q.summary.worst_cell; },
                               "The first cell with the smallest quality (-1 for a mesh without cells).")
        .def_property_readonly(
            "histogram",
            [](const QualityResult& q) {
                return py::make_tuple(copied_array<double>(q.summary.histogram.edges,
                                                           {static_cast<py::ssize_t>(q.summary.histogram.edges.size())}),
                                      copied_array<std::int64_t>(
                                          q.summary.histogram.counts,
                                          {static_cast<py::ssize_t>(q.summary.histogram.counts.size())}));
            },
            "(edges, counts): bins (-inf, 0], (0, 0.1], ..., (0.9, 1] as `dgwarp quality --histogram` prints.")
        .def_readonly("ratio", &QualityResult::ratio,
                      "Per-cell ratio quality / reference quality (0 where the reference cell is not valid); None "
                      "without a reference.")
        .def_property_readonly(
            "ratio_min",
            [](const QualityResult& q) { return q.ratio_summary ? py::object(py::float_(q.ratio_summary->min)) : py::none(); },
            "The smallest ratio (None without a reference).")
        .def_property_readonly(
            "ratio_mean",
            [](const QualityResult& q) { return q.ratio_summary ? py::object(py::float_(q.ratio_summary->mean)) : py::none(); },
            "The mean ratio (None without a reference).")
        .def_property_readonly(
            "ratio_worst_cell",
            [](const QualityResult& q) {
                return q.ratio_summary ? py::object(py::int_(q.ratio_summary->worst_cell)) : py::none();
            },
            "The first cell with the smallest ratio (None without a reference).")
        .def("__repr__", [](const QualityResult& q) {
            std::string s = "dgwarp.Quality(min=" + py::repr(py::float_(q.summary.min)).cast<std::string>() +
                            ", mean=" + py::repr(py::float_(q.summary.mean)).cast<std::string>() +
                            ", inverted=" + std::to_string(q.summary.inverted) +
                            ", worst_cell=" + std::to_string(q.summary.worst_cell);
            if (q.ratio_summary) s += ", ratio_min=" + py::repr(py::float_(q.ratio_summary->min)).cast<std::string>();
            return s + ")";
        });

    m.def(
        "quality",
        [](const PyMesh& mesh, py::handle points, const PyMesh* reference) {
            py::object keep;
            const std::span<const double> xs = mesh_points_arg(mesh, points, "points", keep);
            if (!reference && !points.is_none()) reference = &mesh;  // the points' own original
            if (reference && reference->mesh.cells != mesh.mesh.cells)
                throw MeshError("reference: the reference mesh has other cells than the mesh (it must be the same mesh "
                                "before deformation)");
            QualityResult r;
            std::vector<double> quality, ratio;
            {
                py::gil_scoped_release release;
                if (reference) {
                    const std::vector<std::int8_t> orientation = cell_orientations(reference->mesh);
                    const std::vector<double> original = cell_qualities(reference->mesh, orientation);
                    quality = cell_qualities(mesh.mesh, xs, orientation);
                    ratio = quality_ratios(quality, original);
                    r.ratio_summary = summarize_ratios(ratio);
                } else {
                    quality = cell_qualities(mesh.mesh, dominant_orientations(mesh.mesh));
                }
                r.summary = summarize_quality(quality);
            }
            r.cells = moved_array(std::move(quality));
            if (reference) r.ratio = moved_array(std::move(ratio));
            return r;
        },
        py::arg("mesh").none(false), py::arg("points") = py::none(), py::arg("reference") = py::none(),
        "Knupp's shape quality of every cell of `mesh`, and its summary.\n"
        "  points:    other coordinates of the mesh's nodes to judge, (num_points, dim) float64\n"
        "             (e.g. Plan.deform's result); the mesh itself is then the reference;\n"
        "  reference: the undeformed mesh (same cells): cells are judged against its orientation\n"
        "             and the per-cell ratio to its quality is reported, as\n"
        "             `dgwarp quality MESH --reference ORIGINAL`.\n"
        "Without either, a cell is inverted when it is oriented against most cells of its type,\n"
        "as `dgwarp quality MESH`.");
}

}  // namespace dgwarp::python
