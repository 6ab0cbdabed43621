// record_lines.hpp: the serial pass that finds a block's record lines.
#include "dgwarp/io/record_lines.hpp"

#include <algorithm>
#include <cstring>

#include "dgwarp/io/text_reader.hpp"

namespace dgwarp {

std::optional<RecordBlock> split_record_lines(const TextReader& r, std::int64_t count, SkippedLines skip,
                                              std::int64_t per_chunk) {
    const std::string_view content = r.content();
    RecordBlock block;
    std::size_t pos = r.position();
    std::size_t line_number = r.line_number();
    std::int64_t records = 0;
    RecordChunk chunk{pos, pos, 0, 0, line_number + 1};
    while (records < count) {
        if (pos >= content.size()) return std::nullopt;
        const void* found = std::memchr(content.data() + pos, '\n', content.size() - pos);
        const std::size_t nl = found ? static_cast<std::size_t>(static_cast<const char*>(found) - content.data())
                                     : content.size();
        ++line_number;
        std::string_view line = content.substr(pos, nl - pos);
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
        pos = nl + 1;
        if (skipped_line(line, skip)) continue;
        ++records;
        ++chunk.count;
        block.last_line = line_number;
        if (chunk.count == per_chunk || records == count) {
            chunk.end = std::min(pos, content.size());
            block.chunks.push_back(chunk);
            chunk = RecordChunk{chunk.end, chunk.end, records, 0, line_number + 1};
        }
    }
    block.end = std::min(pos, content.size());
    if (count == 0) block.last_line = r.line_number();
    return block;
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
