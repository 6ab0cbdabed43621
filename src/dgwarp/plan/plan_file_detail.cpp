#include "dgwarp/plan/plan_file_detail.hpp"

#include <algorithm>
#include <cerrno>
#include <cstring>

namespace dgwarp::plan_detail {

PlanSource file_source(const std::filesystem::path& path, std::ifstream& in) {
    std::error_code ec;
    const std::uint64_t file_size = std::filesystem::file_size(path, ec);
    if (ec) throw IoError(path.string(), "cannot read plan file: " + ec.message(), ec.value());
    in.open(path, std::ios::binary);
    if (!in) {
        const int err = errno;
        throw IoError(path.string(), std::string("cannot open plan file for reading: ") + std::strerror(err), err);
    }
    // Arrays are read straight into the plan's vectors: no copy of the whole file.
    return {path.string(), file_size, [&in, name = path.string()](void* to, std::size_t n, std::uint64_t offset) {
                in.seekg(static_cast<std::streamoff>(offset));
                if (!in.read(static_cast<char*>(to), static_cast<std::streamsize>(n)))
                    throw IoError(name, "read failed at byte offset " + std::to_string(offset));
            }};
}

PlanSource bytes_source(std::span<const std::byte> bytes, const std::string& name) {
    return {name, bytes.size(), [bytes, name](void* to, std::size_t n, std::uint64_t offset) {
                // Loaders check sizes against `size` first; a short read is a bug.
                if (offset > bytes.size() || n > bytes.size() - offset)
                    throw IoError(name, "read past the end at byte offset " + std::to_string(offset));
                if (n > 0) std::memcpy(to, bytes.data() + offset, n);  // `to` may be null when n == 0
            }};
}

void fail(const std::filesystem::path& path, std::uint64_t offset, const std::string& expected,
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

std::array<char, 8> peek_magic(const PlanSource& source) {
    std::array<char, 8> m{};
    if (source.size >= m.size()) source.read(m.data(), m.size(), 0);
    return m;
}

std::vector<std::byte> with_recomputed_checksum(std::span<const std::byte> bytes, std::size_t header_bytes,
                                                std::span<const std::size_t> element_sizes) {
    std::vector<std::byte> fixed(bytes.begin(), bytes.end());
    const std::size_t num_arrays = element_sizes.size();
    if (bytes.size() < header_bytes + 8 || header_bytes < 8 * num_arrays) return fixed;
    std::vector<std::uint64_t> sizes(num_arrays);
    std::uint64_t total = header_bytes + 8;
    for (std::size_t a = 0; a < num_arrays; ++a) {
        std::uint64_t count;
        std::memcpy(&count, bytes.data() + header_bytes - 8 * (num_arrays - a), 8);
        if (count > bytes.size()) return fixed;
        sizes[a] = count * element_sizes[a];
        total += sizes[a];
    }
    if (total != bytes.size()) return fixed;
    std::uint64_t checksum = hash64(bytes.first(header_bytes));
    std::size_t at = header_bytes;
    for (const std::uint64_t size : sizes) {
        checksum = hash64(bytes.subspan(at, size), checksum);
        at += size;
    }
    std::memcpy(fixed.data() + at, &checksum, 8);
    return fixed;
}

void check_core_arrays(const std::filesystem::path& path, const GraphPlanCore& a, const CoreOffsets& at,
                       std::int64_t num_points, std::int64_t num_simplices) {
    const auto num_boundary = static_cast<std::int64_t>(a.boundary_nodes.size());
    check_range(path, at.boundary_nodes_at, "a boundary node id", a.boundary_nodes, 0, num_points);
    for (std::size_t b = 0; b < a.boundary_moving.size(); ++b)
        if (a.boundary_moving[b] > 1)
            fail(path, at.boundary_moving_at + b, "a moving flag 0 or 1", std::to_string(a.boundary_moving[b]));
    check_range(path, at.shared_members_at, "a boundary index", a.shared_members, 0, num_boundary);
    check_range(path, at.node_simplex_at, "a simplex id or boundary index", a.node_simplex, -num_boundary, num_simplices);
    // Boundary nodes sorted, and node_simplex marks exactly them (deform counts
    // volume nodes from this), shared groups well formed.
    for (std::size_t b = 0; b < a.boundary_nodes.size(); ++b) {
        if (b > 0 && a.boundary_nodes[b] <= a.boundary_nodes[b - 1])
            fail(path, at.boundary_nodes_at + 4 * b, "sorted boundary node ids", std::to_string(a.boundary_nodes[b]));
        const auto node = static_cast<std::size_t>(a.boundary_nodes[b]);
        if (a.node_simplex[node] != -1 - static_cast<std::int32_t>(b))
            fail(path, at.node_simplex_at + 4 * node,
                 "boundary index " + std::to_string(b) + " encoded as " + std::to_string(-1 - static_cast<std::int64_t>(b)),
                 std::to_string(a.node_simplex[node]));
    }
    if (std::count_if(a.node_simplex.begin(), a.node_simplex.end(), [](std::int32_t s) { return s < 0; }) !=
        num_boundary)
        fail(path, at.node_simplex_at, std::to_string(num_boundary) + " boundary entries in node_simplex", "another count");
    const auto num_shared = static_cast<std::int32_t>(a.shared_members.size());
    const auto& so = a.shared_offsets;
    for (std::size_t g = 0; g < so.size(); ++g)
        if ((g == 0 && so[0] != 0) || (g > 0 && so[g] < so[g - 1]) || (g + 1 == so.size() && so[g] != num_shared))
            fail(path, at.shared_offsets_at + 4 * g,
                 "nondecreasing shared-vertex offsets from 0 to " + std::to_string(num_shared), std::to_string(so[g]));
}

}  // namespace dgwarp::plan_detail
