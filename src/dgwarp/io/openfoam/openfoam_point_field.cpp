// The pointDisplacement field of OpenFOAM's displacement motion solvers, from
// a displacement per node (docs/OPENFOAM.md, "Boundary motion for OpenFOAM").
#include <algorithm>
#include <sstream>
#include <string_view>

#include "dgwarp/core/error.hpp"
#include "dgwarp/io/number_text.hpp"
#include "dgwarp/io/openfoam/openfoam.hpp"

namespace dgwarp {

namespace {

// OpenFOAM's constraint patch types: their point fields take the patch's type.
constexpr std::string_view constraint_types[] = {
    "empty",      "wedge",     "symmetryPlane", "symmetry", "cyclic", "cyclicAMI", "cyclicACMI", "cyclicSlip",
    "nonuniformTransformCyclic", "processor", "processorCyclic"};

bool is_constraint_type(std::string_view type) {
    return std::find(std::begin(constraint_types), std::end(constraint_types), type) != std::end(constraint_types);
}

void write_vector(std::ostream& out, std::span<const double> displacement, NodeId node) {
    out.put('(');
    for (std::size_t d = 0; d < 3; ++d) {
        if (d) out.put(' ');
        write_number(out, displacement[3 * static_cast<std::size_t>(node) + d]);
    }
    out.put(')');
}

bool same_vector(std::span<const double> v, NodeId a, NodeId b) {
    const auto i = 3 * static_cast<std::size_t>(a), j = 3 * static_cast<std::size_t>(b);
    return v[i] == v[j] && v[i + 1] == v[j + 1] && v[i + 2] == v[j + 2];
}

}  // namespace

std::vector<NodeId> openfoam_patch_points(const Marker& marker) {
    std::vector<NodeId> order;
    NodeId largest = -1;
    for (NodeId n : marker.elements.nodes) largest = std::max(largest, n);
    std::vector<char> seen(static_cast<std::size_t>(largest + 1), 0);
    for (NodeId n : marker.elements.nodes)
        if (!seen[static_cast<std::size_t>(n)]) {
            seen[static_cast<std::size_t>(n)] = 1;
            order.push_back(n);
        }
    return order;
}

std::string openfoam_point_displacement_text(const Mesh& mesh, std::span<const double> displacement,
                                             const std::vector<OpenFoamPatch>& patches, const std::string& location) {
    if (mesh.dim != 3) throw MeshError("pointDisplacement: OpenFOAM meshes are 3D, this mesh is 2D");
    if (displacement.size() != 3 * mesh.num_points())
        throw MeshError("pointDisplacement: " + std::to_string(displacement.size()) + " displacement values for " +
                        std::to_string(mesh.num_points()) + " points (3 per point expected)");
    if (!patches.empty() && patches.size() != mesh.markers.size())
        throw MeshError("pointDisplacement: " + std::to_string(patches.size()) + " patch dictionaries for " +
                        std::to_string(mesh.markers.size()) + " markers");
    std::ostringstream out;
    foam::write_header(out, foam::Format::ascii, "pointVectorField", location, "pointDisplacement");
    out << "dimensions      [0 1 0 0 0 0 0];\n\ninternalField   uniform (0 0 0);\n\nboundaryField\n{\n";
    for (std::size_t m = 0; m < mesh.markers.size(); ++m) {
        const Marker& marker = mesh.markers[m];
        const std::string type = patches.empty() ? std::string("patch") : patches[m].type;
        out << "    " << marker.name << "\n    {\n";
        if (is_constraint_type(type)) {
            out << "        type            " << type << ";\n    }\n";
            continue;
        }
        out << "        type            fixedValue;\n        value           ";
        const std::vector<NodeId> points = openfoam_patch_points(marker);
        const bool uniform = std::all_of(points.begin(), points.end(),
                                         [&](NodeId n) { return same_vector(displacement, n, points.front()); });
        if (points.empty()) {
            out << "uniform (0 0 0)";
        } else if (uniform) {
            out << "uniform ";
            write_vector(out, displacement, points.front());
        } else {
            out << "nonuniform List<vector>\n" << points.size() << "\n(\n";
            for (NodeId n : points) {
                write_vector(out, displacement, n);
                out.put('\n');
            }
            out << ")\n";
        }
        out << ";\n    }\n";
    }
    out << "}\n";
    foam::write_footer(out);
    return std::move(out).str();
}

}  // namespace dgwarp
