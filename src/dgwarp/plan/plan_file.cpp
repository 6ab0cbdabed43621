#include "dgwarp/plan/plan_file.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstring>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>

#include "dgwarp/core/atomic_write.hpp"
#include "dgwarp/core/error.hpp"
#include "dgwarp/core/hash.hpp"
#include "dgwarp/plan/plan_file_detail.hpp"

namespace dgwarp {

namespace {

using plan_detail::check_range;
using plan_detail::fail;
using plan_detail::PlanSource;

static_assert(std::endian::native == std::endian::little, "plan files are little-endian");

constexpr std::array<char, 8> magic = {'D', 'G', 'W', 'P', 'L', 'A', 'N', '\0'};
// 2: the DG-IDW weighting (paper / continuous) in the header.
// 3: a_translation, a_rotation and length_scale in the header (deform uses the plan's).
constexpr std::uint32_t format_version = 3;
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
    double a_translation = 0;
    double a_rotation = 0;
    double length_scale = 0;  // 0 = auto
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
    field(h.a_translation);
    field(h.a_rotation);
    field(h.length_scale);
    for (auto& c : h.counts) field(c);
}

constexpr std::size_t header_size() {
    Header h;
    std::size_t n = sizeof(magic);
    visit_header(h, [&](auto& v) { n += sizeof v; });
    return n;
}
constexpr std::size_t header_bytes = header_size();
static_assert(header_bytes == 8 + 3 * 4 + 11 * 8 + num_arrays * 8);
// Byte offsets of auto_length_scale, of a_translation (the options follow
// one another) and of the array counts.
constexpr std::size_t auto_length_scale_at = 8 + 3 * 4 + 3 * 8;
constexpr std::size_t options_at = 8 + 3 * 4 + 8 * 8;
constexpr std::size_t counts_at = header_bytes - 8 * num_arrays;

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

}  // namespace

namespace {
void write_dg_idw(std::ostream& out, const DgIdwPlan& plan) {
    Header h;
    h.dim = static_cast<std::uint32_t>(plan.dim);
    h.weighting = static_cast<std::uint32_t>(plan.options.weighting);
    h.a_translation = plan.options.a_translation;
    h.a_rotation = plan.options.a_rotation;
    h.length_scale = plan.options.length_scale;
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
    plan_detail::write_plan_stream(out, header, [&](auto&& f) { visit_arrays(plan, f); });
}
}  // namespace

void save_dg_idw_plan(const std::filesystem::path& path, const DgIdwPlan& plan) {
    write_file_atomically(path, [&](std::ostream& out) { write_dg_idw(out, plan); });
}

