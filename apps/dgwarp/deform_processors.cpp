// deform_processors.hpp: each process reads, deforms, measures and writes its
// own processor folder of a decomposed OpenFOAM case; rank 0 reports.
#include "deform_processors.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <limits>
#include <nlohmann/json.hpp>
#include <tuple>
#include <unordered_map>
#include <variant>

#include "commands.hpp"
#include "dgwarp/core/error.hpp"
#include "dgwarp/core/stopwatch.hpp"
#include "dgwarp/io/atomic_write.hpp"
#include "dgwarp/io/motion_file.hpp"
#include "dgwarp/io/openfoam.hpp"
#include "dgwarp/repair/unrepairable_cells.hpp"
#include "flag_values.hpp"
#include "foam_output.hpp"
#include "frame_output.hpp"
#include "output_files.hpp"
#include "report.hpp"

namespace dgwarp::cli {

namespace fs = std::filesystem;

namespace {

// The arguments every process needs, sent by rank 0 (mpi_run_everywhere).
nlohmann::json processor_args_json(const DeformArgs& a, const std::string& given_output) {
    const SetupArgs& s = a.setup;
    return {{"mesh", s.mesh},
            {"motion", s.motion},
            {"method", s.method},
            {"method_given", s.method_given},
            {"given", std::vector<std::string>(s.given.begin(), s.given.end())},
            {"zone", s.zone},
            {"threads", s.threads},
            {"a_translation", s.a_translation},
            {"a_rotation", s.a_rotation},
            {"length_scale", s.length_scale},
            {"weights", s.weights},
            {"dgm_substep", s.dgm_substep},
            {"idw_exponent_moving", s.idw_exponent_moving},
            {"idw_exponent_static", s.idw_exponent_static},
            {"rbf_radius", s.rbf_radius},
            {"rbf_greedy", s.rbf_greedy},
            {"harmonic_wall_spacing", s.harmonic_wall_spacing},
            {"harmonic_growth", s.harmonic_growth},
            {"output", a.output},
            {"given_output", given_output},
            {"json", a.json},
            {"allow_invalid", a.allow_invalid},
            {"no_untangle", a.no_untangle},
            {"foam_time", a.foam_time},
            {"quiet", a.quiet}};
}

DeformArgs processor_args_from_json(const nlohmann::json& j, std::string& given_output) {
    DeformArgs a;
    SetupArgs& s = a.setup;
    s.mesh = j.at("mesh");
    s.motion = j.at("motion");
    s.method = j.at("method");
    s.method_given = j.at("method_given");
    for (const auto& g : j.at("given")) s.given.insert(g.get<std::string>());
    s.zone = j.at("zone");
    s.threads = j.at("threads");
    s.a_translation = j.at("a_translation");
    s.a_rotation = j.at("a_rotation");
    s.length_scale = j.at("length_scale");
    s.weights = j.at("weights");
    s.dgm_substep = j.at("dgm_substep");
    s.idw_exponent_moving = j.at("idw_exponent_moving");
    s.idw_exponent_static = j.at("idw_exponent_static");
    s.rbf_radius = j.at("rbf_radius");
    s.rbf_greedy = j.at("rbf_greedy");
    s.harmonic_wall_spacing = j.at("harmonic_wall_spacing");
    s.harmonic_growth = j.at("harmonic_growth");
    a.output = j.at("output");
    given_output = j.at("given_output");
    a.json = j.at("json");
    a.allow_invalid = j.at("allow_invalid");
    a.no_untangle = j.at("no_untangle");
    a.foam_time = j.at("foam_time");
    a.quiet = j.at("quiet");
    return a;
}

/// Runs `phase` on this process, then agrees with the others (mpi_agree):
/// every process goes on, or every process throws the first failure.
template <class F>
void collectively(F&& phase) {
    std::exception_ptr error;
    try {
        phase();
    } catch (...) {
        error = std::current_exception();
    }
    mpi_agree(error);
}

/// What this process holds of the case, beyond its part of the mesh.
struct ProcessorPart {
    fs::path poly_mesh;                   // CASE/processor<r>/constant/polyMesh
    std::vector<std::int64_t> point_ids;  // pointProcAddressing
    std::vector<std::int64_t> cell_ids;   // cellProcAddressing
    foam::Format points_format = foam::Format::ascii;
    std::vector<std::uint8_t> owned;      // per point: this process is the lowest rank holding it
    std::vector<std::int64_t> marker_elements;  // per marker: its faces here (before shared nodes were added)
};

/// Every process's interface points (on processor patches) are held by
/// several processes, possibly on different markers: a point on the edge of a
/// patch whose faces are all on one side. Gives each process every marker
/// any process has each of its points on (as vertex elements added to the
/// marker, which resolve_boundary reads as the marker's nodes), so that every
/// process classifies and moves a shared point as the whole case does; and
/// marks the points this process owns (the lowest rank holding them).
void share_interface_markers(Mesh& mesh, const std::vector<NodeId>& interface, ProcessorPart& part) {
    const int rank = mpi_rank();
    std::vector<std::uint8_t> on_interface(mesh.num_points(), 0);
    for (NodeId n : interface) on_interface[static_cast<std::size_t>(n)] = 1;
    std::unordered_map<std::int64_t, NodeId> local_of;
    local_of.reserve(interface.size());
    std::vector<std::int64_t> ids;
    for (NodeId n : interface) {
        local_of.emplace(part.point_ids[static_cast<std::size_t>(n)], n);
        ids.push_back(part.point_ids[static_cast<std::size_t>(n)]);
    }
    // Owners: the lowest rank holding each interface point.
    std::vector<int> counts;
    const std::vector<std::int64_t> all_ids = mpi_all_gather(ids, &counts);
    part.owned.assign(mesh.num_points(), 1);
    std::size_t at = 0;
    for (int r = 0; r < static_cast<int>(counts.size()); ++r)
        for (int k = 0; k < counts[static_cast<std::size_t>(r)]; ++k, ++at)
            if (r < rank)
                if (const auto it = local_of.find(all_ids[at]); it != local_of.end())
                    part.owned[static_cast<std::size_t>(it->second)] = 0;
    // (point id, marker) of every interface point on a marker, from every process.
    std::vector<std::vector<NodeId>> nodes_of(mesh.markers.size());
    std::vector<std::int64_t> pairs;
    for (std::size_t m = 0; m < mesh.markers.size(); ++m) {
        nodes_of[m] = marker_nodes(mesh.markers[m]);
        for (NodeId n : nodes_of[m])
            if (on_interface[static_cast<std::size_t>(n)])
                pairs.insert(pairs.end(), {part.point_ids[static_cast<std::size_t>(n)], static_cast<std::int64_t>(m)});
    }
    const std::vector<std::int64_t> all_pairs = mpi_all_gather(pairs);
    std::vector<std::vector<NodeId>> extra(mesh.markers.size());
    for (std::size_t k = 0; k + 1 < all_pairs.size(); k += 2) {
        const auto it = local_of.find(all_pairs[k]);
        const auto m = static_cast<std::size_t>(all_pairs[k + 1]);
        if (it == local_of.end() || m >= mesh.markers.size()) continue;
        if (!std::binary_search(nodes_of[m].begin(), nodes_of[m].end(), it->second)) extra[m].push_back(it->second);
    }
    for (std::size_t m = 0; m < mesh.markers.size(); ++m) {
        std::sort(extra[m].begin(), extra[m].end());
        extra[m].erase(std::unique(extra[m].begin(), extra[m].end()), extra[m].end());
        for (NodeId n : extra[m]) mesh.markers[m].elements.push_back(CellType::vertex, {&n, 1});
    }
}

/// "a, b", or "none".
std::string processor_name_list(const std::vector<std::string>& names) {
    std::string s;
    for (const auto& n : names) s += (s.empty() ? "" : ", ") + n;
    return s.empty() ? "none" : s;
}

/// The whole case's counts, from every process's part.
MeshCounts case_counts(const Mesh& mesh, const ProcessorPart& part) {
    MeshCounts c = mesh_counts(mesh);
    std::int64_t largest = -1;
    for (std::int64_t id : part.point_ids) largest = std::max(largest, id);
    c.nodes = mpi_max(largest) + 1;
    c.cells = mpi_sum(c.cells);
    c.cell_types = mpi_sum(c.cell_types);
    std::vector<std::int64_t> elements(part.marker_elements), nodes;
    for (const Marker& m : mesh.markers) {
        std::int64_t owned = 0;
        for (NodeId n : marker_nodes(m)) owned += part.owned[static_cast<std::size_t>(n)];
        nodes.push_back(owned);
    }
    elements = mpi_sum(elements);
    nodes = mpi_sum(nodes);
    for (std::size_t m = 0; m < c.markers.size(); ++m) c.markers[m] = {mesh.markers[m].name, elements[m], nodes[m]};
    return c;
}

/// A compensated (Kahan) sum, as summarize_quality's mean.
double compensated_sum(std::span<const double> values) {
    double sum = 0, carry = 0;
    for (double v : values) {
        const double y = v - carry;
        const double t = sum + y;
        carry = (t - sum) - y;
        sum = t;
    }
    return sum;
}

/// The smallest of `values` over every process and the lowest case id of a
/// cell holding it (worst_cell: the first in the case's order).
std::pair<double, std::int64_t> case_minimum(std::span<const double> values, const std::vector<std::int64_t>& cell_ids) {
    double local = std::numeric_limits<double>::infinity();
    for (double v : values) local = std::min(local, v);
    const double min = mpi_min(local);
    std::int64_t first = std::numeric_limits<std::int64_t>::max();
    for (std::size_t i = 0; i < values.size(); ++i)
        if (values[i] == min) first = std::min(first, cell_ids[i]);
    first = mpi_min(first);
    return {min, first == std::numeric_limits<std::int64_t>::max() ? -1 : first};
}

/// summarize_quality over every process's cells (the mean's last bits may
/// differ from one process's: the sums are added in another order).
QualitySummary case_quality(std::span<const double> q, const std::vector<std::int64_t>& cell_ids) {
    QualitySummary s = summarize_quality(q);
    s.cells = mpi_sum(s.cells);
    s.inverted = mpi_sum(s.inverted);
    s.histogram.counts = mpi_sum(s.histogram.counts);
    const auto [min, worst] = case_minimum(q, cell_ids);
    s.min = s.cells > 0 ? min : 0;
    s.worst_cell = worst;
    s.mean = s.cells > 0 ? mpi_sum(std::vector<double>{compensated_sum(q)})[0] / static_cast<double>(s.cells) : 0;
    return s;
}

RatioSummary case_ratios(std::span<const double> r, const std::vector<std::int64_t>& cell_ids) {
    RatioSummary s;
    const std::int64_t cells = mpi_sum(static_cast<std::int64_t>(r.size()));
    const auto [min, worst] = case_minimum(r, cell_ids);
    s.min = cells > 0 ? min : 0;
    s.worst_cell = worst;
    s.mean = cells > 0 ? mpi_sum(std::vector<double>{compensated_sum(r)})[0] / static_cast<double>(cells) : 0;
    return s;
}

/// worst_cells over every process: up to `count` of the cells `cells` (local
/// indices) of every process, smallest quality first, then the lowest case
/// id, as case ids; and their number over every process.
std::pair<std::vector<std::int64_t>, std::int64_t> case_worst(const std::vector<std::int64_t>& cells,
                                                               const std::vector<double>& quality,
                                                               const std::vector<std::int64_t>& cell_ids,
                                                               std::size_t count) {
    std::vector<std::pair<double, std::int64_t>> mine;
    for (std::int64_t c : cells) mine.emplace_back(quality[static_cast<std::size_t>(c)], cell_ids[static_cast<std::size_t>(c)]);
    std::sort(mine.begin(), mine.end());
    if (mine.size() > count) mine.resize(count);
    std::vector<std::int64_t> flat;
    for (const auto& [q, id] : mine) flat.insert(flat.end(), {std::bit_cast<std::int64_t>(q), id});
    const std::vector<std::int64_t> all = mpi_all_gather(flat);
    std::vector<std::pair<double, std::int64_t>> every;
    for (std::size_t k = 0; k + 1 < all.size(); k += 2) every.emplace_back(std::bit_cast<double>(all[k]), all[k + 1]);
    std::sort(every.begin(), every.end());
    if (every.size() > count) every.resize(count);
    std::vector<std::int64_t> ids;
    for (const auto& e : every) ids.push_back(e.second);
    return {ids, mpi_sum(static_cast<std::int64_t>(cells.size()))};
}

/// Every process's warnings on rank 0: a text every process gives, once; one
/// that only some give, prefixed by "process r: " (its counts and node
/// numbers are that process's), except a marker "with no elements" on some
/// processes, which has faces on another, dropped. `shared_nodes`: the whole
/// case's count of boundary nodes on a moving and a static marker, which
/// replaces each process's in that warning.
std::vector<std::string> case_warnings(const std::vector<std::string>& mine, std::int64_t shared_nodes = -1) {
    std::string joined;
    for (const auto& w : mine) joined += w + '\x1f';
    const std::vector<std::string> all = mpi_gather_text(joined);
    const std::string shared_text = " on both a moving and a static marker; ";
    std::vector<std::vector<std::string>> by_rank(all.size());
    std::unordered_map<std::string, std::size_t> given_by;
    for (std::size_t r = 0; r < all.size(); ++r) {
        std::size_t start = 0;
        for (std::size_t end; (end = all[r].find('\x1f', start)) != std::string::npos; start = end + 1) {
            std::string w = all[r].substr(start, end - start);
            if (const auto at = w.find(shared_text); at != std::string::npos && shared_nodes >= 0)
                w = std::to_string(shared_nodes) + " boundary node" + (shared_nodes == 1 ? " is" : "s are") + w.substr(at);
            if (std::find(by_rank[r].begin(), by_rank[r].end(), w) != by_rank[r].end()) continue;
            by_rank[r].push_back(w);
            ++given_by[w];
        }
    }
    std::vector<std::string> out;
    std::unordered_map<std::string, bool> done;
    for (std::size_t r = 0; r < by_rank.size(); ++r)
        for (const std::string& w : by_rank[r]) {
            if (given_by[w] == all.size()) {
                if (!done[w]) out.push_back(w);
                done[w] = true;
            } else if (w.find("which has no elements") == std::string::npos) {
                out.push_back("process " + std::to_string(r) + ": " + w);
            }
        }
    return out;
}

/// The boundary nodes this process owns that are on a moving and on a static marker.
std::int64_t owned_moving_and_static(const Mesh& mesh, const ResolvedBoundary& b, const std::vector<std::uint8_t>& owned) {
    std::vector<std::uint8_t> on(mesh.num_points(), 0);  // bit 1: a moving marker, bit 2: a static one
    for (const Marker& m : mesh.markers) {
        const bool moving = std::find(b.moving_markers.begin(), b.moving_markers.end(), m.name) != b.moving_markers.end();
        for (NodeId n : marker_nodes(m)) on[static_cast<std::size_t>(n)] |= moving ? 1 : 2;
    }
    std::int64_t count = 0;
    for (std::size_t n = 0; n < on.size(); ++n) count += on[n] == 3 && owned[n];
    return count;
}

/// The points of frame `time` for this process's processor folder of
/// `out`: written to a temporary file beside the points file, renamed into
/// place only when every process wrote its own (so that an error on one
/// leaves no process's new points). Returns the points file.
fs::path write_processor_points(const fs::path& out, const std::string& time, const ProcessorPart& part,
                                const std::vector<double>& points, bool& base_written) {
    const fs::path folder = out / ("processor" + std::to_string(mpi_rank()));
    const OpenFoamPointsFile file = openfoam_points_file(folder, time);
    const fs::path tmp = file.file.string() + ".dgwarp-part";
    collectively([&] {
        try {
            if (!base_written) {
                const fs::path base = openfoam_output_poly_mesh(folder);
                std::error_code ec;
                if (!fs::equivalent(base, part.poly_mesh, ec)) {
                    const bool points_here = file.file.parent_path() == base;
                    copy_poly_mesh(part.poly_mesh, base,
                                   points_here ? std::vector<std::string>{"points", "points.gz"} : std::vector<std::string>{});
                }
                base_written = true;
            }
            write_openfoam_points(tmp, points, part.points_format, file.location);
        } catch (...) {
            std::error_code ec;
            fs::remove(tmp, ec);
            throw;
        }
    });
    // Every process has its new points beside the old: each renames its own
    // (an error in a rename leaves the other processes' files renamed).
    collectively([&] {
        std::error_code ec;
        fs::rename(tmp, file.file, ec);
        if (ec) {
            fs::remove(tmp, ec);
            throw IoError(file.file.string(), "cannot rename " + tmp.string() + " to it: " + ec.message());
        }
    });
    return file.file;
}

void deform_per_processor(const DeformArgs& a, const std::string& given_output) {
    const int rank = mpi_rank(), processes = mpi_processes();
    const bool text = rank == 0 && !a.json && !a.quiet;
    ProgressLine progress(text);
    WarningPrinter warnings(text);
    use_threads(a.setup.threads);
    const Method method = chosen_methods(a.setup, false).front();
    Inputs in;
    in.args = a.setup;
    ProcessorPart part;
    std::vector<NodeId> interface;
    std::vector<std::string> foam_times;
    Stopwatch sw;

    // Each process reads the motion and its own processor folder.
    collectively([&] {
        if (rank == 0) refuse_other_methods_options(a.setup, method);
        in.spec = read_motion_file(a.setup.motion);
        foam_times = foam_time_names(in.spec, frame_count(in.spec), a.foam_time);
        if (rank == 0) {
            std::vector<fs::path> inputs = motion_files(in.spec);
            inputs.insert(inputs.end(), {a.setup.mesh, a.setup.motion});
            for (const auto& file : mesh_input_files(a.setup.mesh)) inputs.push_back(file);
            check_foam_outputs(a.output, foam_times, a.setup.mesh, inputs);
        }
        const std::vector<fs::path> processors = openfoam_processor_meshes(a.setup.mesh);
        if (processors.size() != static_cast<std::size_t>(processes))
            throw FormatError(a.setup.mesh + ": " + std::to_string(processors.size()) + " processor folders for " +
                              std::to_string(processes) + " processes");
        progress.phase("reading " + processors[static_cast<std::size_t>(rank)].string());
        OpenFoamProcessorMesh read = read_openfoam_processor(processors[static_cast<std::size_t>(rank)]);
        part.poly_mesh = processors[static_cast<std::size_t>(rank)];
        part.point_ids = std::move(read.point_ids);
        part.cell_ids = std::move(read.cell_ids);
        part.points_format = read.points_format;
        interface = std::move(read.interface_nodes);
        in.mesh = std::move(read.mesh);
        for (const Marker& m : in.mesh.markers) part.marker_elements.push_back(static_cast<std::int64_t>(m.elements.size()));
    });
    in.read_seconds = sw.lap();

    // The same patches, in the same order, on every process.
    std::string names;
    for (const Marker& m : in.mesh.markers) names += m.name + "\n";
    const std::string names0 = mpi_broadcast_text(names);
    collectively([&] {
        if (names != names0)
            throw ParseError((part.poly_mesh / "boundary").string(), 0,
                             "the patches of processor 0, in the same order (decomposePar writes every patch to every "
                             "processor)",
                             "other patches");
    });

    // The boundary: each process's nodes on the markers every process has them on.
    progress.phase("classifying the boundary");
    share_interface_markers(in.mesh, interface, part);
    if (in.spec.shared_tolerance <= 0) {
        // The tolerance one process takes: 1e-9 × the whole case's bounding-box diagonal.
        double sum = 0;
        for (int d = 0; d < 3; ++d) {
            double lo = std::numeric_limits<double>::infinity(), hi = -lo;
            for (std::size_t p = static_cast<std::size_t>(d); p < in.mesh.points.size(); p += 3) {
                lo = std::min(lo, in.mesh.points[p]);
                hi = std::max(hi, in.mesh.points[p]);
            }
            lo = mpi_min(lo);
            hi = mpi_max(hi);
            sum += (hi - lo) * (hi - lo);
        }
        in.spec.shared_tolerance = 1e-9 * std::sqrt(sum);
    }
    collectively([&] { in.boundary = resolve_boundary(in.mesh, in.spec); });
    const MeshCounts counts = case_counts(in.mesh, part);
    std::int64_t boundary_nodes = 0, moving_nodes = 0;
    for (std::size_t b = 0; b < in.boundary.boundary.nodes.size(); ++b)
        if (part.owned[static_cast<std::size_t>(in.boundary.boundary.nodes[b])]) {
            ++boundary_nodes;
            moving_nodes += in.boundary.boundary.moving[b];
        }
    boundary_nodes = mpi_sum(boundary_nodes);
    moving_nodes = mpi_sum(moving_nodes);
    in.resolve_seconds = sw.lap();

    // The original quality, judged by the whole case's majority orientation per cell type.
    progress.phase("measuring the original mesh's quality");
    in.own_orientation = cell_orientations(in.mesh);
    std::vector<std::int64_t> balance(std::size(all_cell_types), 0);
    for (std::size_t c = 0; c < in.own_orientation.size(); ++c)
        balance[static_cast<std::size_t>(in.mesh.cells.types[c])] += in.own_orientation[c];
    balance = mpi_sum(balance);
    in.orientation.resize(in.own_orientation.size());
    for (std::size_t c = 0; c < in.orientation.size(); ++c)
        in.orientation[c] = balance[static_cast<std::size_t>(in.mesh.cells.types[c])] < 0 ? -1 : 1;
    in.original_cell_quality = cell_qualities(in.mesh, in.orientation);
    in.original_quality = case_quality(in.original_cell_quality, part.cell_ids);
    if (const std::int64_t bad = in.original_quality.inverted; bad > 0)
        in.boundary.warnings.push_back(
            std::to_string(bad) + (bad == 1 ? " cell is" : " cells are") +
            " already inverted or degenerate in the input mesh (quality <= 0, e.g. cell " +
            std::to_string(in.original_quality.worst_cell) +
            "): they are counted as inverted before and after, but not blamed on the motion, and do not make a "
            "step invalid");
    in.boundary.warnings =
        case_warnings(in.boundary.warnings, mpi_sum(owned_moving_and_static(in.mesh, in.boundary, part.owned)));
    in.quality_seconds = sw.lap();
    progress.clear();
    const std::size_t frames = frame_count(in.spec);
    if (text) {
        std::cout << "mesh      " << in.args.mesh << ": " << describe_mesh(counts) << ", read by " << processes
                  << " processes, each its own processor folder\n";
        std::cout << "motion    " << in.args.motion << ": " << frames << " frame" << (frames == 1 ? "" : "s")
                  << "; moving: " << processor_name_list(in.boundary.moving_markers)
                  << "; static: " << processor_name_list(in.boundary.static_markers) << "\n";
        std::cout << "boundary  " << boundary_nodes << " nodes (" << moving_nodes << " moving)\n";
        for (const auto& w : in.boundary.warnings) warnings.print(w);
    }

    // The plan, on every process over its own nodes.
    MethodRun run;
    run.planned.method = method;
    run.planned.options = method_options(a.setup);
    progress.phase("preparing " + std::string(method_name(method)) + " on " + std::to_string(processes) + " processes");
    std::int64_t outside_hull = 0;
    collectively([&] {
        run.planned.distributed =
            mpi_prepare_own(method, 3, run.planned.options, in.mesh.points, part.point_ids, in.boundary.boundary,
                            run.planned.plan, run.planned.process_prepare_seconds, outside_hull);
    });
    run.planned.prepare_seconds = sw.lap();
    progress.clear();
    if (text) print_plan(std::cout, in, run.planned, warnings);

    std::vector<double> deformed(in.mesh.points.size());
    bool base_written = false;
    for (std::size_t k = 0; k < frames; ++k) {
        FrameResult f;
        f.frame = k;
        f.time = frame_time(in.spec, k);
        f.own_parts = true;
        progress.phase(std::string(method_name(method)) + ": deforming" +
                       (frames > 1 ? " frame " + std::to_string(k) + " (" + std::to_string(k + 1) + " of " +
                                         std::to_string(frames) + ")"
                                   : ""));
        ResolvedFrame motion;
        collectively([&] { motion = resolve_frame(in.mesh, in.spec, in.boundary, k); });
        const std::vector<std::string> motion_warnings = case_warnings(motion.warnings);
        f.warnings = motion_warnings;
        Stopwatch step_sw;
        f.step = mpi_deform_own(*run.planned.distributed, in.mesh.points, motion.motion, deformed, f.process_seconds);
        f.deform_seconds = step_sw.lap();
        const std::vector<std::string> step_warning_texts = step_warnings(f.step);
        f.warnings.insert(f.warnings.end(), step_warning_texts.begin(), step_warning_texts.end());

        // The frame's quality, reduced over the processes.
        const std::vector<double> quality = cell_qualities(in.mesh, deformed, in.orientation);
        const std::vector<double> ratio = quality_ratios(quality, in.original_cell_quality);
        const std::vector<std::int64_t> folded = newly_inverted_cells(quality, in.original_cell_quality);
        const std::vector<std::int64_t> on_boundary =
            cells_with_only_fixed_nodes(in.mesh.cells, in.boundary.boundary.nodes, folded);
        f.quality = case_quality(quality, part.cell_ids);
        f.ratio = case_ratios(ratio, part.cell_ids);
        std::tie(f.worst_inverted, f.inverted_by_motion) = case_worst(folded, quality, part.cell_ids, 10);
        std::tie(f.worst_on_boundary, f.inverted_on_boundary) = case_worst(on_boundary, quality, part.cell_ids, 10);
        f.quality_seconds = step_sw.lap();
        if (method == Method::dg_harmonic && !a.no_untangle && f.inverted_by_motion > 0 && f.inverted_on_boundary == 0)
            // One process would repair them (the last resort); it moves nodes
            // that several processes hold, so it is not run on the parts.
            throw InvalidResultError(
                "dg-harmonic inverted " + std::to_string(f.inverted_by_motion) + " cell" +
                    (f.inverted_by_motion == 1 ? "" : "s") + " in frame " + std::to_string(k) + " (worst: " +
                    cell_list(f.worst_inverted) +
                    "), which its last resort (untangle) would repair on one process; it does not run when each "
                    "process reads its own processor folder. Nothing was written for this frame. Run with "
                    "--untangle (rank 0 then reads the whole case and repairs them), or on one process",
                f.inverted_by_motion);
        const bool invalid = f.inverted_by_motion > 0;
        if (!invalid || a.allow_invalid) {
            write_processor_points(a.output, foam_times[k], part, deformed, base_written);
            f.output = openfoam_points_file(fs::path(a.output) / "processor*", foam_times[k]).file.string();
            f.write_seconds = step_sw.lap();
        }
        if (text) {
            progress.clear();
            print_frame(in, f, motion_warnings, step_warning_texts, frames, warnings);
        }
        run.frames.push_back(std::move(f));
        if (invalid) {
            run.invalid = true;
            run.error = invalid_frame_error(run.frames.back());
            if (!a.allow_invalid) break;  // nothing more is written after an invalid frame
        }
    }
    progress.clear();

    if (a.json && rank == 0) {
        nlohmann::json j = inputs_json(in, "deform");
        j["mesh"] = mesh_json(counts);
        j["boundary"]["nodes"] = boundary_nodes;
        j["boundary"]["moving_nodes"] = moving_nodes;
        j["output"] = given_output;
        j["processes"] = processes;
        for (const auto& w : plan_warnings(run.planned)) j["warnings"].push_back(w);
        const nlohmann::json method_run = run_json(in, run);
        for (const auto& [key, value] : method_run.items()) j[key] = value;
        j["valid"] = !run.invalid;
        std::cout << j.dump(2) << "\n";
    }
    if (run.invalid) {
        if (!a.allow_invalid)
            throw InvalidResultError(run.error + ". Nothing was written for an invalid frame. " +
                                         invalid_result_advice(method) + "; or --allow-invalid to write it anyway",
                                     1);
        if (!a.quiet && rank == 0) std::cerr << "warning: " << run.error << "; written anyway (--allow-invalid)\n";
    }
}

/// True when a marker of `spec` moves by a per-node table (node ids of the whole case).
bool has_node_tables(const MotionSpec& spec) {
    const auto tabled = [](const MarkerMotion& m) {
        return std::holds_alternative<PrescribedDisplacements>(m) || std::holds_alternative<PrescribedPositions>(m) ||
               std::holds_alternative<PrescribedNodeMotions>(m);
    };
    if (tabled(spec.default_motion)) return true;
    for (const MotionFrame& frame : spec.frames)
        for (const auto& [name, motion] : frame.markers)
            if (tabled(motion)) return true;
    return false;
}

}  // namespace

bool deforms_per_processor(const DeformArgs& a, const std::vector<Method>& methods) {
    if (mpi_processes() < 2 || methods.size() != 1 || !a.plan.empty() || a.untangle || !writes_openfoam(a.output))
        return false;
    try {
        if (openfoam_processor_meshes(a.setup.mesh).size() != static_cast<std::size_t>(mpi_processes())) return false;
        return !has_node_tables(read_motion_file(a.setup.motion));
    } catch (const Error&) {
        return false;  // the whole-case run reports it
    }
}

void run_deform_per_processor(const DeformArgs& a, const std::string& given_output) {
    mpi_run_everywhere(processor_args_json(a, given_output).dump());
    deform_per_processor(a, given_output);
}

int run_everywhere(const std::string& payload) {
    // Rank 0 reports every error; the other processes only exit with its code.
    try {
        std::string given_output;
        const DeformArgs a = processor_args_from_json(nlohmann::json::parse(payload), given_output);
        deform_per_processor(a, given_output);
        return exit_ok;
    } catch (const CLI::ParseError&) {
        return exit_usage;
    } catch (const InvalidResultError&) {
        return exit_invalid_result;
    } catch (const Error&) {
        return exit_bad_input;
    } catch (const std::exception&) {
        return exit_internal;
    }
}

}  // namespace dgwarp::cli
