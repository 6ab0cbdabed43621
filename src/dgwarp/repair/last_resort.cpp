#include "dgwarp/repair/last_resort.hpp"

#include "dgwarp/repair/unrepairable_cells.hpp"

namespace dgwarp {

UntangleOptions last_resort_untangle_options(std::span<const std::int64_t> step_folded) {
    UntangleOptions o;
    o.max_rounds = last_resort_max_rounds;
    o.cells = step_folded;
    return o;
}

std::optional<UntangleReport> run_last_resort(int dim, const ElementList& cells,
                                              std::span<const std::int8_t> orientations,
                                              std::span<const NodeId> fixed_nodes,
                                              std::span<const std::int64_t> step_folded, std::span<double> points) {
    if (step_folded.empty() || !cells_with_only_fixed_nodes(cells, fixed_nodes, step_folded).empty()) return {};
    return untangle(dim, cells, orientations, fixed_nodes, points, last_resort_untangle_options(step_folded));
}

}  // namespace dgwarp
