// record_lines.hpp: the serial pass that finds a block's record lines.
#include "dgwarp/io/record_lines.hpp"

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

}  // namespace dgwarp