namespace {

// The header of a plan file, checked field by field (`raw`: its bytes, which
// the checksum covers).
Header read_header(const PlanSource& source, std::array<std::byte, header_bytes>& raw) {
    const std::filesystem::path path = source.name;  // names the plan in errors
    if (source.size < header_bytes)
        fail(path, 0, "a plan header of " + std::to_string(header_bytes) + " bytes",
             "a file of " + std::to_string(source.size) + " bytes");
    source.read(raw.data(), raw.size(), 0);
    if (std::memcmp(raw.data(), magic.data(), magic.size()) != 0)
        fail(path, 0, "the plan file signature DGWPLAN", "another file type");
    Header h;
    std::size_t at = magic.size();
    visit_header(h, [&](auto& v) {
        std::memcpy(&v, raw.data() + at, sizeof v);
        at += sizeof v;
    });
    if (h.version != format_version)
        fail(path, 8, "plan format version " + std::to_string(format_version),
             std::to_string(h.version) + (h.version < format_version ? " (an older dgwarp's: run dgwarp prepare again)"
                                                                      : " (a newer dgwarp's: run dgwarp prepare again)"));
    if (h.dim != 2 && h.dim != 3) fail(path, 12, "dim 2 or 3", std::to_string(h.dim));
    if (h.weighting > static_cast<std::uint32_t>(DgIdwWeighting::continuous))
        fail(path, 16, "weighting 0 (paper) or 1 (continuous)", std::to_string(h.weighting));

    auto positive = [](double a) { return std::isfinite(a) && a > 0; };
    if (!positive(h.a_translation)) fail(path, options_at, "a positive a_translation", std::to_string(h.a_translation));
    if (!positive(h.a_rotation)) fail(path, options_at + 8, "a positive a_rotation", std::to_string(h.a_rotation));
    if (!std::isfinite(h.length_scale) || h.length_scale < 0)
        fail(path, options_at + 16, "a length_scale >= 0 (0 = auto)", std::to_string(h.length_scale));
    if (!std::isfinite(h.auto_length_scale) || h.auto_length_scale < 0)
        fail(path, auto_length_scale_at, "an auto length scale >= 0", std::to_string(h.auto_length_scale));
    return h;
}

// The arrays' lengths agree with each other and with num_points.
void check_array_lengths(const std::filesystem::path& path, const Header& h) {
    const std::uint64_t corners = h.dim + 1;
    const auto& c = h.counts;
    const std::uint64_t n = static_cast<std::uint64_t>(h.num_points);
    if (h.num_points < 0 || c[boundary_moving_at] != c[boundary_nodes_at] || c[node_simplex_at] != n ||
        c[boundary_nodes_at] > n || c[simplex_motion_at] % corners != 0 || c[shared_offsets_at] < 1 ||
        c[node_coefficients_at] != (n - c[boundary_nodes_at]) * corners)
        fail(path, counts_at, "array lengths consistent with each other and num_points " + std::to_string(h.num_points),
             "inconsistent lengths");
}

// Every index in range, so that a plan deforms without reading out of bounds,
// and each simplex row with its moving corners first. `offsets`: each array's
// byte offset in the file (for the messages).
void check_indices(const std::filesystem::path& path, const DgIdwPlan& plan, const Header& h,
                   const std::vector<std::uint64_t>& offsets) {
    const std::uint64_t corners = h.dim + 1;
    const auto num_boundary = static_cast<std::int64_t>(h.counts[boundary_nodes_at]);
    const auto num_simplices = static_cast<std::int64_t>(h.counts[simplex_motion_at] / corners);
    plan_detail::check_core_arrays(path, plan,
                                   {offsets[boundary_nodes_at], offsets[boundary_moving_at], offsets[node_simplex_at],
                                    offsets[shared_offsets_at], offsets[shared_members_at]},
                                   h.num_points, num_simplices);
    check_range(path, offsets[simplex_motion_at], "a corner motion index", plan.simplex_motion, -num_boundary,
                num_boundary);
    for (std::size_t k = 0; k < plan.simplex_motion.size(); ++k)
        if (k % corners != 0 && plan.simplex_motion[k] >= 0 && plan.simplex_motion[k - 1] < 0)
            fail(path, offsets[simplex_motion_at] + 4 * k, "the moving corners first in each simplex row",
                 "a moving corner after a static one");
}

DgIdwPlan load_dg_idw(const PlanSource& source) {
    const std::filesystem::path path = source.name;  // names the plan in errors
    std::array<std::byte, header_bytes> header_raw;
    const Header h = read_header(source, header_raw);

    DgIdwPlan plan;
    plan.dim = static_cast<int>(h.dim);
    plan.options = {.a_translation = h.a_translation,
                    .a_rotation = h.a_rotation,
                    .length_scale = h.length_scale,
                    .weighting = static_cast<DgIdwWeighting>(h.weighting)};
    const std::vector<std::uint64_t> offsets =
        plan_detail::read_plan_arrays(source, header_raw, h.counts, [&](auto&& f) { visit_arrays(plan, f); });
    check_array_lengths(path, h);
    check_indices(path, plan, h, offsets);
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
    return load_dg_idw(plan_detail::bytes_source(bytes, name));
}

DgIdwPlan load_dg_idw_plan(const std::filesystem::path& path) {
    std::ifstream in;
    return load_dg_idw(plan_detail::file_source(path, in));
}

DgIdwPlan load_dg_idw_plan(const std::filesystem::path& path, std::span<const double> points,
                           const BoundarySet& boundary) {
    DgIdwPlan plan = load_dg_idw_plan(path);
    check_plan_fits(plan, points, boundary);
    return plan;
}

std::vector<std::byte> with_recomputed_plan_checksum(std::span<const std::byte> bytes) {
    if (bytes.size() >= 8 && std::memcmp(bytes.data(), plan_detail::dg_harmonic_magic.data(), 8) == 0)
        return plan_detail::with_recomputed_dg_harmonic_checksum(bytes);
    std::vector<std::size_t> sizes;
    DgIdwPlan element_types;
    visit_arrays(element_types, [&](const auto& v) { sizes.push_back(sizeof(v[0])); });
    return plan_detail::with_recomputed_checksum(bytes, header_bytes, sizes);
}

namespace {
[[noreturn]] void refuse_to_save(const Plan& plan) {
    throw Error(std::string("plans of ") + std::string(method_name(plan_method(plan))) +
                " cannot be saved (only dg-idw and dg-harmonic plans can)");
}

/// Writes any savable plan's file to `out`; throws Error for the others.
void write_any(std::ostream& out, const Plan& plan) {
    if (const auto* p = std::get_if<DgIdwPlan>(&plan)) return write_dg_idw(out, *p);
    if (const auto* p = std::get_if<DgHarmonicPlan>(&plan)) return plan_detail::write_dg_harmonic(out, *p);
    refuse_to_save(plan);
}
}  // namespace

bool plan_can_be_saved(const Plan& plan) {
    return std::holds_alternative<DgIdwPlan>(plan) || std::holds_alternative<DgHarmonicPlan>(plan);
}

void save_plan(const std::filesystem::path& path, const Plan& plan) {
    if (!plan_can_be_saved(plan)) refuse_to_save(plan);  // before a file is made
    write_file_atomically(path, [&](std::ostream& out) { write_any(out, plan); });
}

std::vector<std::byte> plan_file_bytes(const Plan& plan) {
    std::ostringstream out(std::ios::binary);
    write_any(out, plan);
    const std::string text = std::move(out).str();
    const auto* first = reinterpret_cast<const std::byte*>(text.data());
    return std::vector<std::byte>(first, first + text.size());
}

namespace {
Plan load_any(const PlanSource& source) {
    if (plan_detail::peek_magic(source) == plan_detail::dg_harmonic_magic) return plan_detail::load_dg_harmonic(source);
    return load_dg_idw(source);
}
}  // namespace

Plan load_plan(const std::filesystem::path& path) {
    std::ifstream in;
    return load_any(plan_detail::file_source(path, in));
}

Plan load_plan_bytes(std::span<const std::byte> bytes, const std::string& name) {
    return load_any(plan_detail::bytes_source(bytes, name));
}

Plan load_plan(const std::filesystem::path& path, std::span<const double> points, const BoundarySet& boundary) {
    Plan plan = load_plan(path);
    if (const auto* p = std::get_if<DgIdwPlan>(&plan)) check_plan_fits(*p, points, boundary);
    if (const auto* p = std::get_if<DgHarmonicPlan>(&plan)) check_plan_fits(*p, points, boundary);
    return plan;
}

}  // namespace dgwarp
