#pragma once
// Printing reports for the CLI, as text for people and JSON for scripts.
#include <nlohmann/json.hpp>
#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

#include "dgwarp/io/mesh_io.hpp"
#include "dgwarp/mesh/mesh.hpp"
#include "dgwarp/mesh/mesh_counts.hpp"
#include "dgwarp/quality/mesh_quality.hpp"
#include "dgwarp/run/report_json.hpp"

namespace dgwarp::cli {

/// "2D, 5233 nodes, 10216 cells (10216 triangle)".
std::string describe_mesh(const Mesh& mesh);
std::string describe_mesh(const MeshCounts& counts);

/// {"dim", "nodes", "cells", "cell_types": {"triangle": n, ...}, "markers": [{"name", "elements", "nodes"}]}
nlohmann::json mesh_json(const Mesh& mesh);
nlohmann::json mesh_json(const MeshCounts& counts);

/// Indented text lines: min (and its cell), mean, inverted; the histogram when asked.
void print_quality(std::ostream& out, const QualitySummary& q, bool histogram);
void print_ratio(std::ostream& out, const RatioSummary& r);

/// A duration for people: "12.3 ms" (two decimals below 10 ms).
std::string milliseconds(double seconds);

/// For a multi-zone SU2 file read as one zone: "FILE holds 3 zones; zone 1
/// is read (--zone N reads another)"; "" for a single-zone file or another format.
std::string zone_notice(const MeshExtras& extras, const std::string& file, int zone);

/// Flushes standard output; throws IoError("standard output", the system's
/// reason) when anything printed was lost (a full disk, /dev/full): a report
/// a script reads must not vanish with exit code 0.
void check_standard_output();

}  // namespace dgwarp::cli
