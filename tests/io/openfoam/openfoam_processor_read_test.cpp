// One processor of a decomposed OpenFOAM case read alone
// (read_openfoam_processor: what each process of an mpirun reads), checked
// against the reconstructed case read whole: decomposePar's 2, 3 and 4
// processors of `mixed` and 2 of the binary cavity (tests/data/openfoam).
#include <gtest/gtest.h>

#include <map>
#include <set>

#include "dgwarp/core/error.hpp"
#include "dgwarp/io/openfoam/openfoam.hpp"
#include "dgwarp/mesh/mesh.hpp"
#include "io/openfoam/openfoam_test_support.hpp"

using namespace dgwarp;
using namespace dgwarp::test;

namespace {

struct ProcessorReadCase {
    std::string decomposed, whole;
    std::size_t processors;
};

}  // namespace

TEST(OpenFoamProcessorRead, EachProcessorIsItsPartOfTheWholeCase) {
    for (const ProcessorReadCase& c : {ProcessorReadCase{"mixed-decomposed", "mixed", 2},
                                       ProcessorReadCase{"mixed-decomposed-3", "mixed", 3},
                                       ProcessorReadCase{"mixed-decomposed-4", "mixed", 4},
                                       ProcessorReadCase{"cavity-binary-decomposed", "cavity-binary", 2},
                                       ProcessorReadCase{"snappy-sphere-decomposed", "snappy-sphere", 2}}) {
        SCOPED_TRACE(c.decomposed);
        const Mesh whole = read_openfoam(openfoam_case(c.whole));
        const auto folders = openfoam_processor_meshes(openfoam_case(c.decomposed));
        ASSERT_EQ(folders.size(), c.processors);
        std::vector<OpenFoamProcessorMesh> parts;
        for (const auto& folder : folders) parts.push_back(read_openfoam_processor(folder));

        // How many processors hold each point of the case, and which hold each cell.
        std::map<std::int64_t, int> holders;
        std::vector<int> cell_seen(whole.cells.size(), 0);
        for (const auto& part : parts) {
            for (std::int64_t id : part.point_ids) ++holders[id];
            for (std::int64_t id : part.cell_ids) ++cell_seen[static_cast<std::size_t>(id)];
        }
        EXPECT_EQ(holders.size(), whole.num_points());
        for (int seen : cell_seen) EXPECT_EQ(seen, 1);  // every cell of the case on exactly one processor

        std::vector<std::size_t> marker_faces(whole.markers.size(), 0);
        for (std::size_t p = 0; p < parts.size(); ++p) {
            const OpenFoamProcessorMesh& part = parts[p];
            const Mesh& m = part.mesh;
            EXPECT_EQ(part.points_format, c.whole == "cavity-binary" ? foam::Format::binary : foam::Format::ascii);
            // Points: the case's, bit for bit.
            ASSERT_EQ(part.point_ids.size(), m.num_points());
            for (std::size_t i = 0; i < m.num_points(); ++i)
                for (std::size_t d = 0; d < 3; ++d)
                    EXPECT_EQ(m.points[3 * i + d], whole.points[3 * static_cast<std::size_t>(part.point_ids[i]) + d]);
            // Cells: the case's, with their nodes in the same order.
            ASSERT_EQ(part.cell_ids.size(), m.cells.size());
            for (std::size_t k = 0; k < m.cells.size(); ++k) {
                const auto g = static_cast<std::size_t>(part.cell_ids[k]);
                EXPECT_EQ(m.cells.types[k], whole.cells.types[g]);
                const auto mine = m.cells.nodes_of(k);
                const auto theirs = whole.cells.nodes_of(g);
                ASSERT_EQ(mine.size(), theirs.size());
                for (std::size_t i = 0; i < mine.size(); ++i)
                    EXPECT_EQ(part.point_ids[static_cast<std::size_t>(mine[i])], theirs[i]) << "cell " << g;
                // A polyhedron's faces too, in the same order from the same node.
                const auto [f0, f1] = m.cells.faces_of(k);
                const auto [g0, g1] = whole.cells.faces_of(g);
                ASSERT_EQ(f1 - f0, g1 - g0) << "cell " << g;
                for (std::int64_t f = 0; f < f1 - f0; ++f) {
                    std::vector<NodeId> ring;
                    for (NodeId n : m.cells.face_nodes_of(f0 + f)) ring.push_back(static_cast<NodeId>(part.point_ids[static_cast<std::size_t>(n)]));
                    const auto expected = whole.cells.face_nodes_of(g0 + f);
                    EXPECT_EQ(ring, std::vector<NodeId>(expected.begin(), expected.end())) << "cell " << g;
                }
            }
            // Interface points: exactly those another processor holds too.
            std::vector<NodeId> shared;
            for (std::size_t i = 0; i < m.num_points(); ++i)
                if (holders[part.point_ids[i]] > 1) shared.push_back(static_cast<NodeId>(i));
            EXPECT_EQ(part.interface_nodes, shared) << "processor " << p;
            // Markers: the case's patches, each face on one processor, its nodes the case's.
            ASSERT_EQ(m.markers.size(), whole.markers.size());
            ASSERT_EQ(part.patches.size(), whole.markers.size());
            for (std::size_t k = 0; k < m.markers.size(); ++k) {
                EXPECT_EQ(m.markers[k].name, whole.markers[k].name);
                marker_faces[k] += m.markers[k].elements.size();
                const std::vector<NodeId> all = marker_nodes(whole.markers[k]);
                const std::set<NodeId> case_nodes(all.begin(), all.end());
                for (NodeId n : marker_nodes(m.markers[k]))
                    EXPECT_TRUE(case_nodes.count(static_cast<NodeId>(part.point_ids[static_cast<std::size_t>(n)])));
            }
        }
        for (std::size_t k = 0; k < whole.markers.size(); ++k)
            EXPECT_EQ(marker_faces[k], whole.markers[k].elements.size()) << whole.markers[k].name;
    }
}

TEST(OpenFoamProcessorRead, AMissingAddressingFileIsNamed) {
    const auto dir = scratch_dir();
    const auto from = openfoam_processor_meshes(openfoam_case("mixed-decomposed"))[1];
    const auto to = dir / "processor1" / "constant" / "polyMesh";
    copy_poly_mesh(from, to, {"cellProcAddressing"});
    try {
        read_openfoam_processor(to);
        FAIL() << "read without cellProcAddressing";
    } catch (const IoError& e) {
        EXPECT_NE(std::string(e.what()).find("cellProcAddressing"), std::string::npos) << e.what();
    }
}
