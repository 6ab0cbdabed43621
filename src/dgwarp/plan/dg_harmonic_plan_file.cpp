// DG-harmonic plan files: magic "DGWHARM", format 1 (plan_file.hpp). Header,
// little-endian, no padding: u32 version, u32 dim, i64 num_points, u64 points
// hash, u64 boundary hash, f64 × 6 options (wall_spacing, growth,
// translation_exponent, rotation_exponent, rigid_zone, rigid_gap), i32
// num_boundary_vertices, u32 shared (0/1), i64 × 5 stats (coarse_interior,
// graph_vertices, outside_count, shared_vertex_count, factor_nonzeros), then
// the u64 element counts of the 19 arrays in visit_arrays' order; the arrays;
// the chained XXH64 checksum.
#include <array>
#include <cmath>
#include <string>

#include "dgwarp/plan/plan_file_detail.hpp"

namespace dgwarp::plan_detail {

namespace {

constexpr std::uint32_t format_version = 1;
constexpr std::size_t num_arrays = 19;
enum ArrayIndex : std::size_t { boundary_nodes_at, boundary_moving_at, vertex_motion_at, shared_offsets_at,
                                shared_members_at, simplices_at, node_simplex_at, node_barycentric_at, perm_at,
                                l_start_at, l_row_at, coupling_start_at, coupling_vertex_at, t_value_at, t_d_at,
                                t_weight_at, r_value_at, r_d_at, r_weight_at };

template <class Plan, class F>
void visit_arrays(Plan& p, F&& f) {
    f(p.boundary_nodes);
    f(p.boundary_moving);
    f(p.vertex_motion);
    f(p.shared_offsets);
    f(p.shared_members);
    f(p.simplices);
    f(p.node_simplex);
    f(p.node_barycentric);
    f(p.solve.perm);
    f(p.solve.l_start);
    f(p.solve.l_row);
    f(p.solve.coupling_start);
    f(p.solve.coupling_vertex);
    for (auto* s : {&p.solve.translation, &p.solve.rotation}) {
        f(s->l_value);
        f(s->d);
        f(s->coupling_weight);
    }
}

struct Header {
    std::uint32_t version = format_version, dim = 0;
    std::int64_t num_points = 0;
    std::uint64_t points_hash = 0, boundary_hash = 0;
    std::array<double, 6> options{};
    std::int32_t num_boundary_vertices = 0;
    std::uint32_t shared = 0;
    std::array<std::int64_t, 5> stats{};
    std::array<std::uint64_t, num_arrays> counts{};
};

template <class H, class F>
void visit_header(H& h, F&& field) {
    field(h.version);
    field(h.dim);
    field(h.num_points);
    field(h.points_hash);
    field(h.boundary_hash);
    for (auto& o : h.options) field(o);
    field(h.num_boundary_vertices);
    field(h.shared);
    for (auto& s : h.stats) field(s);
    for (auto& c : h.counts) field(c);
}

std::size_t header_size() {
    Header h;
    std::size_t n = dg_harmonic_magic.size();
    visit_header(h, [&](auto& v) { n += sizeof v; });
    return n;
}

// Offsets of header fields, for error messages.
constexpr std::uint64_t version_at = 8, dim_at = 12, options_at = 40, shared_at = 92;

}  // namespace

void write_dg_harmonic(std::ostream& out, const DgHarmonicPlan& plan) {
    Header h;
    h.dim = static_cast<std::uint32_t>(plan.dim);
    h.num_points = plan.mesh.num_points;
    h.points_hash = plan.mesh.points_hash;
    h.boundary_hash = plan.mesh.boundary_hash;
    const DgHarmonicOptions& o = plan.options;
    // A plan's options are resolved (resolved_options): every one set.
    h.options = {o.wall_spacing, o.growth, o.translation_exponent.value(), o.rotation_exponent.value(),
                 o.rigid_zone.value(), o.rigid_gap};
    h.num_boundary_vertices = plan.num_boundary_vertices;
    h.shared = plan.solve.shared ? 1 : 0;
    const DgHarmonicPrepareStats& s = plan.stats;
    h.stats = {s.coarse_interior, s.graph_vertices, s.outside_count, s.shared_vertex_count, s.factor_nonzeros};
    std::size_t a = 0;
    visit_arrays(plan, [&](const auto& v) { h.counts[a++] = v.size(); });
    std::vector<std::byte> header;
    header.insert(header.end(), reinterpret_cast<const std::byte*>(dg_harmonic_magic.data()),
                  reinterpret_cast<const std::byte*>(dg_harmonic_magic.data()) + dg_harmonic_magic.size());
    visit_header(h, [&](const auto& v) { put(header, v); });
    write_plan_stream(out, header, [&](auto&& f) { visit_arrays(plan, f); });
}

namespace {

// The header, checked field by field (`raw`: its bytes, which the checksum covers).
Header read_header(const PlanSource& source, std::vector<std::byte>& raw) {
    const std::filesystem::path path = source.name;
    const std::size_t header_bytes = header_size();
    if (source.size < header_bytes)
        fail(path, 0, "a DG-harmonic plan header of " + std::to_string(header_bytes) + " bytes",
             "a file of " + std::to_string(source.size) + " bytes");
    raw.resize(header_bytes);
    source.read(raw.data(), raw.size(), 0);
    Header h;
    std::size_t at = dg_harmonic_magic.size();
    visit_header(h, [&](auto& v) { get(raw, at, v); });
    if (h.version != format_version)
        fail(path, version_at, "DG-harmonic plan format version " + std::to_string(format_version),
             std::to_string(h.version) + (h.version < format_version ? " (an older dgwarp's" : " (a newer dgwarp's") +
                 ": run dgwarp prepare again)");
    if (h.dim != 2 && h.dim != 3) fail(path, dim_at, "dim 2 or 3", std::to_string(h.dim));
    for (std::size_t i = 0; i < h.options.size(); ++i)
        if (!std::isfinite(h.options[i])) fail(path, options_at + 8 * i, "a finite option", std::to_string(h.options[i]));
    if (h.shared > 1) fail(path, shared_at, "a shared flag 0 or 1", std::to_string(h.shared));
    return h;
}

// The arrays' lengths agree with each other and with num_points.
void check_array_lengths(const std::filesystem::path& path, const Header& h) {
    const auto& c = h.counts;
    const std::uint64_t corners = h.dim + 1, n = c[perm_at], nnz = c[l_row_at], nb = c[boundary_nodes_at];
    const std::uint64_t points = static_cast<std::uint64_t>(h.num_points);
    const std::uint64_t vertices = c[vertex_motion_at];
    const bool rotation_ok = h.shared == 1 ? c[r_value_at] == 0 && c[r_d_at] == 0 && c[r_weight_at] == 0
                                           : c[r_value_at] == nnz && c[r_d_at] == n && c[r_weight_at] == c[coupling_vertex_at];
    if (h.num_points < 0 || c[boundary_moving_at] != nb || nb > points || c[node_simplex_at] != points ||
        c[node_barycentric_at] != (points - nb) * corners || c[simplices_at] % corners != 0 || c[shared_offsets_at] < 1 ||
        h.num_boundary_vertices < 0 || static_cast<std::uint64_t>(h.num_boundary_vertices) > vertices ||
        n != vertices - static_cast<std::uint64_t>(h.num_boundary_vertices) || c[l_start_at] != n + 1 ||
        c[coupling_start_at] != n + 1 || c[t_value_at] != nnz || c[t_d_at] != n ||
        c[t_weight_at] != c[coupling_vertex_at] || !rotation_ok)
        fail(path, header_size() - 8 * num_arrays,
             "DG-harmonic array lengths consistent with each other and num_points " + std::to_string(h.num_points),
             "inconsistent lengths");
}

// Indices in range, so that deform never reads out of bounds, and the
// factor's structure sound (a permutation, nondecreasing column starts, rows
// below the diagonal, nonzero pivots). `off`: each array's byte offset in the file.
void check_indices(const std::filesystem::path& path, const DgHarmonicPlan& p, const Header& h,
                   const std::vector<std::uint64_t>& off) {
    const auto& c = h.counts;
    const std::uint64_t corners = h.dim + 1, n = c[perm_at], nnz = c[l_row_at], nb = c[boundary_nodes_at];
    const std::uint64_t vertices = c[vertex_motion_at];
    const auto num_simplices = static_cast<std::int64_t>(c[simplices_at] / corners);
    const auto nbv = static_cast<std::int64_t>(h.num_boundary_vertices);
    check_core_arrays(path, p,
                      {off[boundary_nodes_at], off[boundary_moving_at], off[node_simplex_at], off[shared_offsets_at],
                       off[shared_members_at]},
                      h.num_points, num_simplices);
    check_range(path, off[vertex_motion_at], "a vertex motion index",
                std::span(p.vertex_motion).first(static_cast<std::size_t>(nbv)), -static_cast<std::int64_t>(nb),
                static_cast<std::int64_t>(nb));
    check_range(path, off[simplices_at], "a coarse graph vertex", p.simplices, 0, static_cast<std::int64_t>(vertices));
    check_range(path, off[coupling_vertex_at], "a boundary vertex", p.solve.coupling_vertex, 0, nbv);
    check_range(path, off[perm_at], "a factor position", p.solve.perm, 0, static_cast<std::int64_t>(n));
    std::vector<char> seen(n, 0);
    for (std::size_t i = 0; i < n; ++i)
        if (seen[p.solve.perm[i]]++) fail(path, off[perm_at] + 4 * i, "a permutation", "a repeated position");
    for (const auto& [start, start_at, end] : {std::tuple{&p.solve.l_start, off[l_start_at], nnz},
                                               std::tuple{&p.solve.coupling_start, off[coupling_start_at],
                                                          c[coupling_vertex_at]}}) {
        const auto& s = *start;
        for (std::size_t j = 0; j < s.size(); ++j)
            if ((j == 0 && s[0] != 0) || (j > 0 && s[j] < s[j - 1]) ||
                (j + 1 == s.size() && static_cast<std::uint64_t>(s[j]) != end))
                fail(path, start_at + 8 * j, "nondecreasing offsets from 0 to " + std::to_string(end), std::to_string(s[j]));
    }
    for (std::size_t j = 0; j < n; ++j)
        for (std::int64_t q = p.solve.l_start[j]; q < p.solve.l_start[j + 1]; ++q)
            if (p.solve.l_row[q] <= static_cast<std::int32_t>(j) || static_cast<std::uint64_t>(p.solve.l_row[q]) >= n)
                fail(path, off[l_row_at] + 4 * q,
                     "a row below the diagonal of column " + std::to_string(j) + " and under " + std::to_string(n),
                     std::to_string(p.solve.l_row[q]));
    for (const auto& [d, d_at] : {std::pair{&p.solve.translation.d, off[t_d_at]}, std::pair{&p.solve.rotation.d, off[r_d_at]}})
        for (std::size_t i = 0; i < d->size(); ++i)
            if (!std::isfinite((*d)[i]) || (*d)[i] == 0) fail(path, d_at + 8 * i, "a finite nonzero pivot", std::to_string((*d)[i]));
}

}  // namespace

DgHarmonicPlan load_dg_harmonic(const PlanSource& source) {
    const std::filesystem::path path = source.name;
    std::vector<std::byte> raw;
    const Header h = read_header(source, raw);
    DgHarmonicPlan p;
    p.dim = static_cast<int>(h.dim);
    p.solve.shared = h.shared == 1;
    const std::vector<std::uint64_t> off = read_plan_arrays(source, raw, h.counts, [&](auto&& f) { visit_arrays(p, f); });
    check_array_lengths(path, h);
    check_indices(path, p, h, off);
    p.mesh = {h.num_points, h.points_hash, h.boundary_hash};
    p.options.wall_spacing = h.options[0];
    p.options.growth = h.options[1];
    p.options.translation_exponent = h.options[2];
    p.options.rotation_exponent = h.options[3];
    p.options.rigid_zone = h.options[4];
    p.options.rigid_gap = h.options[5];
    p.num_boundary_vertices = h.num_boundary_vertices;
    p.stats = {h.stats[0], h.stats[1], h.stats[2], h.stats[3], h.stats[4]};
    return p;
}

std::vector<std::byte> with_recomputed_dg_harmonic_checksum(std::span<const std::byte> bytes) {
    std::vector<std::size_t> sizes;
    DgHarmonicPlan element_types;
    visit_arrays(element_types, [&](const auto& v) { sizes.push_back(sizeof(v[0])); });
    return with_recomputed_checksum(bytes, header_size(), sizes);
}

}  // namespace dgwarp::plan_detail
