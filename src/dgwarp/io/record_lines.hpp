#pragma once
// Blocks of records, one per line, parsed on several threads (issue #33): a
// pass finds the lines of the block (a search for '\n' per line; a large
// block's byte ranges on the threads) and cuts them into chunks; the chunks
// are then parsed in parallel by the format's reader. The fast path only
// ever accepts valid records: a reader that meets anything else in a chunk
// goes back (TextReader::seek) and reads the block with its line-by-line
// code, whose errors name the line, so error messages do not depend on this
// path.
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "dgwarp/core/parallel_for.hpp"
#include "dgwarp/io/text_reader.hpp"
#include "dgwarp/mesh/mesh.hpp"

namespace dgwarp {

/// A run of consecutive record lines of a block.
struct RecordChunk {
    std::size_t begin = 0;       // byte offset of its first line (a record or a skipped line)
    std::size_t end = 0;         // byte offset just past its last record line (and its '\n')
    std::int64_t first = 0;      // index in the block of its first record
    std::int64_t count = 0;      // records in it
    std::size_t first_line = 0;  // 1-based line number of the line at `begin`
};

struct RecordBlock {
    std::vector<RecordChunk> chunks;
    std::size_t end = 0;        // byte offset after the block's last record line
    std::size_t last_line = 0;  // line number of the block's last record line
};

/// Lines a record block passes over: blank ones, and with `comment` not 0
/// those whose first non-blank character is `comment` (SU2's '%').
struct SkippedLines {
    char comment = 0;
};

/// The `count` record lines that follow the reader's current line, in
/// chunks of `per_chunk` records (a block of a MB or more on several
/// threads: chunks of whole byte ranges, about `per_chunk` records each);
/// nullopt when the content ends first (the line-by-line code then says
/// which record is missing).
std::optional<RecordBlock> split_record_lines(const TextReader& r, std::int64_t count, SkippedLines skip,
                                              std::int64_t per_chunk = 1 << 12);

/// Appends the elements of `parts` (one list per chunk, in order) to `out`,
/// the copies on the threads; polyhedra with their faces.
void append_element_parts(ElementList& out, std::span<const ElementList> parts);

/// Calls parse(c) for every chunk index c of `block`, on several threads, in
/// waves that end where the reader's progress is next due (all at once
/// without a progress function), reporting it between waves as reading line
/// by line would. Returns false as soon as a wave had a parse(c) that did.
template <class F>
bool parse_record_chunks(TextReader& r, const RecordBlock& block, F&& parse);
/// As parse_record_chunks, in waves of at most `max_wave` chunks, with
/// after_wave(first, last) called on this thread after each wave of chunks
/// [first, last) parsed, and the content before the wave's end released
/// (TextReader::release_before: a mapped file is not held in memory beside
/// what it is parsed into).
template <class F, class G>
bool parse_record_waves(TextReader& r, const RecordBlock& block, std::size_t max_wave, F&& parse, G&& after_wave);
/// The element records of `block` appended to `out`: parse(c, part) fills
/// `part` (empty; its arrays keep their capacity from an earlier chunk) with
/// chunk c's elements and returns false at anything that is not a valid
/// record. On the threads, in waves of a few chunks per thread, each wave's
/// parts appended to `out` before the next (so the parts hold a wave's
/// elements, not the block's: 130 MB less for the 5.3M tetrahedra of the
/// 865k-node sphere, memory a virtual machine makes dear to touch). Returns
/// false, with `out` as it was, as soon as a parse did.
template <class F>
bool parse_element_chunks(TextReader& r, const RecordBlock& block, ElementList& out, F&& parse);

/// The sizes of a list's arrays, to put it back as it was (restore_sizes).
struct ElementListSizes {
    std::size_t cells = 0, nodes = 0, face_first = 0, face_offsets = 0, face_nodes = 0;
};
ElementListSizes sizes_of(const ElementList& list);
/// `list` cut back to `sizes` (taken from it before elements were appended).
void restore_sizes(ElementList& list, const ElementListSizes& sizes);
/// Reserves room in `out` for `more` elements like those of `sample` (its
/// nodes per element, on average), on top of what it holds.
void reserve_like(ElementList& out, std::size_t more, std::span<const ElementList> sample);
/// Chunks per wave of parse_element_chunks: a few per thread.
std::size_t element_wave_chunks();

/// Calls f(line, record, line_number) for every record line of `chunk`, the
/// line without its end-of-line characters; stops and returns false as soon
/// as f does.
template <class F>
bool for_each_record_line(std::string_view content, const RecordChunk& chunk, SkippedLines skip, F&& f);

/// The whitespace-separated tokens of a line (blanks: space, tab, CR, FF, VT).
class LineTokens {
public:
    explicit LineTokens(std::string_view line) : line_(line) {}
    /// The next token, empty at the end of the line.
    std::string_view next() {
        while (at_ < line_.size() && blank(line_[at_])) ++at_;
        const std::size_t start = at_;
        while (at_ < line_.size() && !blank(line_[at_])) ++at_;
        return line_.substr(start, at_ - start);
    }
    static bool blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }

private:
    std::string_view line_;
    std::size_t at_ = 0;
};

