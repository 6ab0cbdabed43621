#pragma once
// A 3 × 3 grid of unit squares split into triangles (node (i, j) = 4 j + i)
// and its outer ring of 12 nodes, the fixed ones: the smallest mesh on
// which moving a volume node folds cells that a repair can mend.
#include <vector>

#include "dgwarp/mesh/mesh.hpp"

namespace dgwarp::test {

struct SplitGrid {
    Mesh mesh;
    std::vector<NodeId> ring;  // sorted
};

inline SplitGrid split_grid() {
    SplitGrid g;
    g.mesh.dim = 2;
    for (int n = 0; n < 16; ++n) {
        g.mesh.points.push_back(n % 4);
        g.mesh.points.push_back(n / 4);
        if (n % 4 == 0 || n % 4 == 3 || n / 4 == 0 || n / 4 == 3) g.ring.push_back(n);
    }
    for (NodeId j = 0; j < 3; ++j)
        for (NodeId i = 0; i < 3; ++i) {
            const NodeId a = 4 * j + i, t1[] = {a, a + 1, a + 5}, t2[] = {a, a + 5, a + 4};
            g.mesh.cells.push_back(CellType::triangle, t1);
            g.mesh.cells.push_back(CellType::triangle, t2);
        }
    return g;
}

}  // namespace dgwarp::test
