#pragma once
// Internal to the plan files (plan_file.cpp, dg_harmonic_plan_file.cpp): the
// layout every plan file shares (magic, a fixed header ending with the element
// counts of the arrays, the arrays, a chained XXH64 checksum), written and read
// by the same code whatever the method.
#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "dgwarp/core/atomic_write.hpp"
#include "dgwarp/core/error.hpp"
#include "dgwarp/core/hash.hpp"
#include "dgwarp/methods/dg_harmonic.hpp"
#include "dgwarp/methods/plan_core.hpp"

namespace dgwarp::plan_detail {

/// Where a plan is read from: a file or bytes in memory. `read` copies n bytes
/// at `offset` (always the next unread byte) or throws IoError.
struct PlanSource {
    std::string name;
    std::uint64_t size = 0;
    std::function<void(void* to, std::size_t n, std::uint64_t offset)> read;
};

/// The source over a file (read in order, straight into the arrays) or bytes.
PlanSource file_source(const std::filesystem::path& path, std::ifstream& in);
PlanSource bytes_source(std::span<const std::byte> bytes, const std::string& name);

[[noreturn]] void fail(const std::filesystem::path& path, std::uint64_t offset, const std::string& expected,
                       const std::string& found);

/// Every value in [lo, hi), else ParseError at the offending element's offset.
void check_range(const std::filesystem::path& path, std::uint64_t offset, const char* what,
                 std::span<const std::int32_t> values, std::int64_t lo, std::int64_t hi);

/// The 8-byte magic of a file, or zeros when it is shorter.
std::array<char, 8> peek_magic(const PlanSource& source);

/// Serialises fields in order into `bytes` at `at` (or, reading, from it).
template <class T>
void put(std::vector<std::byte>& bytes, const T& v) {
    const auto* p = reinterpret_cast<const std::byte*>(&v);
    bytes.insert(bytes.end(), p, p + sizeof v);
}
template <class T>
void get(std::span<const std::byte> bytes, std::size_t& at, T& v) {
    std::memcpy(&v, bytes.data() + at, sizeof v);
    at += sizeof v;
}

/// Writes `header` (magic and fields, ending with the arrays' element counts),
/// the arrays visit_arrays(f) passes to f, and the checksum to `out`.
template <class VisitArrays>
void write_plan_stream(std::ostream& out, std::span<const std::byte> header, VisitArrays&& visit_arrays) {
    out.write(reinterpret_cast<const char*>(header.data()), static_cast<std::streamsize>(header.size()));
    std::uint64_t checksum = hash64(header);
    visit_arrays([&](const auto& v) {
        const auto bytes = std::as_bytes(std::span(v));
        out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
        checksum = hash64(bytes, checksum);
    });
    out.write(reinterpret_cast<const char*>(&checksum), sizeof checksum);
}

/// Reads the arrays after a header of `header.size()` bytes whose last
/// counts.size() × 8 bytes are the element counts: checks every count
/// against the file size before allocating, the file's total size, then reads
/// each array (visit_arrays passes them in file order) and the checksum.
/// Returns the byte offset of each array.
template <class VisitArrays>
std::vector<std::uint64_t> read_plan_arrays(const PlanSource& source, std::span<const std::byte> header,
                                            std::span<const std::uint64_t> counts, VisitArrays&& visit_arrays) {
    const std::filesystem::path path = source.name;
    const std::uint64_t file_size = source.size, header_bytes = header.size();
    std::uint64_t expected = header_bytes + 8;  // header + checksum
    std::size_t a = 0;
    visit_arrays([&](const auto& v) {
        const std::uint64_t count = counts[a], element = sizeof(v[0]);
        if (count > file_size / element)
            fail(path, header_bytes - 8 * (counts.size() - a),
                 "an array length that fits in the file's " + std::to_string(file_size) + " bytes (truncated file?)",
                 std::to_string(count));
        expected += count * element;
        ++a;
    });
    if (expected != file_size)
        fail(path, std::min(expected, file_size), "a file of " + std::to_string(expected) + " bytes (from its header)",
             std::to_string(file_size) + " bytes (truncated or extended)");
    std::uint64_t checksum = hash64(header), offset = header_bytes;
    std::vector<std::uint64_t> offsets;
    a = 0;
    visit_arrays([&](auto& v) {
        v.resize(static_cast<std::size_t>(counts[a++]));
        const auto bytes = std::as_writable_bytes(std::span(v));
        source.read(bytes.data(), bytes.size(), offset);
        checksum = hash64(bytes, checksum);
        offsets.push_back(offset);
        offset += bytes.size();
    });
    std::uint64_t stored;
    source.read(&stored, sizeof stored, offset);
    if (stored != checksum) fail(path, offset, "checksum " + std::to_string(checksum), std::to_string(stored));
    return offsets;
}

/// `bytes` with its checksum recomputed, for a file whose header is
/// `header_bytes` long and ends with the counts of arrays of the given element
/// sizes; unchanged when the sizes do not add up.
std::vector<std::byte> with_recomputed_checksum(std::span<const std::byte> bytes, std::size_t header_bytes,
                                                std::span<const std::size_t> element_sizes);

/// The checks every plan's core (methods/plan_core.hpp) needs: boundary
/// nodes sorted and in [0, num_points), moving flags 0 or 1, node_simplex
/// marking exactly them (-1 - b for boundary index b), the rest in
/// [0, num_simplices), and the shared-vertex groups well formed (offsets
/// from 0 to members' size, members boundary indices). `CoreOffsets`: where
/// each array starts in the file, for the messages.
struct CoreOffsets {
    std::uint64_t boundary_nodes_at, boundary_moving_at, node_simplex_at, shared_offsets_at, shared_members_at;
};
void check_core_arrays(const std::filesystem::path& path, const GraphPlanCore& a, const CoreOffsets& at,
                       std::int64_t num_points, std::int64_t num_simplices);

/// DG-harmonic plan files (dg_harmonic_plan_file.cpp): their magic, writer,
/// loader and checksum fixer.
inline constexpr std::array<char, 8> dg_harmonic_magic{'D', 'G', 'W', 'H', 'A', 'R', 'M', '\0'};
void write_dg_harmonic(std::ostream& out, const DgHarmonicPlan& plan);
DgHarmonicPlan load_dg_harmonic(const PlanSource& source);
std::vector<std::byte> with_recomputed_dg_harmonic_checksum(std::span<const std::byte> bytes);

}  // namespace dgwarp::plan_detail
