// Reader of SU2 native ASCII meshes (https://su2code.github.io/docs_v7/Mesh-File/).
//
// A zone is the four sections NDIME=, NELEM=, NPOIN=, NMARK= (NDIME first, the
// others in any order); reading stops once all four are read, so FFD boxes,
// periodic data and later zones are never parsed. Unknown keyword sections
// met before that are skipped. Every count is checked against the rest of the file
// before anything is reserved (a record of k tokens takes at least 2k bytes), so
// a damaged header cannot make us allocate more than a few times the file size.
#include <algorithm>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <string_view>

#include "dgwarp/core/error.hpp"
#include "dgwarp/core/parallel_for.hpp"
#include "dgwarp/io/record_lines.hpp"
#include "dgwarp/io/su2/su2.hpp"
#include "dgwarp/io/text_reader.hpp"

namespace dgwarp {

namespace {

// Node ids must fit NodeId, and so must their count.
constexpr std::int64_t max_node_count = std::numeric_limits<NodeId>::max();

struct Keyword {
    std::string_view key;    // e.g. "NELEM"
    std::string_view value;  // trimmed text after '='
};

bool is_key_char(char c) {
    return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_';
}

/// `KEY= value` (blanks around '=' optional), or nullopt for a data line.
std::optional<Keyword> parse_keyword(std::string_view line) {
    const std::string_view t = trim(line);
    const std::size_t eq = t.find('=');
    if (eq == std::string_view::npos) return std::nullopt;
    const std::string_view key = trim(t.substr(0, eq));
    if (key.empty()) return std::nullopt;
    for (char c : key)
        if (!is_key_char(c)) return std::nullopt;
    return Keyword{key, trim(t.substr(eq + 1))};
}

/// Advances to the next line that is neither blank nor a '%' comment.
bool next_content_line(TextReader& r) {
    while (r.next_line()) {
        const std::string_view t = trim(r.line());
        if (!t.empty() && t.front() != '%') return true;
    }
    return false;
}

std::string_view first_word(std::string_view s) {
    std::size_t end = 0;
    while (end < s.size() && s[end] != ' ' && s[end] != '\t') ++end;
    return s.substr(0, end);
}

std::string str(std::int64_t v) { return std::to_string(v); }

/// Parses the count after `KEY=` (a second number, as in `NPOIN= 5233 5233`,
/// is ignored). A count above what the file could hold is rejected: a record of
/// `record_tokens` tokens takes at least 2 × record_tokens bytes after the
/// current line, so n records need n ≤ remaining / (2 × record_tokens) + 1.
std::int64_t parse_count(const TextReader& r, const Keyword& kw, std::string_view what,
                         int record_tokens, std::int64_t min_count = 0) {
    const std::string_view token = first_word(kw.value);
    std::int64_t n = 0;
    if (!parse_int(token, n) || n < min_count)
        r.fail((min_count == 0 ? "a non-negative " : "a positive ") + std::string(what) + " after " +
                   std::string(kw.key) + "=",
               token.empty() ? std::string_view("nothing") : token);
    const std::size_t bytes = r.remaining_bytes();
    const auto most = static_cast<std::int64_t>(bytes / (2 * static_cast<std::size_t>(record_tokens)) + 1);
    if (n > most)
        r.fail(std::string(what) + " that the rest of the file can hold (at most " + str(most) + " in its " +
                   str(static_cast<std::int64_t>(bytes)) + " bytes)",
               token);
    return n;
}

int parse_dimension(const TextReader& r, const Keyword& kw) {
    const std::string_view token = first_word(kw.value);
    std::int64_t d = 0;
    if (!parse_int(token, d) || (d != 2 && d != 3))
        r.fail("dimension 2 or 3 after NDIME=", token.empty() ? std::string_view("nothing") : token);
    return static_cast<int>(d);
}

/// Where a block of records was announced, to name a record in errors.
struct Block {
    std::string_view record;   // "element", "point", "boundary element"
    std::string_view keyword;  // "NELEM", "NPOIN", "MARKER_ELEMS"
    std::size_t line = 0;      // line of the keyword
    std::int64_t count = 0;
    std::string_view marker;   // marker name for boundary elements
};

/// "element 3 of the 10 announced by NELEM= on line 2".
std::string record_name(const Block& b, std::int64_t i) {
    return std::string(b.record) + " " + str(i + 1) + " of the " + str(b.count) + " announced by " +
           std::string(b.keyword) + "= on line " + str(static_cast<std::int64_t>(b.line)) +
           (b.marker.empty() ? std::string() : " (marker '" + std::string(b.marker) + "')");
}

/// "the 10 elements announced by NELEM= on line 2".
std::string block_summary(const Block& b) {
    return "the " + str(b.count) + " " + std::string(b.record) + "s announced by " + std::string(b.keyword) +
           "= on line " + str(static_cast<std::int64_t>(b.line));
}

/// Throws ParseError at the current line: `what` in record i of block b.
[[noreturn]] void fail_in(const TextReader& r, const Block& b, std::int64_t i, const std::string& what,
                          std::string_view found) {
    r.fail(what + " in " + record_name(b, i), found);
}

/// Moves to record i of block b; at the end of the file the error names the
/// missing record and its block.
void require_record(TextReader& r, const Block& b, std::int64_t i) {
    if (!next_content_line(r)) r.fail(record_name(b, i), "end of file");
}

/// A record's token is missing or malformed. When it is the record's first
/// token and the line is a keyword line, the record itself is missing (the
/// block's count is larger than its records): say so instead.
[[noreturn]] void fail_record_token(const TextReader& r, const Block& b, std::int64_t i, const std::string& what,
                                    std::string_view token, bool first_token) {
    if (token.empty()) fail_in(r, b, i, what, "end of line");
    if (first_token && parse_keyword(r.line())) r.fail(record_name(b, i), trim(r.line()));
    fail_in(r, b, i, what, token);
}

/// The element types allowed in a block, as "5 triangle, 9 quadrilateral".
std::string type_list(bool (*allowed)(CellType, int), int dim) {
    std::string s;
    for (CellType t : all_cell_types)
        if (allowed(t, dim))
            s += (s.empty() ? "" : ", ") + str(vtk_cell_id(t)) + " " + std::string(cell_type_name(t));
    return s;
}

// SU2 has no polygons or polyhedra.
bool allowed_cell(CellType t, int dim) { return cell_dimension(t) == dim && !has_any_node_count(t); }
bool allowed_boundary(CellType t, int dim) {
    return (cell_dimension(t) == dim - 1 && !has_any_node_count(t)) || (dim == 2 && t == CellType::vertex);
}
bool su2_type(CellType t, int) { return !has_any_node_count(t); }

/// The largest node id met so far and its line: checked against NPOIN once the
/// zone is read, since NPOIN may come after the elements.
struct NodeIdRange {
    std::int64_t max = -1;
    std::size_t line = 0;
};

/// Reads record i of block b: a type id allowed for a cell (or, when
/// `boundary`, a boundary element) of a `dim`-dimensional mesh, then its node
/// ids; appends it to `out`.
void read_element(TextReader& r, const Block& b, std::int64_t i, int dim, bool boundary, ElementList& out,
                  NodeIdRange& range) {
    require_record(r, b, i);
    const std::string_view type_token = r.next_token();
    std::int64_t id = 0;
    if (!parse_int(type_token, id)) fail_record_token(r, b, i, "an integer element type id", type_token, true);
    const std::optional<CellType> type =
        (id >= 0 && id <= 255) ? cell_type_from_vtk_id(static_cast<int>(id)) : std::nullopt;
    const auto allowed = boundary ? allowed_boundary : allowed_cell;
    if (!type || !su2_type(*type, dim))
        fail_in(r, b, i, "a known element type id (" + type_list(su2_type, dim) + ")", type_token);
    if (!allowed(*type, dim))
        fail_in(r, b, i,
                std::string(boundary ? "a boundary element" : "a cell") + " of a " + str(dim) + "D mesh (" +
                    type_list(allowed, dim) + ")",
                std::string(type_token) + " (" + std::string(cell_type_name(*type)) + ")");
    const int n = nodes_per_cell(*type);
    NodeId nodes[8];
    for (int k = 0; k < n; ++k) {
        const std::string_view token = r.next_token();
        std::int64_t v = 0;
        if (!parse_int(token, v))
            fail_record_token(r, b, i,
                              "node " + str(k + 1) + " of the " + std::string(cell_type_name(*type)) +
                                  " (an integer node id)",
                              token, false);
        if (v < 0) fail_in(r, b, i, "a node id >= 0", token);
        if (v >= max_node_count) fail_in(r, b, i, "a node id below " + str(max_node_count), token);
        if (v > range.max) range = {v, r.line_number()};
        nodes[k] = static_cast<NodeId>(v);
    }
    // Further columns (SU2's element index) are ignored.
    out.push_back(*type, {nodes, static_cast<std::size_t>(n)});
}

// The fast path of a block (record_lines.hpp): its chunks on several
// threads, accepting only what read_element and read_points accept; false
// sends the block back to the line-by-line code, which names the error.
constexpr SkippedLines su2_skipped{'%'};

/// parse_element_line for the usual record: tokens of 1-18 plain digits,
/// each read as its characters are scanned (not found, then parsed); false,
/// with nothing pushed, at anything else (the token path then reads the line).
bool parse_plain_element_line(std::string_view line, int dim, bool boundary, ElementList& out,
                              std::int64_t& max_id) {
    const char* p = line.data();
    const char* const end = p + line.size();
    const auto next = [&](std::int64_t& value) {
        while (p < end && LineTokens::blank(*p)) ++p;
        const char* const start = p;
        p = scan_plain_digits(p, end, value);
        return p != start && (p == end || LineTokens::blank(*p));  // a 19th digit is no blank
    };
    std::int64_t id = 0;
    if (!next(id) || id > 255) return false;
    const std::optional<CellType> type = cell_type_from_vtk_id(static_cast<int>(id));
    if (!type || !(boundary ? allowed_boundary : allowed_cell)(*type, dim)) return false;
    const int n = nodes_per_cell(*type);
    NodeId nodes[8];
    std::int64_t largest = max_id;
    for (int k = 0; k < n; ++k) {
        std::int64_t v = 0;
        if (!next(v) || v >= max_node_count) return false;
        largest = std::max(largest, v);
        nodes[k] = static_cast<NodeId>(v);
    }
    out.push_back(*type, {nodes, static_cast<std::size_t>(n)});
    max_id = largest;
    return true;
}

/// An SU2 element record: its type (allowed in the block) and node ids
/// (each in [0, max_node_count)); further columns are ignored.
bool parse_element_line(std::string_view line, int dim, bool boundary, ElementList& out, std::int64_t& max_id) {
    if (parse_plain_element_line(line, dim, boundary, out, max_id)) return true;
    LineTokens tokens(line);
    const auto int_token = [](std::string_view token, std::int64_t& v) {
        return parse_plain_digits(token, v) || parse_int(token, v);
    };
    std::int64_t id = 0;
    if (!int_token(tokens.next(), id) || id < 0 || id > 255) return false;
    const std::optional<CellType> type = cell_type_from_vtk_id(static_cast<int>(id));
    if (!type || !(boundary ? allowed_boundary : allowed_cell)(*type, dim)) return false;
    const int n = nodes_per_cell(*type);
    NodeId nodes[8];
    for (int k = 0; k < n; ++k) {
        std::int64_t v = 0;
        if (!int_token(tokens.next(), v) || v < 0 || v >= max_node_count) return false;
        max_id = std::max(max_id, v);
        nodes[k] = static_cast<NodeId>(v);
    }
    out.push_back(*type, {nodes, static_cast<std::size_t>(n)});
    return true;
}

/// The block of `count` element records after the current line, on several
/// threads; false (the reader where it was) when anything is not a valid record.
bool read_elements_fast(TextReader& r, std::int64_t count, int dim, bool boundary, int min_nodes, ElementList& out,
                        NodeIdRange& range) {
    const std::optional<RecordBlock> block = split_record_lines(r, count, su2_skipped);
    if (!block) return false;
    std::vector<NodeIdRange> ranges(block->chunks.size());
    const bool ok = parse_element_chunks(r, *block, out, [&](std::size_t c, ElementList& part) {
        const RecordChunk& chunk = block->chunks[c];
        NodeIdRange& rg = ranges[c];
        part.reserve(static_cast<std::size_t>(chunk.count), min_nodes);
        return for_each_record_line(r.content(), chunk, su2_skipped,
                                    [&](std::string_view line, std::int64_t, std::size_t line_number) {
                                        std::int64_t max_id = -1;
                                        if (!parse_element_line(line, dim, boundary, part, max_id)) return false;
                                        if (max_id > rg.max) rg = {max_id, line_number};
                                        return true;
                                    });
    });
    if (!ok) return false;
    // The first line holding the largest id, as the line-by-line code keeps it.
    for (const NodeIdRange& rg : ranges)
        if (rg.max > range.max) range = rg;
    r.seek(block->end, block->last_line);
    return true;
}

/// The block of `count` points after the current line, on several threads;
/// false (the reader where it was) when anything is not a valid record.
bool read_points_fast(TextReader& r, std::int64_t count, int dim, std::vector<double>& points) {
    const std::optional<RecordBlock> block = split_record_lines(r, count, su2_skipped);
    if (!block) return false;
    const std::size_t first = points.size();
    points.resize(first + static_cast<std::size_t>(count) * static_cast<std::size_t>(dim));
    const bool ok = parse_record_chunks(r, *block, [&](std::size_t c) {
        return for_each_record_line(r.content(), block->chunks[c], su2_skipped,
                                    [&](std::string_view line, std::int64_t record, std::size_t) {
                                        LineTokens tokens(line);
                                        double* x = points.data() + first +
                                                    static_cast<std::size_t>(record) * static_cast<std::size_t>(dim);
                                        for (int d = 0; d < dim; ++d)
                                            if (!parse_double(tokens.next(), x[d])) return false;
                                        return true;
                                    });
    });
    if (!ok) {
        points.resize(first);
        return false;
    }
    r.seek(block->end, block->last_line);
    return true;
}

/// NELEM= block of volume cells. The current line is the NELEM= line.
/// Returns a description of the block for errors about what follows it.
std::string read_cells(TextReader& r, const Keyword& kw, int dim, ElementList& cells, NodeIdRange& range) {
    const int min_nodes = dim == 2 ? 3 : 4;
    const Block block = {"element", "NELEM", r.line_number(), parse_count(r, kw, "element count", 1 + min_nodes, 1), {}};
    if (!read_elements_fast(r, block.count, dim, false, min_nodes, cells, range)) {
        cells.reserve(static_cast<std::size_t>(block.count), min_nodes);
        for (std::int64_t i = 0; i < block.count; ++i) read_element(r, block, i, dim, false, cells, range);
    }
    return block_summary(block);
}

/// NPOIN= block of `dim` coordinates per line. The current line is the NPOIN= line.
std::string read_points(TextReader& r, const Keyword& kw, int dim, std::vector<double>& points) {
    const Block block = {"point", "NPOIN", r.line_number(), parse_count(r, kw, "point count", dim), {}};
    if (block.count > max_node_count) r.fail("at most " + str(max_node_count) + " points", first_word(kw.value));
    if (read_points_fast(r, block.count, dim, points)) return block_summary(block);
    points.reserve(static_cast<std::size_t>(block.count) * static_cast<std::size_t>(dim));
    for (std::int64_t i = 0; i < block.count; ++i) {
        require_record(r, block, i);
        for (int d = 0; d < dim; ++d) {
            const std::string_view token = r.next_token();
            double x = 0;
            if (!parse_double(token, x))
                fail_record_token(r, block, i, "coordinate " + str(d + 1) + " of " + str(dim) + " (a finite number)",
                                  token, d == 0);
            points.push_back(x);
        }
        // Further columns (SU2's point index, sometimes more) are ignored.
    }
    return block_summary(block);
}

/// Moves to the next content line and checks it is `KEY=`; `what` names it in errors.
Keyword require_keyword(TextReader& r, std::string_view key, const std::string& what) {
    if (!next_content_line(r)) r.fail(what, "end of file");
    const std::optional<Keyword> kw = parse_keyword(r.line());
    if (!kw || kw->key != key) r.fail(what, trim(r.line()));
    return *kw;
}

/// NMARK= block: MARKER_TAG= / MARKER_ELEMS= / elements, per marker. The
/// current line is the NMARK= line.
std::string read_markers(TextReader& r, const Keyword& kw, int dim, std::vector<Marker>& markers,
                         NodeIdRange& range) {
    const std::size_t nmark_line = r.line_number();
    const std::int64_t count = parse_count(r, kw, "marker count", 2);
    Block last;
    for (std::int64_t m = 0; m < count; ++m) {
        const Keyword tag = require_keyword(r, "MARKER_TAG",
                                           "MARKER_TAG= of marker " + str(m + 1) + " of the " + str(count) +
                                               " announced by NMARK= on line " +
                                               str(static_cast<std::int64_t>(nmark_line)));
        if (tag.value.empty()) r.fail("a marker name after MARKER_TAG=");
        for (const Marker& other : markers)
            if (other.name == tag.value) r.fail("a marker name not used before in this zone", tag.value);
        Marker& marker = markers.emplace_back(Marker{std::string(tag.value), {}});
        const Keyword elems =
            require_keyword(r, "MARKER_ELEMS", "MARKER_ELEMS= after MARKER_TAG= " + marker.name);
        const int min_nodes = dim == 2 ? 1 : 3;
        last = {"boundary element", "MARKER_ELEMS", r.line_number(),
                parse_count(r, elems, "boundary element count", 1 + min_nodes), marker.name};
        if (read_elements_fast(r, last.count, dim, true, min_nodes, marker.elements, range)) continue;
        marker.elements.reserve(static_cast<std::size_t>(last.count), min_nodes);
        for (std::int64_t i = 0; i < last.count; ++i)
            read_element(r, last, i, dim, true, marker.elements, range);
    }
    const std::string nmark = "NMARK= on line " + str(static_cast<std::int64_t>(nmark_line));
    if (count == 0) return nmark + " (no markers)";
    return block_summary(last) + " (marker '" + markers.back().name + "', the last of the " + str(count) +
           " markers announced by " + nmark + ")";
}

/// Where the requested zone's sections begin, and what the file said before.
struct ZoneStart {
    int dim = 0;                // from an NDIME= before the zone's own sections (0: none)
    std::size_t dim_line = 0;
    std::size_t dim_offset = 0;  // byte offset of that NDIME= line
    bool dim_in_zone = false;   // that NDIME= belongs to the zone (single-zone file)
    bool pending = false;       // the current line is the zone's first keyword, still to handle
};

/// Reads the file header and, for a multi-zone file (NZONE=), skips to `IZONE= zone`.
ZoneStart locate_zone(TextReader& r, int zone) {
    ZoneStart z;
    while (true) {
        if (!next_content_line(r))
            r.fail(z.dim ? "the NELEM=, NPOIN= and NMARK= sections" : "the NDIME=, NELEM=, NPOIN= and NMARK= sections",
                   "end of file");
        const std::optional<Keyword> kw = parse_keyword(r.line());
        if (!kw) r.fail("a keyword line such as NDIME=", trim(r.line()));
        if (kw->key == "NDIME" && !z.dim) {
            z.dim = parse_dimension(r, *kw);
            z.dim_line = r.line_number();
            z.dim_offset = r.line_offset();
            continue;
        }
        if (kw->key == "IZONE") r.fail("NZONE= before IZONE=", trim(r.line()));
        if (kw->key != "NZONE") {
            if (zone != 1)
                throw ParseError(r.file(), 0, "zone 1: the file has a single zone (no NZONE=)",
                                 "requested zone " + str(zone));
            z.dim_in_zone = z.dim != 0;
            z.pending = true;
            return z;
        }
        const std::size_t nzone_line = r.line_number();
        const std::int64_t nzone = parse_count(r, *kw, "zone count", 2, 1);
        if (zone > nzone)
            throw ParseError(r.file(), nzone_line,
                             "a zone from 1 to " + str(nzone) + " (the file has " + str(nzone) + " zones)",
                             "requested zone " + str(zone));
        while (next_content_line(r)) {
            const std::optional<Keyword> izone = parse_keyword(r.line());
            if (!izone || izone->key != "IZONE") continue;
            std::int64_t k = 0;
            if (!parse_int(first_word(izone->value), k)) r.fail("a zone number after IZONE=", izone->value);
            if (k == zone) return z;
        }
        r.fail("IZONE= " + str(zone) + " (NZONE= on line " + str(static_cast<std::int64_t>(nzone_line)) +
                   " announces " + str(nzone) + " zones)",
               "end of file");
    }
}

/// Keyword lines of `text` that say what it holds (for Su2Surroundings::contents):
/// zones, FFD boxes, periodic data and unknown sections, not the zone sections'
/// own keywords nor the FFD and periodic sections' inner ones.
void describe_surroundings(std::string_view text, int zone, std::vector<std::string>& contents, std::int64_t& zones) {
    std::size_t at = 0;
    while (at < text.size()) {
        std::size_t end = text.find('\n', at);
        if (end == std::string_view::npos) end = text.size();
        const std::string_view line = trim(text.substr(at, end - at));
        at = end + 1;
        if (line.empty() || line.front() == '%') continue;
        const std::optional<Keyword> kw = parse_keyword(line);
        if (!kw) continue;
        const std::string_view key = kw->key;
        if (key == "IZONE") {
            std::int64_t k = 0;
            zones += !(parse_int(first_word(kw->value), k) && k == zone);  // another zone than the one read
            continue;
        }
        constexpr std::string_view zone_keys[] = {"NDIME", "NELEM", "NPOIN", "NMARK", "MARKER_TAG", "MARKER_ELEMS", "NZONE"};
        if (std::find(std::begin(zone_keys), std::end(zone_keys), key) != std::end(zone_keys)) continue;
        if ((key.starts_with("FFD_") && key != "FFD_NBOX") || key.starts_with("PERIODIC_")) continue;
        contents.push_back(std::string(key) + "= " + std::string(trim(kw->value)));
    }
}

/// Reads the sections of one zone; returns the checked mesh. With
/// `surroundings`, also the text around the zone's sections.
Mesh read_zone(TextReader& r, int zone, ZoneStart start, Su2Surroundings* surroundings) {
    Mesh mesh;
    mesh.dim = start.dim;
    std::size_t ndime_line = start.dim_in_zone ? start.dim_line : 0, nelem_line = 0, npoin_line = 0, nmark_line = 0;
    NodeIdRange range;
    std::string after;  // the block read last, to explain a stray data line after it
    bool pending = start.pending;
    std::size_t first_offset = start.dim_in_zone ? start.dim_offset : std::string::npos;

    auto missing = [&] {
        std::string s;
        const std::pair<std::size_t, const char*> sections[] = {
            {ndime_line, "NDIME="}, {nelem_line, "NELEM="}, {npoin_line, "NPOIN="}, {nmark_line, "NMARK="}};
        for (const auto& [line, name] : sections)
            if (!line && !(name == std::string_view("NDIME=") && mesh.dim)) s += (s.empty() ? "" : ", ") + std::string(name);
        return "the " + s + " section" + (s.find(',') == std::string::npos ? "" : "s");
    };

    while (!(nelem_line && npoin_line && nmark_line)) {
        if (!pending && !next_content_line(r)) r.fail(missing(), "end of file");
        pending = false;
        const std::optional<Keyword> kw = parse_keyword(r.line());
        if (!kw)
            r.fail(after.empty() ? "a keyword line such as NELEM=" : "a keyword line after " + after, trim(r.line()));
        const std::size_t line = r.line_number();
        if (first_offset == std::string::npos) first_offset = r.line_offset();
        auto first_time = [&](std::size_t seen_at) {
            if (seen_at)
                r.fail(missing() + " (" + std::string(kw->key) + "= already appeared on line " +
                           str(static_cast<std::int64_t>(seen_at)) + ")",
                       trim(r.line()));
            if (kw->key != "NDIME" && !mesh.dim) r.fail("NDIME= before " + std::string(kw->key) + "=", trim(r.line()));
        };
        if (kw->key == "NDIME") {
            first_time(ndime_line);
            mesh.dim = parse_dimension(r, *kw);
            ndime_line = line;
            after.clear();
        } else if (kw->key == "NELEM") {
            first_time(nelem_line);
            after = read_cells(r, *kw, mesh.dim, mesh.cells, range);
            nelem_line = line;
        } else if (kw->key == "NPOIN") {
            first_time(npoin_line);
            after = read_points(r, *kw, mesh.dim, mesh.points);
            npoin_line = line;
        } else if (kw->key == "NMARK") {
            first_time(nmark_line);
            after = read_markers(r, *kw, mesh.dim, mesh.markers, range);
            nmark_line = line;
        } else if (kw->key == "NZONE" || kw->key == "IZONE") {
            r.fail(missing() + " of zone " + str(zone), trim(r.line()));
        } else {
            // An unknown section: skip its data lines up to the next keyword.
            after.clear();
            while (next_content_line(r))
                if (parse_keyword(r.line())) {
                    pending = true;
                    break;
                }
        }
    }

    // The zone's sections end with the current line (the last block's last).
    const std::string_view content = r.content();
    const std::size_t newline = content.find('\n', r.line_offset());
    const std::size_t end_offset = newline == std::string_view::npos ? content.size() : newline + 1;

    // After the last block, only a keyword line may follow (FFD, periodic data,
    // the next zone): a data line or another marker means a count was too small.
    if (next_content_line(r)) {
        const std::optional<Keyword> kw = parse_keyword(r.line());
        if (!kw || kw->key == "MARKER_TAG" || kw->key == "MARKER_ELEMS")
            r.fail("a keyword line after " + after, trim(r.line()));
    }

    const auto num_points = static_cast<std::int64_t>(mesh.num_points());
    if (range.max >= num_points)
        throw ParseError(r.file(), range.line,
                         "node ids below " + str(num_points) + ", the number of points (NPOIN= on line " +
                             str(static_cast<std::int64_t>(npoin_line)) + ")",
                         str(range.max));
    validate(mesh);
    if (surroundings) {
        Su2Surroundings& s = *surroundings;
        s.before = std::string(content.substr(0, first_offset));
        s.after = std::string(content.substr(end_offset));
        s.zone_has_ndime = ndime_line != 0;
        s.num_points = num_points;
        s.num_cells = static_cast<std::int64_t>(mesh.cells.size());
        s.contents.clear();
        std::int64_t other_zones = 0;
        describe_surroundings(s.before, zone, s.contents, other_zones);
        describe_surroundings(s.after, zone, s.contents, other_zones);
        s.zones = other_zones + 1;
        if (other_zones > 0)
            s.contents.insert(s.contents.begin(), std::to_string(other_zones) + " other zone" +
                                                      (other_zones == 1 ? "" : "s") + " (IZONE=)");
    }
    return mesh;
}

/// Reads zone `zone` (1-based) of the SU2 text in `r`.
Mesh read_su2_zone(TextReader& r, int zone, Su2Surroundings* surroundings = nullptr) {
    if (zone < 1)
        throw ParseError(r.file(), 0, "a zone number >= 1 (zones are numbered from 1)", "requested zone " + str(zone));
    const ZoneStart start = locate_zone(r, zone);
    return read_zone(r, zone, start, surroundings);
}

}  // namespace

Mesh read_su2_text(const std::string& file_name, std::string content, int zone) {
    TextReader r(file_name, std::move(content));
    return read_su2_zone(r, zone);
}

Mesh read_su2(const std::filesystem::path& path, int zone, const ProgressFn& progress) {
    TextReader r = TextReader::open(path);
    r.set_progress(progress);
    Mesh mesh = read_su2_zone(r, zone);
    if (progress) progress(1.0);
    return mesh;
}

Mesh read_su2(const std::filesystem::path& path, int zone, const ProgressFn& progress, Su2Surroundings& surroundings) {
    TextReader r = TextReader::open(path);
    r.set_progress(progress);
    Mesh mesh = read_su2_zone(r, zone, &surroundings);
    if (progress) progress(1.0);
    return mesh;
}

}  // namespace dgwarp
