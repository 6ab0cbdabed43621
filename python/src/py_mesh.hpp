#pragma once
// dgwarp.Mesh: the library's Mesh (and what its file held besides it), shared
// by the Python objects that use it (plans keep theirs alive). Immutable from
// Python: its arrays are read-only views, so a plan can use the mesh it was
// prepared for without a copy.
#include <pybind11/pybind11.h>

#include <memory>
#include <string>

#include "dgwarp/io/mesh_io.hpp"
#include "dgwarp/mesh/mesh.hpp"

namespace dgwarp::python {

struct PyMesh {
    Mesh mesh;
    MeshExtras extras;   // an SU2 file's other zones, FFD boxes, ...: kept by write() to .su2
    std::string source;  // the file it was read from; "" when built from arrays
};

using MeshPtr = std::shared_ptr<const PyMesh>;

void bind_mesh(pybind11::module_& m);

/// A mesh's pickled state and the mesh from it (py_mesh_pickle.cpp).
pybind11::tuple mesh_state(const PyMesh& mesh);
std::shared_ptr<PyMesh> mesh_from_state(const pybind11::tuple& state);

/// `points` (None: the mesh's own) checked as the mesh's new coordinates:
/// float64, C-contiguous, num_points × dim, finite. Returns a span over it
/// (valid while `keep` lives).
std::span<const double> mesh_points_arg(const PyMesh& mesh, pybind11::handle points, const char* name,
                                        pybind11::object& keep);

}  // namespace dgwarp::python
