// record_lines.hpp: the pass that finds a block's record lines, and the joins of parsed parts.
#include "dgwarp/io/record_lines.hpp"

#include <algorithm>
#include <bit>
#include <cstring>
#include <limits>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "dgwarp/io/text_reader.hpp"

namespace dgwarp {

namespace {

/// What a scan of whole lines found.
struct LineScan {
    std::size_t lines = 0;         // lines passed (records and skipped ones)
    std::int64_t records = 0;      // record lines among them
    std::size_t after_record = 0;  // byte offset just past the last record line (and its '\n')
    std::size_t record_line = 0;   // lines passed up to and including the last record line
};

/// Whether the line [begin, end) (without its '\n') is a record line: one
/// that starts with a digit at once (nearly all), else as skipped_line says.
bool record_line(std::string_view content, std::size_t begin, std::size_t end, SkippedLines skip) {
    if (begin < end && static_cast<unsigned char>(content[begin] - '0') <= 9 && content[begin] != skip.comment)
        return true;
    std::string_view line = content.substr(begin, end - begin);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    return !skipped_line(line, skip);
}

/// Scans the lines from `begin` (a line start) to `end` (a line start, or
/// the content's end), stopping after `max_records` record lines. The line
/// ends are found 16 bytes at a time (SSE2) rather than by a search per line
/// (the 5.3M cells of the 865k-node sphere: 0.10 -> 0.075 s on 2 threads).
LineScan scan_lines(std::string_view content, std::size_t begin, std::size_t end, SkippedLines skip,
                    std::int64_t max_records) {
    LineScan s;
    s.after_record = begin;
    if (max_records <= 0) return s;
    std::size_t line_start = begin;
    // Counts the line ending at `nl`; true once the scan has its records.
    const auto line_ends_at = [&](std::size_t nl) {
        ++s.lines;
        if (record_line(content, line_start, nl, skip)) {
            ++s.records;
            s.after_record = std::min(nl + 1, content.size());
            s.record_line = s.lines;
        }
        line_start = nl + 1;
        return s.records >= max_records;
    };
    const char* data = content.data();
    std::size_t p = begin;
#if defined(__SSE2__)
    const __m128i newline = _mm_set1_epi8('\n');
    for (; p + 16 <= end; p += 16) {
        auto mask = static_cast<unsigned>(
            _mm_movemask_epi8(_mm_cmpeq_epi8(_mm_loadu_si128(reinterpret_cast<const __m128i*>(data + p)), newline)));
        for (; mask != 0; mask &= mask - 1)
            if (line_ends_at(p + static_cast<std::size_t>(std::countr_zero(mask)))) return s;
    }
#endif
    for (; p < end; ++p)
        if (data[p] == '\n' && line_ends_at(p)) return s;
    if (line_start < end) line_ends_at(end);  // the content's last line, without a '\n'
    return s;
}

/// One chunk of `per_chunk` records after another, on this thread.
std::optional<RecordBlock> split_serially(std::string_view content, std::size_t pos, std::size_t line_number,
                                          std::int64_t count, SkippedLines skip, std::int64_t per_chunk) {
    RecordBlock block;
    block.end = pos;
    block.last_line = line_number;
    for (std::int64_t records = 0; records < count;) {
        const std::int64_t wanted = std::min(per_chunk, count - records);
        const LineScan s = scan_lines(content, pos, content.size(), skip, wanted);
        if (s.records < wanted) return std::nullopt;
        block.chunks.push_back({pos, s.after_record, records, s.records, line_number + 1});
        records += s.records;
        line_number += s.record_line;
        pos = s.after_record;
        block.end = pos;
        block.last_line = line_number;
    }
    return block;
}

}  // namespace

// Large blocks are cut in byte ranges of whole lines, scanned on the threads
// a wave at a time (their lines and records counted), and the counts summed
// in order: a chunk per range, of about per_chunk records (the 5.3M cells of
// the 865k-node sphere: 0.19 s on one thread). The wave that holds the
// block's last record is scanned past it by at most a wave of ranges.
std::optional<RecordBlock> split_record_lines(const TextReader& r, std::int64_t count, SkippedLines skip,
                                              std::int64_t per_chunk) {
    const std::string_view content = r.content();
    const std::size_t start = r.position();
    std::size_t lines = r.line_number();
    per_chunk = std::max<std::int64_t>(per_chunk, 1);
    // Bytes per record, from the first lines.
    const LineScan sample = scan_lines(content, start, content.size(), skip, std::min<std::int64_t>(count, 64));
    const double record_bytes =
        sample.records > 0 ? static_cast<double>(sample.after_record - start) / static_cast<double>(sample.records) : 0;
    const int threads = num_threads();
    if (threads == 1 || count <= 2 * per_chunk || record_bytes * static_cast<double>(count) < (1 << 20))
        return split_serially(content, start, lines, count, skip, per_chunk);
    const auto range = std::max<std::size_t>(4096, static_cast<std::size_t>(record_bytes * static_cast<double>(per_chunk)));
    const std::size_t wave = 8 * static_cast<std::size_t>(threads);
    std::vector<std::size_t> starts(wave + 1);
    std::vector<LineScan> scans(wave);
    RecordBlock block;
    std::int64_t records = 0;
    for (std::size_t at = start; at < content.size(); at = starts[wave]) {
        // Range k: the lines that start in [at + k * range, at + (k + 1) * range).
        starts[0] = at;
        for (std::size_t k = 1; k <= wave; ++k) {
            const std::size_t nominal = at + k * range;
            std::size_t s = content.size();
            if (nominal < content.size()) {
                const void* found = std::memchr(content.data() + nominal - 1, '\n', content.size() - (nominal - 1));
                if (found) s = static_cast<std::size_t>(static_cast<const char*>(found) - content.data()) + 1;
            }
            starts[k] = std::max(s, starts[k - 1]);
        }
        parallel_for(
            static_cast<std::int64_t>(wave),
            [&](std::int64_t k) {
                scans[k] = scan_lines(content, starts[k], starts[k + 1], skip, std::numeric_limits<std::int64_t>::max());
            },
            1);
        for (std::size_t k = 0; k < wave; ++k) {
            LineScan s = scans[k];
            const bool last = records + s.records >= count;
            if (last) s = scan_lines(content, starts[k], starts[k + 1], skip, count - records);
            if (s.records > 0) block.chunks.push_back({starts[k], s.after_record, records, s.records, lines + 1});
            if (last) {
                block.end = s.after_record;
                block.last_line = lines + s.record_line;
                return block;
            }
            records += s.records;
            lines += s.lines;
        }
    }
    return std::nullopt;
}

ElementListSizes sizes_of(const ElementList& list) {
    return {list.size(), list.nodes.size(), list.face_first.size(), list.face_offsets.size(), list.face_nodes.size()};
}

void restore_sizes(ElementList& list, const ElementListSizes& sizes) {
    list.types.resize(sizes.cells);
    list.offsets.resize(sizes.cells + 1);
    list.nodes.resize(sizes.nodes);
    list.face_first.resize(sizes.face_first);
    list.face_offsets.resize(sizes.face_offsets);
    list.face_nodes.resize(sizes.face_nodes);
}

void reserve_like(ElementList& out, std::size_t more, std::span<const ElementList> sample) {
    std::size_t cells = 0, nodes = 0;
    for (const ElementList& p : sample) {
        cells += p.size();
        nodes += p.nodes.size();
    }
    out.types.reserve(out.size() + more);
    out.offsets.reserve(out.size() + more + 1);
    if (cells > 0) out.nodes.reserve(out.nodes.size() + (more * nodes + cells - 1) / cells);
}

std::size_t element_wave_chunks() { return std::max<std::size_t>(32, 4 * static_cast<std::size_t>(num_threads())); }

void append_element_parts(ElementList& out, std::span<const ElementList> parts) {
    // Where each part begins in the lists, then the copies.
    const std::size_t n = parts.size();
    std::vector<std::size_t> cell_at(n + 1, out.size()), node_at(n + 1, out.nodes.size());
    for (std::size_t c = 0; c < n; ++c) {
        cell_at[c + 1] = cell_at[c] + parts[c].size();
        node_at[c + 1] = node_at[c] + parts[c].nodes.size();
    }
    out.types.resize(cell_at[n]);
    out.offsets.resize(cell_at[n] + 1);
    out.nodes.resize(node_at[n]);
    parallel_for(
        static_cast<std::int64_t>(n),
        [&](std::int64_t ci) {
            const auto c = static_cast<std::size_t>(ci);
            const ElementList& p = parts[c];
            std::copy(p.types.begin(), p.types.end(), out.types.begin() + static_cast<std::ptrdiff_t>(cell_at[c]));
            std::copy(p.nodes.begin(), p.nodes.end(), out.nodes.begin() + static_cast<std::ptrdiff_t>(node_at[c]));
            const auto base = static_cast<std::int64_t>(node_at[c]);
            for (std::size_t i = 1; i < p.offsets.size(); ++i) out.offsets[cell_at[c] + i] = base + p.offsets[i];
        },
        1);
    // Polyhedra's faces (rare: one pass on this thread), where any list has them.
    const bool faces = out.has_faces() ||
                       std::any_of(parts.begin(), parts.end(), [](const ElementList& p) { return p.has_faces(); });
    if (!faces) return;
    if (out.face_first.empty()) out.face_first.assign(cell_at[0] + 1, 0);
    for (const ElementList& p : parts) {
        const auto face_base = static_cast<std::int64_t>(out.face_offsets.size()) - 1;
        const auto node_base = static_cast<std::int64_t>(out.face_nodes.size());
        if (!p.has_faces()) {
            out.face_first.insert(out.face_first.end(), p.size(), face_base);
            continue;
        }
        for (std::size_t i = 1; i < p.face_first.size(); ++i) out.face_first.push_back(face_base + p.face_first[i]);
        for (std::size_t f = 1; f < p.face_offsets.size(); ++f) out.face_offsets.push_back(node_base + p.face_offsets[f]);
        out.face_nodes.insert(out.face_nodes.end(), p.face_nodes.begin(), p.face_nodes.end());
    }
}

}  // namespace dgwarp
