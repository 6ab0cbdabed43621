#include "report.hpp"

#include <cmath>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <iomanip>
#include <sstream>

#include "dgwarp/core/error.hpp"

namespace dgwarp::cli {

std::string describe_mesh(const Mesh& mesh) { return describe_mesh(mesh_counts(mesh)); }

std::string describe_mesh(const MeshCounts& c) {
    std::ostringstream s;
    s << c.dim << "D, " << c.nodes << " nodes, " << c.cells << " cells (";
    bool first = true;
    for (CellType t : all_cell_types) {
        if (c.cell_types[static_cast<std::size_t>(t)] == 0) continue;
        s << (first ? "" : ", ") << c.cell_types[static_cast<std::size_t>(t)] << " " << cell_type_name(t);
        first = false;
    }
    s << "), " << c.markers.size() << " markers";
    return s.str();
}

nlohmann::json mesh_json(const Mesh& mesh) { return mesh_json(mesh_counts(mesh)); }

nlohmann::json mesh_json(const MeshCounts& c) {
    nlohmann::json types = nlohmann::json::object();
    for (CellType t : all_cell_types)
        if (c.cell_types[static_cast<std::size_t>(t)] > 0)
            types[std::string(cell_type_name(t))] = c.cell_types[static_cast<std::size_t>(t)];
    nlohmann::json markers = nlohmann::json::array();
    for (const auto& m : c.markers) markers.push_back({{"name", m.name}, {"elements", m.elements}, {"nodes", m.nodes}});
    return {{"dim", c.dim}, {"nodes", c.nodes}, {"cells", c.cells}, {"cell_types", types}, {"markers", markers}};
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

std::string zone_notice(const MeshExtras& extras, const std::string& file, int zone) {
    if (!extras.su2 || extras.su2->zones <= 1) return "";
    return file + " holds " + std::to_string(extras.su2->zones) + " zones; zone " + std::to_string(zone) +
           " is read (--zone N reads another)";
}

void check_standard_output() {
    errno = 0;
    std::cout.flush();
    const bool lost = !std::cout || std::fflush(stdout) != 0 || std::ferror(stdout);
    const int err = errno;
    if (lost)
        throw IoError("standard output",
                      std::string("the report could not be written: ") + (err != 0 ? std::strerror(err) : "write error"),
                      err);
}

}  // namespace dgwarp::cli
