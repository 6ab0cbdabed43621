// Dispatch of the per-element shape metric and orientation by cell type.
#include "dgwarp/quality/cell_quality.hpp"

#include <array>
#include <cassert>

#include "dgwarp/quality/element_quality.hpp"

namespace dgwarp {

using quality_detail::Point3;

double cell_shape_quality(CellType type, std::span<const double> coords, int dim, int orientation) {
    assert(dim == 2 || dim == 3);
    assert(coords.size() >= static_cast<std::size_t>(nodes_per_cell(type) * dim));
    const int sign = orientation < 0 ? -1 : 1;
    std::array<Point3, 8> storage;
    const std::span<Point3> x(storage.data(), static_cast<std::size_t>(nodes_per_cell(type)));
    quality_detail::to_scaled_points(coords, dim, x);
    switch (type) {
        case CellType::triangle: return quality_detail::triangle_quality(x, dim == 2, sign);
        case CellType::quadrilateral: return quality_detail::quadrilateral_quality(x, dim == 2, sign);
        case CellType::tetrahedron: return quality_detail::tetrahedron_quality(x, sign);
        case CellType::hexahedron: return quality_detail::hexahedron_quality(x, sign);
        case CellType::prism: return quality_detail::prism_quality(x, sign);
        case CellType::pyramid: return quality_detail::pyramid_quality(x, sign);
        case CellType::vertex:
        case CellType::line:
        case CellType::polygon:      // by their nodes and faces:
        case CellType::polyhedron: return 0.0;  // element_shape_quality
    }
    return 0.0;
}

int cell_orientation(CellType type, std::span<const double> coords, int dim) {
    assert(dim == 2 || dim == 3);
    assert(coords.size() >= static_cast<std::size_t>(nodes_per_cell(type) * dim));
    std::array<Point3, 8> storage;
    const std::span<Point3> x(storage.data(), static_cast<std::size_t>(nodes_per_cell(type)));
    quality_detail::to_scaled_points(coords, dim, x);
    double measure = 0;
    switch (type) {
        // Faces in 3D space have no orientation of their own.
        case CellType::triangle: measure = dim == 2 ? quality_detail::triangle_alpha_2d(x) : 0.0; break;
        case CellType::quadrilateral: measure = dim == 2 ? quality_detail::quadrilateral_alpha_sum_2d(x) : 0.0; break;
        case CellType::tetrahedron: measure = quality_detail::tetrahedron_alpha(x); break;
        case CellType::hexahedron: measure = quality_detail::hexahedron_alpha_sum(x); break;
        case CellType::prism: measure = quality_detail::prism_alpha_sum(x); break;
        case CellType::pyramid: measure = quality_detail::pyramid_alpha_sum(x); break;
        case CellType::vertex:
        case CellType::line:
        case CellType::polygon:  // element_orientation
        case CellType::polyhedron: break;
    }
    return measure < 0 ? -1 : 1;
}

}  // namespace dgwarp
