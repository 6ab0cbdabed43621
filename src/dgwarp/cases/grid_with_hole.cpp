#include "dgwarp/cases/grid_with_hole.hpp"

#include <vector>

#include "dgwarp/core/error.hpp"

namespace dgwarp {

Mesh make_grid_with_hole(const GridWithHoleOptions& o) {
    const int n = o.cells, rx = o.rect_cells_x, ry = o.rect_cells_y;
    if (!(o.box_half_size > 0) || n < 3 || rx < 1 || ry < 1 || rx > n - 2 || ry > n - 2 || (n - rx) % 2 != 0 ||
        (n - ry) % 2 != 0)
        throw MeshError("grid with a hole: the rectangle (" + std::to_string(rx) + " x " + std::to_string(ry) +
                        " cells) must fit inside the box (" + std::to_string(n) +
                        " cells) with an even number of cells on each side");
    const int i0 = (n - rx) / 2, i1 = i0 + rx, j0 = (n - ry) / 2, j1 = j0 + ry;
    auto in_hole = [&](int i, int j) { return i > i0 && i < i1 && j > j0 && j < j1; };  // strictly inside
    const double h = 2 * o.box_half_size / n;

    Mesh mesh;
    mesh.dim = 2;
    std::vector<NodeId> id(static_cast<std::size_t>(n + 1) * (n + 1), -1);
    auto at = [&](int i, int j) -> NodeId& { return id[static_cast<std::size_t>(j) * (n + 1) + i]; };
    NodeId next = 0;
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) {
            if (in_hole(i, j)) continue;
            at(i, j) = next++;
            mesh.points.push_back(-o.box_half_size + i * h);
            mesh.points.push_back(-o.box_half_size + j * h);
        }
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            if (i >= i0 && i < i1 && j >= j0 && j < j1) continue;  // cell inside the rectangle
            const NodeId q[] = {at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)};
            mesh.cells.push_back(CellType::quadrilateral, q);
        }
    // Boundary lines, each loop counter-clockwise.
    Marker rect{"rectangle", {}}, farfield{"farfield", {}};
    auto loop = [&](Marker& m, int a0, int a1, int b0, int b1) {
        std::vector<std::pair<int, int>> walk;
        for (int i = a0; i < a1; ++i) walk.emplace_back(i, b0);
        for (int j = b0; j < b1; ++j) walk.emplace_back(a1, j);
        for (int i = a1; i > a0; --i) walk.emplace_back(i, b1);
        for (int j = b1; j > b0; --j) walk.emplace_back(a0, j);
        for (std::size_t k = 0; k < walk.size(); ++k) {
            const auto [ia, ja] = walk[k];
            const auto [ib, jb] = walk[(k + 1) % walk.size()];
            const NodeId e[] = {at(ia, ja), at(ib, jb)};
            m.elements.push_back(CellType::line, e);
        }
    };
    loop(rect, i0, i1, j0, j1);
    loop(farfield, 0, n, 0, n);
    mesh.markers = {std::move(rect), std::move(farfield)};
    return mesh;
}

}  // namespace dgwarp
