#pragma once
// A simple partition of a mesh's cells for `mpirun dgwarp` and the scaling
// benchmark: the cells sorted along a Morton curve of their centroids, cut
// into P blocks of equal count. Spatially compact whatever the file's cell
// order (Gmsh's 3D Delaunay numbers cells in a spatially random order, where
// blocks of the file's order would each touch nearly every node). Not a
// graph partitioner (METIS balances the interface too); a solver brings its own.
#include <cstdint>
#include <vector>

#include "dgwarp/mesh/mesh.hpp"

namespace dgwarp::mpi {

/// Per cell of `mesh`, its part in 0..parts-1 (parts >= 1).
std::vector<std::int32_t> morton_cell_parts(const Mesh& mesh, int parts);

}  // namespace dgwarp::mpi
