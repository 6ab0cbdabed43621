#include "dgwarp/run/original_cells.hpp"

#include <string>
#include <utility>

#include "dgwarp/core/error.hpp"
#include "dgwarp/core/parallel_for.hpp"
#include "dgwarp/core/stopwatch.hpp"

namespace dgwarp {

namespace {
double lowest_valid(const std::vector<double>& quality) {
    double lowest = 0;
    bool any = false;
    for (double q : quality)
        if (q > 0 && (!any || q < lowest)) lowest = q, any = true;
    return lowest;
}
}  // namespace

OriginalCells measure_original(const Mesh& mesh) {
    OriginalCells o;
    o.layout = std::make_shared<const QualityLayout>(make_quality_layout(mesh));
    o.quality = original_qualities(*o.layout, mesh, o.own_orientation, o.orientation);
    o.summary = summarize_quality(o.quality);
    o.valid_min = lowest_valid(o.quality);
    return o;
}

OriginalCells measure_original_beside(const Mesh& mesh, const std::function<void()>& work, double* seconds) {
    OriginalCells o;
    run_beside(work, [&] {
        Stopwatch sw;
        o = measure_original(mesh);
        if (seconds) *seconds = sw.lap();
    });
    return o;
}

OriginalCells measure_original(const Mesh& mesh, std::vector<std::int8_t> own_orientation,
                               std::vector<std::int8_t> orientation) {
    for (const auto* given : {&own_orientation, &orientation})
        if (given->size() != mesh.cells.size())
            throw MeshError(std::to_string(given->size()) + " cell orientations for a mesh of " +
                            std::to_string(mesh.cells.size()) + " cells");
    OriginalCells o;
    o.layout = std::make_shared<const QualityLayout>(make_quality_layout(mesh));
    o.own_orientation = std::move(own_orientation);
    o.orientation = std::move(orientation);
    o.quality = cell_qualities(*o.layout, mesh, mesh.points, o.orientation);
    o.summary = summarize_quality(o.quality);
    o.valid_min = lowest_valid(o.quality);
    return o;
}

}  // namespace dgwarp
