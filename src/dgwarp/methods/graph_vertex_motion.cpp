#include "dgwarp/methods/graph_vertex_motion.hpp"

#include <algorithm>

namespace dgwarp {

namespace {
bool is_zero(const Vec3& v) { return v[0] == 0 && v[1] == 0 && v[2] == 0; }
}  // namespace

GraphVertexMotion graph_vertex_motion(const DelaunayGraph& graph, std::span<const std::uint8_t> moving) {
    GraphVertexMotion out;
    out.vertex_motion.resize(graph.num_vertices());
    for (std::size_t v = 0; v < graph.num_vertices(); ++v) {
        const auto first = graph.vertex_nodes.begin() + graph.vertex_offsets[v];
        const auto last = graph.vertex_nodes.begin() + graph.vertex_offsets[v + 1];
        const auto mover = std::find_if(first, last, [&](std::int32_t b) { return moving[b] != 0; });
        out.vertex_motion[v] = mover != last ? *mover : -1 - *first;
        if (last - first > 1) {
            out.shared_members.insert(out.shared_members.end(), first, last);
            out.shared_offsets.push_back(static_cast<std::int32_t>(out.shared_members.size()));
        }
    }
    return out;
}

std::int64_t count_conflicting_shared_vertices(std::span<const std::int32_t> shared_offsets,
                                               std::span<const std::int32_t> shared_members,
                                               std::span<const std::uint8_t> moving, const BoundaryMotion& motion) {
    std::int64_t conflicts = 0;
    for (std::size_t g = 0; g + 1 < shared_offsets.size(); ++g) {
        const auto first = shared_members.begin() + shared_offsets[g];
        const auto last = shared_members.begin() + shared_offsets[g + 1];
        const auto mover = std::find_if(first, last, [&](std::int32_t b) { return moving[b] != 0; });
        if (mover == last) continue;
        const NodeMotion& used = motion[*mover];
        const bool moves = !is_zero(used.translation) || !is_zero(used.rotation);
        const bool conflict = std::any_of(first, last, [&](std::int32_t b) {
            return moving[b] ? !(motion[b] == used) : moves;
        });
        conflicts += conflict;
    }
    return conflicts;
}

}  // namespace dgwarp
