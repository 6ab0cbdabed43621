// Example 01: read a mesh and measure it.
//
// Shows the neutral Mesh (dim, row-major points, cells, named markers), how
// to read one from a file (the format comes from the extension), and the
// quality driver: Knupp's shape quality per cell and its summary.
//
// Run:   build/examples/01_read_and_measure              (the built-in rect-box)
//        build/examples/01_read_and_measure naca0012.su2 (any .su2 or .msh file)
#include <cstdio>
#include <iostream>

#include "dgwarp/cases/rect_box.hpp"
#include "dgwarp/core/error.hpp"
#include "dgwarp/io/mesh_io.hpp"
#include "dgwarp/quality/mesh_quality.hpp"

int main(int argc, char** argv) {
    using namespace dgwarp;
    try {
        // A mesh from a file, or the paper's rectangle in a box (2,340 nodes).
        const Mesh mesh = argc > 1 ? read_mesh(argv[1]) : make_rect_box();
        std::cout << "mesh " << (argc > 1 ? argv[1] : "rect-box (built in)") << "\n";
        std::cout << "dim " << mesh.dim << ", points " << mesh.num_points() << ", cells " << mesh.cells.size()
                  << "\n";

        // Cells of mixed types live in one ElementList; count them by type.
        const auto counts = count_by_type(mesh.cells);
        for (CellType t : all_cell_types)
            if (counts[static_cast<int>(t)] > 0)
                std::cout << "  " << cell_type_name(t) << " " << counts[static_cast<int>(t)] << "\n";

        // Markers: named lists of boundary elements (lines in 2D, faces in 3D).
        for (const Marker& m : mesh.markers)
            std::cout << "marker " << m.name << ": " << m.elements.size() << " elements, "
                      << marker_nodes(m).size() << " nodes\n";

        const BoundingBox box = bounding_box(mesh);
        std::cout << "bounding box";
        for (int d = 0; d < mesh.dim; ++d) std::cout << " [" << box.min[d] << ", " << box.max[d] << "]";
        std::cout << "\n";

        // Quality of a mesh on its own: each cell is judged against the
        // orientation most cells of its type have (a mirrored cell is inverted).
        const std::vector<double> quality = cell_qualities(mesh, dominant_orientations(mesh));
        const QualitySummary q = summarize_quality(quality);
        std::printf("quality min %.6f (cell %lld), mean %.6f\n", q.min, static_cast<long long>(q.worst_cell),
                    q.mean);
        std::printf("inverted %lld\n", static_cast<long long>(q.inverted));
        for (std::size_t i = 0; i < q.histogram.counts.size(); ++i)  // bins (-inf, 0], (0, 0.1], ..., (0.9, 1]
            if (q.histogram.counts[i] > 0)
                std::printf("  quality in (%g, %g]: %lld cells\n", q.histogram.edges[i], q.histogram.edges[i + 1],
                            static_cast<long long>(q.histogram.counts[i]));
        return 0;
    } catch (const Error& e) {  // IoError, ParseError, FormatError, MeshError: all say what was wrong
        std::cerr << "error: " << e.what() << "\n";
        return 1;
    }
}
