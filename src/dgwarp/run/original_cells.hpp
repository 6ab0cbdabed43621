#pragma once
// What every frame of a run is judged against: the original mesh's cells,
// measured once. A cell flipped in the input counts as inverted before and
// after (reported as already inverted, never as the motion's doing).
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include "dgwarp/mesh/mesh.hpp"
#include "dgwarp/quality/mesh_quality.hpp"
#include "dgwarp/quality/quality_layout.hpp"

namespace dgwarp {

struct OriginalCells {
    /// Per cell, the orientation cells are judged by: the majority of the
    /// original's per cell type (dominant_orientations, as `dgwarp info`
    /// judges a mesh).
    std::vector<std::int8_t> orientation;
    std::vector<std::int8_t> own_orientation;  // per cell, its own in the original (untangle keeps it)
    std::vector<double> quality;               // per cell, judged by `orientation`
    QualitySummary summary;                    // of `quality`
    double valid_min = 0;  // the lowest quality of the cells valid in the original (quality > 0); 0 when none is
    /// The cells laid out for the quality pass (quality_layout.hpp), built
    /// here once: measure_frame measures every frame over it.
    std::shared_ptr<const QualityLayout> layout;
};

/// The original cells of `mesh`, judged by the majority orientation of each cell type. Threaded.
OriginalCells measure_original(const Mesh& mesh);

/// work() on this thread with every thread for its loops, and
/// measure_original(mesh) beside it on a thread of its own (run_beside,
/// core/parallel_for.hpp): for a prepare, mostly serial, whose idle core the
/// measure fills. `seconds`, when given, receives the measure's own time
/// (which overlaps work's). work() must not change `mesh`.
OriginalCells measure_original_beside(const Mesh& mesh, const std::function<void()>& work, double* seconds = nullptr);

/// The same from the cells' own orientations (cell_orientations(mesh)),
/// judged by `orientation` (e.g. the majority over every process's part of a
/// decomposed mesh). Throws MeshError when a size is not the number of cells.
OriginalCells measure_original(const Mesh& mesh, std::vector<std::int8_t> own_orientation,
                               std::vector<std::int8_t> orientation);

}  // namespace dgwarp