/// The decimal digits from `p` on (at most 18 of them, so no overflow), read
/// as they are scanned into `value`; returns where they end (`p` when there
/// are none, a digit when there are more than 18).
inline const char* scan_plain_digits(const char* p, const char* end, std::int64_t& value) {
    const char* const start = p;
    std::int64_t v = 0;
    for (; p < end && p - start < 18; ++p) {
        const auto d = static_cast<unsigned char>(*p - '0');
        if (d > 9) break;
        v = v * 10 + d;
    }
    value = v;
    return p;
}

/// A token of 1 to 18 decimal digits (the usual node id or type id), parsed
/// inline; false for anything else, which parse_int (text_reader.hpp) then
/// reads or refuses.
inline bool parse_plain_digits(std::string_view token, std::int64_t& value) {
    const char* const end = token.data() + token.size();
    std::int64_t v = 0;
    if (token.empty() || scan_plain_digits(token.data(), end, v) != end) return false;
    value = v;
    return true;
}

/// Whether `line` is one a record block passes over.
inline bool skipped_line(std::string_view line, SkippedLines skip) {
    for (char c : line)
        if (!LineTokens::blank(c)) return c == skip.comment && skip.comment != 0;
    return true;
}

template <class F>
bool parse_record_chunks(TextReader& r, const RecordBlock& block, F&& parse) {
    return parse_record_waves(r, block, block.chunks.size(), parse, [](std::size_t, std::size_t) {});
}

template <class F, class G>
bool parse_record_waves(TextReader& r, const RecordBlock& block, std::size_t max_wave, F&& parse, G&& after_wave) {
    const std::size_t chunks = block.chunks.size();
    std::vector<std::uint8_t> ok(chunks, 0);
    for (std::size_t first = 0; first < chunks;) {
        std::size_t last = first + 1;
        while (last < chunks && last - first < max_wave && block.chunks[last - 1].end < r.progress_due()) ++last;
        parallel_for(
            static_cast<std::int64_t>(last - first),
            [&](std::int64_t i) {
                const std::size_t c = first + static_cast<std::size_t>(i);
                ok[c] = parse(c) ? 1 : 0;
            },
            1);
        for (std::size_t c = first; c < last; ++c)
            if (!ok[c]) return false;
        after_wave(first, last);
        r.release_before(block.chunks[last - 1].end);
        r.report_progress_to(block.chunks[last - 1].end);
        first = last;
    }
    return true;
}

template <class F>
bool parse_element_chunks(TextReader& r, const RecordBlock& block, ElementList& out, F&& parse) {
    const ElementListSizes before = sizes_of(out);
    const std::size_t wave = element_wave_chunks();
    std::vector<ElementList> parts(std::min(wave, block.chunks.size()));
    std::size_t wave_first = 0;  // the chunk parts[0] holds
    std::size_t still = 0;       // elements of the block not yet appended
    for (const RecordChunk& chunk : block.chunks) still += static_cast<std::size_t>(chunk.count);
    const bool ok = parse_record_waves(
        r, block, wave,
        [&](std::size_t c) {
            ElementList& part = parts[c - wave_first];
            part.clear();
            return parse(c, part);
        },
        [&](std::size_t first, std::size_t last) {
            const std::span<const ElementList> done(parts.data(), last - first);
            if (first == 0) reserve_like(out, still, done);  // the block's room, from its first wave
            append_element_parts(out, done);
            for (const ElementList& p : done) still -= p.size();
            wave_first = last;
        });
    if (!ok) restore_sizes(out, before);
    return ok;
}

template <class F>
bool for_each_record_line(std::string_view content, const RecordChunk& chunk, SkippedLines skip, F&& f) {
    std::size_t pos = chunk.begin;
    std::size_t line_number = chunk.first_line;
    std::int64_t record = chunk.first;
    const std::int64_t last = chunk.first + chunk.count;
    while (record < last && pos < chunk.end) {
        std::size_t nl = content.find('\n', pos);
        if (nl == std::string_view::npos) nl = content.size();
        std::string_view line = content.substr(pos, nl - pos);
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
        if (!skipped_line(line, skip)) {
            if (!f(line, record, line_number)) return false;
            ++record;
        }
        pos = nl + 1;
        ++line_number;
    }
    return record == last;
}

}  // namespace dgwarp
