// The rest of the API: the paper's test cases, the thread count, the
// untangle step on its own.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "arrays.hpp"
#include "bindings.hpp"
#include "dgwarp/cases/paper_cases.hpp"
#include "dgwarp/core/parallel_for.hpp"
#include "dgwarp/quality/mesh_quality.hpp"
#include "dgwarp/repair/untangle.hpp"
#include "py_mesh.hpp"

namespace py = pybind11;

namespace dgwarp::python {

void bind_extras(py::module_& m) {
    m.def("case_names", &case_names, "The names of the built-in test cases (`dgwarp case`).");
    m.def(
        "case",
        [](const std::string& name, int size) {
            auto p = std::make_shared<PyMesh>();
            py::gil_scoped_release release;
            p->mesh = make_case(name, size);
            return p;
        },
        py::arg("name"), py::arg("size") = 0,
        "The mesh of a built-in test case, as `dgwarp case NAME --size SIZE` writes it: the paper's\n"
        "rect-box, naca0012, twisted-bar, squeezed-sphere (sizes 0-2), wing-body (sizes 0-1), and\n"
        "two-element, store. Deterministic. Raises InputError for an unknown name or size.");
    m.def("num_threads", &num_threads, "The number of threads the library's loops use (for calls from this thread).");
    m.def(
        "set_num_threads",
        [](int n) {
            // As the CLI's --threads: a count out of range is refused, not clamped.
            if (n < 1 || n > max_threads())
                throw py::value_error("set_num_threads: n must be 1 to " + std::to_string(max_threads()) +
                                      " (4 per core, and at least 64; this machine has " +
                                      std::to_string(available_cores()) + " cores), got " + std::to_string(n));
            set_num_threads(n);
        },
        py::arg("n"),
        "Sets the number of threads of the library's loops, 1 to max (4 x cores, at least 64; ValueError\n"
        "otherwise), for later calls from the calling Python thread (OpenMP's setting is per thread;\n"
        "OMP_NUM_THREADS sets every thread's default).");
    m.def(
        "untangle",
        [](const PyMesh& mesh, py::handle points, py::handle fixed, double target) {
            auto xs = output_matrix(points, "points", static_cast<py::ssize_t>(mesh.mesh.num_points()), mesh.mesh.dim,
                                    true);
            std::vector<NodeId> fixed_nodes;
            if (fixed.is_none()) {
                for (const Marker& marker : mesh.mesh.markers) {
                    const std::vector<NodeId> ids = marker_nodes(marker);
                    fixed_nodes.insert(fixed_nodes.end(), ids.begin(), ids.end());
                }
            } else {
                fixed_nodes = node_ids(fixed, "fixed", any_rows);
            }
            UntangleOptions options;
            options.target_quality = target;
            UntangleReport r;
            {
                py::gil_scoped_release release;
                const std::vector<std::int8_t> orientation = cell_orientations(mesh.mesh);
                r = untangle(mesh.mesh.dim, mesh.mesh.cells, orientation, fixed_nodes,
                             {xs.mutable_data(), static_cast<std::size_t>(xs.size())}, options);
            }
            py::dict d;
            d["inverted_before"] = r.inverted_before;
            d["inverted_after"] = r.inverted_after;
            d["below_target_before"] = r.below_target_before;
            d["below_target_after"] = r.below_target_after;
            d["nodes_moved"] = r.nodes_moved;
            d["max_move"] = r.max_move;
            d["rounds"] = r.rounds;
            d["min_quality_after"] = r.min_quality_after;
            return d;
        },
        py::arg("mesh").none(false), py::arg("points"), py::arg("fixed") = py::none(), py::arg("target") = 0.0,
        "Repairs inverted cells of `points` (the mesh's deformed coordinates, float64 (num_points, dim),\n"
        "changed in place) by moving the volume nodes around them (docs/UNTANGLE.md); `fixed` node ids\n"
        "never move (default: every marker's nodes); cells at or below `target` are repaired too.\n"
        "Orientation is the mesh's own. Returns the report (counts before and after, nodes moved).");
}

}  // namespace dgwarp::python
