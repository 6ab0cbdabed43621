#pragma once
// What a report says about a mesh's size: its nodes, cells by type and
// markers. A part of a mesh held by one process counts its own; summed over
// the processes (mpi_job/processor_job.hpp) they are the whole mesh's.
#include <cstdint>
#include <string>
#include <vector>

#include "dgwarp/mesh/mesh.hpp"

namespace dgwarp {

struct MeshCounts {
    int dim = 3;
    std::int64_t nodes = 0, cells = 0;
    std::vector<std::int64_t> cell_types;  // per CellType (count_by_type)
    struct MarkerCounts {
        std::string name;
        std::int64_t elements = 0, nodes = 0;  // nodes: each once (marker_nodes)
    };
    std::vector<MarkerCounts> markers;  // in the mesh's order
};

/// The counts of `mesh`.
MeshCounts mesh_counts(const Mesh& mesh);

}  // namespace dgwarp
