#include "report.hpp"

#include <cstdio>
#include <iomanip>
#include <sstream>

namespace dgwarp::cli {

std::string describe_mesh(const Mesh& mesh) {
    std::ostringstream s;
    s << mesh.dim << "D, " << mesh.num_points() << " nodes, " << mesh.cells.size() << " cells (";
    const auto counts = count_by_type(mesh.cells);
    bool first = true;
    for (CellType t : all_cell_types) {
        if (counts[static_cast<int>(t)] == 0) continue;
        s << (first ? "" : ", ") << counts[static_cast<int>(t)] << " " << cell_type_name(t);
        first = false;
    }
    s << "), " << mesh.markers.size() << " markers";
    return s.str();
}

nlohmann::json mesh_json(const Mesh& mesh) {
    nlohmann::json types = nlohmann::json::object();
    const auto counts = count_by_type(mesh.cells);
    for (CellType t : all_cell_types)
        if (counts[static_cast<int>(t)] > 0) types[std::string(cell_type_name(t))] = counts[static_cast<int>(t)];
    nlohmann::json markers = nlohmann::json::array();
    for (const Marker& m : mesh.markers)
        markers.push_back({{"name", m.name}, {"elements", m.elements.size()}, {"nodes", marker_nodes(m).size()}});
    return {{"dim", mesh.dim},
            {"nodes", mesh.num_points()},
            {"cells", mesh.cells.size()},
            {"cell_types", types},
            {"markers", markers}};
}

nlohmann::json quality_json(const QualitySummary& q) {
    return {{"cells", q.cells},
            {"min", q.min},
            {"mean", q.mean},
            {"inverted", q.inverted},
            {"worst_cell", q.worst_cell},
            {"histogram", {{"edges", q.histogram.edges}, {"counts", q.histogram.counts}}}};
}

nlohmann::json ratio_json(const RatioSummary& r) {
    return {{"min", r.min}, {"mean", r.mean}, {"worst_cell", r.worst_cell}};
}

void print_quality(std::ostream& out, const QualitySummary& q, bool histogram) {
    out << std::fixed << std::setprecision(6);
    out << "  min quality   " << q.min << "  (cell " << q.worst_cell << ")\n";
    out << "  mean quality  " << q.mean << "\n";
    out << "  inverted      " << q.inverted << " of " << q.cells << " cells\n";
    if (histogram) {
        out << "  histogram\n";
        for (std::size_t b = 0; b < q.histogram.counts.size(); ++b) {
            char range[64];
            if (b == 0)
                std::snprintf(range, sizeof range, "       <= %.1f", q.histogram.edges[1]);
            else
                std::snprintf(range, sizeof range, "  (%.1f, %.1f]", q.histogram.edges[b], q.histogram.edges[b + 1]);
            out << "  " << range << "  " << q.histogram.counts[b] << "\n";
        }
    }
    out.unsetf(std::ios::floatfield);
}

void print_ratio(std::ostream& out, const RatioSummary& r) {
    out << std::fixed << std::setprecision(6);
    out << "  min ratio     " << r.min << "  (cell " << r.worst_cell << ")\n";
    out << "  mean ratio    " << r.mean << "\n";
    out.unsetf(std::ios::floatfield);
}

std::string milliseconds(double seconds) {
    std::ostringstream s;
    s << std::fixed << std::setprecision(seconds < 0.01 ? 2 : 1) << seconds * 1e3 << " ms";
    return s.str();
}

}  // namespace dgwarp::cli
