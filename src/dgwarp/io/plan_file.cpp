#include "dgwarp/io/plan_file.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cstring>
#include <fstream>
#include <functional>
#include <string>

#include "dgwarp/core/error.hpp"
#include "dgwarp/core/hash.hpp"
#include "dgwarp/io/atomic_write.hpp"

namespace dgwarp {

namespace {

static_assert(std::endian::native == std::endian::little, "plan files are little-endian");

constexpr std::array<char, 8> magic = {'D', 'G', 'W', 'P', 'L', 'A', 'N', '\0'};
// 2: the DG-IDW weighting (paper / continuous) in the header.
constexpr std::uint32_t format_version = 2;
constexpr int num_arrays = 7;
// Positions of the arrays in the file (and in Header::counts).
enum ArrayIndex { boundary_nodes_at, boundary_moving_at, simplex_motion_at, shared_offsets_at, shared_members_at,
                  node_simplex_at, node_coefficients_at };

// The fixed-size header, field by field (written without padding).
struct Header {
    std::uint32_t version = format_version;
    std::uint32_t dim = 0;
    std::uint32_t weighting = 0;  // DgIdwWeighting
    std::int64_t num_points = 0;
    std::uint64_t points_hash = 0;
    std::uint64_t boundary_hash = 0;
    double auto_length_scale = 0;
    std::int64_t outside_count = 0;
    std::int64_t snapped_count = 0;
    std::int64_t shared_vertex_count = 0;
    std::int64_t graph_vertex_count = 0;
    std::array<std::uint64_t, num_arrays> counts{};  // elements of each array
};

// Serialises the header fields in order.
template <class F>
constexpr void visit_header(Header& h, F&& field) {
    field(h.version);
    field(h.dim);
    field(h.weighting);
    field(h.num_points);
    field(h.points_hash);
    field(h.boundary_hash);
    field(h.auto_length_scale);
    field(h.outside_count);
    field(h.snapped_count);
    field(h.shared_vertex_count);
    field(h.graph_vertex_count);
    for (auto& c : h.counts) field(c);
}

constexpr std::size_t header_size() {
    Header h;
    std::size_t n = sizeof(magic);
    visit_header(h, [&](auto& v) { n += sizeof v; });
    return n;
}
constexpr std::size_t header_bytes = header_size();
static_assert(header_bytes == 8 + 3 * 4 + 8 * 8 + num_arrays * 8);

// The plan's arrays in file order, as (bytes, element size) views.
template <class Plan, class F>
void visit_arrays(Plan& plan, F&& array) {
    array(plan.boundary_nodes);
    array(plan.boundary_moving);
    array(plan.simplex_motion);
    array(plan.shared_offsets);
    array(plan.shared_members);
    array(plan.node_simplex);
    array(plan.node_coefficients);
}

std::array<std::byte, header_bytes> encode_header(Header h) {
    std::array<std::byte, header_bytes> bytes{};
    std::size_t at = 0;
    std::memcpy(bytes.data(), magic.data(), magic.size());
    at += magic.size();
    visit_header(h, [&](auto& v) {
        std::memcpy(bytes.data() + at, &v, sizeof v);
        at += sizeof v;
    });
    return bytes;
}

[[noreturn]] void fail(const std::filesystem::path& path, std::uint64_t offset, const std::string& expected,
                       const std::string& found) {
    throw ParseError(path.string(), 0, expected + " at byte offset " + std::to_string(offset), found);
}

void check_range(const std::filesystem::path& path, std::uint64_t offset, const char* what,
                 std::span<const std::int32_t> values, std::int64_t lo, std::int64_t hi) {
    for (std::size_t i = 0; i < values.size(); ++i)
        if (values[i] < lo || values[i] >= hi)
            fail(path, offset + 4 * i, std::string(what) + " in [" + std::to_string(lo) + ", " + std::to_string(hi) + ")",
                 std::to_string(values[i]));
}

}  // namespace

void save_dg_idw_plan(const std::filesystem::path& path, const DgIdwPlan& plan) {
    Header h;
    h.dim = static_cast<std::uint32_t>(plan.dim);
    h.weighting = static_cast<std::uint32_t>(plan.weighting);
    h.num_points = plan.mesh.num_points;
    h.points_hash = plan.mesh.points_hash;
    h.boundary_hash = plan.mesh.boundary_hash;
    h.auto_length_scale = plan.auto_length_scale;
    h.outside_count = plan.stats.outside_count;
    h.snapped_count = plan.stats.snapped_count;
    h.shared_vertex_count = plan.stats.shared_vertex_count;
    h.graph_vertex_count = plan.stats.graph_vertex_count;
    int a = 0;
    visit_arrays(plan, [&](const auto& v) { h.counts[a++] = v.size(); });
    const auto header = encode_header(h);
    write_file_atomically(path, [&](std::ostream& out) {
        out.write(reinterpret_cast<const char*>(header.data()), header.size());
        std::uint64_t checksum = hash64(header);
        visit_arrays(plan, [&](const auto& v) {
            const auto bytes = std::as_bytes(std::span(v));
            out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
            checksum = hash64(bytes, checksum);
        });
        out.write(reinterpret_cast<const char*>(&checksum), sizeof checksum);
    });
}

namespace {

/// Where a plan is read from: a file or bytes in memory. `read` copies n bytes
/// at `offset` (always the next unread byte) or throws IoError.
struct PlanSource {
    std::string name;
    std::uint64_t size = 0;
    std::function<void(void* to, std::size_t n, std::uint64_t offset)> read;
};

DgIdwPlan load_plan(const PlanSource& source) {
    const std::filesystem::path path = source.name;  // names the plan in errors
    const std::uint64_t file_size = source.size;
    const auto& read = source.read;

    // Header.
    if (file_size < header_bytes)
        fail(path, 0, "a plan header of " + std::to_string(header_bytes) + " bytes",
             "a file of " + std::to_string(file_size) + " bytes");
    std::array<std::byte, header_bytes> header_raw;
    read(header_raw.data(), header_raw.size(), 0);
    if (std::memcmp(header_raw.data(), magic.data(), magic.size()) != 0)
        fail(path, 0, "the plan file signature DGWPLAN", "another file type");
    Header h;
    std::size_t at = magic.size();
    visit_header(h, [&](auto& v) {
        std::memcpy(&v, header_raw.data() + at, sizeof v);
        at += sizeof v;
    });
    if (h.version != format_version)
        fail(path, 8, "plan format version " + std::to_string(format_version), std::to_string(h.version));
    if (h.dim != 2 && h.dim != 3) fail(path, 12, "dim 2 or 3", std::to_string(h.dim));
    if (h.weighting > static_cast<std::uint32_t>(DgIdwWeighting::continuous))
        fail(path, 16, "weighting 0 (paper) or 1 (continuous)", std::to_string(h.weighting));

    // Sizes: each count is checked against the file size first, so the sums
    // below cannot overflow and nothing huge is allocated for a corrupt header.
    DgIdwPlan plan;
    plan.dim = static_cast<int>(h.dim);
    plan.weighting = static_cast<DgIdwWeighting>(h.weighting);
    std::uint64_t expected = header_bytes + 8;  // header + checksum
    std::uint64_t offset = header_bytes;
    int a = 0;
    visit_arrays(plan, [&](const auto& v) {
        const std::uint64_t count = h.counts[a], element = sizeof(v[0]);
        if (count > file_size / element)
            fail(path, header_bytes - 8 * (num_arrays - a),
                 "an array length that fits in the file's " + std::to_string(file_size) + " bytes (truncated file?)",
                 std::to_string(count));
        expected += count * element;
        ++a;
    });
    if (expected != file_size)
        fail(path, std::min(expected, file_size), "a file of " + std::to_string(expected) + " bytes (from its header)",
             std::to_string(file_size) + " bytes (truncated or extended)");
    const std::uint64_t corners = h.dim + 1;
    const auto& c = h.counts;
    const std::uint64_t n = static_cast<std::uint64_t>(h.num_points);
    if (h.num_points < 0 || c[boundary_moving_at] != c[boundary_nodes_at] || c[node_simplex_at] != n ||
        c[boundary_nodes_at] > n || c[simplex_motion_at] % corners != 0 || c[shared_offsets_at] < 1 ||
        c[node_coefficients_at] != (n - c[boundary_nodes_at]) * corners)
        fail(path, header_bytes - 8 * num_arrays,
             "array lengths consistent with each other and num_points " + std::to_string(h.num_points),
             "inconsistent lengths");

    // Arrays, read in place, and the checksum.
    std::uint64_t checksum = hash64(header_raw);
    std::array<std::uint64_t, num_arrays> offsets{};
    a = 0;
    visit_arrays(plan, [&](auto& v) {
        v.resize(static_cast<std::size_t>(h.counts[a]));
        const auto bytes = std::as_writable_bytes(std::span(v));
        read(bytes.data(), bytes.size(), offset);
        checksum = hash64(bytes, checksum);
        offsets[a++] = offset;
        offset += bytes.size();
    });
    std::uint64_t stored;
    read(&stored, sizeof stored, offset);
    if (stored != checksum) fail(path, offset, "checksum " + std::to_string(checksum), std::to_string(stored));

    // Indices must be in range, so a plan deforms without reading out of bounds.
    const auto num_boundary = static_cast<std::int64_t>(c[boundary_nodes_at]);
    const auto num_simplices = static_cast<std::int64_t>(c[simplex_motion_at] / corners);
    const auto num_shared = static_cast<std::int32_t>(c[shared_members_at]);
    check_range(path, offsets[boundary_nodes_at], "a boundary node id", plan.boundary_nodes, 0, h.num_points);
    for (std::size_t b = 0; b < plan.boundary_moving.size(); ++b)
        if (plan.boundary_moving[b] > 1)
            fail(path, offsets[boundary_moving_at] + b, "a moving flag 0 or 1", std::to_string(plan.boundary_moving[b]));
    check_range(path, offsets[simplex_motion_at], "a corner motion index", plan.simplex_motion, -num_boundary,
                num_boundary);
    for (std::size_t k = 0; k < plan.simplex_motion.size(); ++k)
        if (k % corners != 0 && plan.simplex_motion[k] >= 0 && plan.simplex_motion[k - 1] < 0)
            fail(path, offsets[simplex_motion_at] + 4 * k, "the moving corners first in each simplex row",
                 "a moving corner after a static one");
    check_range(path, offsets[shared_members_at], "a boundary index", plan.shared_members, 0, num_boundary);
    check_range(path, offsets[node_simplex_at], "a simplex id or boundary index", plan.node_simplex, -num_boundary,
                num_simplices);
    // Boundary nodes sorted, and node_simplex marks exactly them (deform counts
    // volume nodes from this), shared groups well formed.
    for (std::size_t b = 0; b < plan.boundary_nodes.size(); ++b) {
        if (b > 0 && plan.boundary_nodes[b] <= plan.boundary_nodes[b - 1])
            fail(path, offsets[boundary_nodes_at] + 4 * b, "sorted boundary node ids",
                 std::to_string(plan.boundary_nodes[b]));
        const auto node = static_cast<std::size_t>(plan.boundary_nodes[b]);
        if (plan.node_simplex[node] != -1 - static_cast<std::int32_t>(b))
            fail(path, offsets[node_simplex_at] + 4 * node,
                 "boundary index " + std::to_string(b) + " encoded as " + std::to_string(-1 - static_cast<std::int64_t>(b)),
                 std::to_string(plan.node_simplex[node]));
    }
    if (std::count_if(plan.node_simplex.begin(), plan.node_simplex.end(), [](std::int32_t s) { return s < 0; }) !=
        num_boundary)
        fail(path, offsets[node_simplex_at], std::to_string(num_boundary) + " boundary entries in node_simplex",
             "another count");
    const auto& so = plan.shared_offsets;
    for (std::size_t g = 0; g < so.size(); ++g)
        if ((g == 0 && so[0] != 0) || (g > 0 && so[g] < so[g - 1]) || (g + 1 == so.size() && so[g] != num_shared))
            fail(path, offsets[shared_offsets_at] + 4 * g,
                 "nondecreasing shared-vertex offsets from 0 to " + std::to_string(num_shared), std::to_string(so[g]));

    plan.mesh = {h.num_points, h.points_hash, h.boundary_hash};
    plan.auto_length_scale = h.auto_length_scale;
    plan.stats.outside_count = h.outside_count;
    plan.stats.snapped_count = h.snapped_count;
    plan.stats.shared_vertex_count = h.shared_vertex_count;
    plan.stats.graph_vertex_count = h.graph_vertex_count;
    return plan;
}

}  // namespace

DgIdwPlan load_dg_idw_plan_bytes(std::span<const std::byte> bytes, const std::string& name) {
    const PlanSource source{name, bytes.size(), [&](void* to, std::size_t n, std::uint64_t offset) {
                                // load_plan checks sizes against `size` first; a short read is a bug.
                                if (offset > bytes.size() || n > bytes.size() - offset)
                                    throw IoError(name, "read past the end at byte offset " + std::to_string(offset));
                                if (n > 0) std::memcpy(to, bytes.data() + offset, n);  // `to` may be null when n == 0
                            }};
    return load_plan(source);
}

DgIdwPlan load_dg_idw_plan(const std::filesystem::path& path) {
    std::error_code ec;
    const std::uint64_t file_size = std::filesystem::file_size(path, ec);
    if (ec) throw IoError(path.string(), "cannot read plan file: " + ec.message());
    std::ifstream in(path, std::ios::binary);
    if (!in) throw IoError(path.string(), "cannot open plan file for reading");
    // Arrays are read straight into the plan's vectors: no copy of the whole file.
    const PlanSource source{path.string(), file_size, [&](void* to, std::size_t n, std::uint64_t offset) {
                                if (!in.read(static_cast<char*>(to), static_cast<std::streamsize>(n)))
                                    throw IoError(path.string(), "read failed at byte offset " + std::to_string(offset));
                            }};
    return load_plan(source);
}

DgIdwPlan load_dg_idw_plan(const std::filesystem::path& path, std::span<const double> points,
                           const BoundarySet& boundary) {
    DgIdwPlan plan = load_dg_idw_plan(path);
    check_plan_fits(plan, points, boundary);
    return plan;
}

std::vector<std::byte> with_recomputed_plan_checksum(std::span<const std::byte> bytes) {
    std::vector<std::byte> fixed(bytes.begin(), bytes.end());
    if (bytes.size() < header_bytes + 8) return fixed;
    std::array<std::uint64_t, num_arrays> sizes{};
    std::uint64_t total = header_bytes + 8;
    bool fits = true;
    DgIdwPlan element_types;
    int a = 0;
    visit_arrays(element_types, [&](const auto& v) {
        std::uint64_t count;
        std::memcpy(&count, bytes.data() + header_bytes - 8 * (num_arrays - a), 8);
        fits = fits && count <= bytes.size();
        sizes[a] = count * sizeof(v[0]);
        total += sizes[a];
        ++a;
    });
    if (!fits || total != bytes.size()) return fixed;
    std::uint64_t checksum = hash64(bytes.first(header_bytes));
    std::size_t at = header_bytes;
    for (const std::uint64_t size : sizes) {
        checksum = hash64(bytes.subspan(at, size), checksum);
        at += size;
    }
    std::memcpy(fixed.data() + at, &checksum, 8);
    return fixed;
}

}  // namespace dgwarp
