#include "dgwarp/io/node_table_read.hpp"

#include <algorithm>
#include <array>
#include <limits>
#include <numeric>
#include <string>
#include <string_view>
#include <vector>

#include "dgwarp/core/error.hpp"
#include "dgwarp/io/text_reader.hpp"

namespace dgwarp {

namespace {

constexpr std::size_t max_fields = 10;

/// The fields of a line: split on commas when it has one, else on blanks.
/// An empty field between two commas is kept (and later rejected).
std::vector<std::string_view> split_fields(std::string_view line) {
    std::vector<std::string_view> fields;
    if (line.find(',') != std::string_view::npos) {
        std::size_t start = 0;
        while (true) {
            const std::size_t comma = line.find(',', start);
            fields.push_back(trim(line.substr(start, comma - start)));
            if (comma == std::string_view::npos) break;
            start = comma + 1;
        }
        return fields;
    }
    std::size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
        const std::size_t start = i;
        while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '\r') ++i;
        if (i > start) fields.push_back(line.substr(start, i - start));
    }
    return fields;
}

std::string join_counts(const std::vector<std::size_t>& counts) {
    std::string s;
    for (std::size_t i = 0; i < counts.size(); ++i)
        s += (i == 0 ? "" : i + 1 == counts.size() ? " or " : ", ") + std::to_string(counts[i]);
    return s;
}

/// One data line: the node id and up to max_fields - 1 values.
struct Row {
    NodeId node = 0;
    std::array<double, max_fields - 1> values{};
};

/// Reads every data line of a node file. `field_counts` are the accepted
/// numbers of fields per line (node id included); `format` describes the line
/// form for messages. Calls add(row, field_count, line_number) per data line.
template <class Add>
void read_rows(TextReader& in, const std::vector<std::size_t>& field_counts, bool header_allowed,
               std::string_view format, Add add) {
    std::size_t fields_per_line = 0;  // set by the first data line
    bool first = true;
    while (in.next_line()) {
        const std::string_view line = trim(in.line());
        if (line.empty() || line.front() == '#' || line.front() == '%') continue;
        const auto fields = split_fields(line);
        std::int64_t id = 0;
        if (first && header_allowed && !fields.empty() && !parse_int(fields[0], id)) {
            first = false;  // a header line, e.g. "node,dx,dy"
            continue;
        }
        first = false;
        if (fields_per_line == 0) {
            if (std::find(field_counts.begin(), field_counts.end(), fields.size()) == field_counts.end())
                in.fail(join_counts(field_counts) + " fields (" + std::string(format) + ")",
                        std::to_string(fields.size()) + " fields: " + std::string(line));
            fields_per_line = fields.size();
        } else if (fields.size() != fields_per_line) {
            in.fail(std::to_string(fields_per_line) + " fields like the first data line",
                    std::to_string(fields.size()) + " fields: " + std::string(line));
        }
        if (!parse_int(fields[0], id) || id < 0 || id > std::numeric_limits<NodeId>::max())
            in.fail("a node id (an integer >= 0) in field 1", fields[0]);
        Row row;
        row.node = static_cast<NodeId>(id);
        for (std::size_t f = 1; f < fields.size(); ++f)
            if (!parse_double(fields[f], row.values[f - 1]))
                in.fail("a finite number in field " + std::to_string(f + 1), fields[f]);
        add(row, fields.size(), in.line_number());
    }
    if (fields_per_line == 0) in.fail("at least one data line (" + std::string(format) + ")", "end of file");
}

/// Drops repeated entries of a node with equal values; throws ParseError at
/// the second line when the values differ. Keeps the file order.
template <class Value>
void drop_duplicates(NodeTable<Value>& table) {
    std::vector<std::size_t> order(table.nodes.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return table.nodes[a] < table.nodes[b]; });
    std::vector<char> keep(order.size(), 1);
    for (std::size_t k = 1; k < order.size(); ++k) {
        const std::size_t first = order[k - 1], again = order[k];
        if (table.nodes[first] != table.nodes[again]) continue;
        if (!(table.values[first] == table.values[again]))
            throw ParseError(table.source, table.lines[again],
                             "node " + std::to_string(table.nodes[again]) + " once, or again with the same values as at line " +
                                 std::to_string(table.lines[first]),
                             "other values");
        keep[again] = 0;
        order[k] = first;  // compare a third repetition with the first
    }
    std::size_t out = 0;
    for (std::size_t i = 0; i < keep.size(); ++i) {
        if (!keep[i]) continue;
        table.nodes[out] = table.nodes[i];
        table.values[out] = table.values[i];
        table.lines[out] = table.lines[i];
        ++out;
    }
    table.nodes.resize(out);
    table.values.resize(out);
    table.lines.resize(out);
}

/// Reads a table of vectors (node + 2 or 3 numbers per line).
NodeTable<Vec3> read_vector_table(const std::filesystem::path& path, bool header_allowed,
                                  std::string_view format) {
    TextReader in = TextReader::open(path);
    NodeTable<Vec3> table;
    table.source = path.string();
    read_rows(in, {3, 4}, header_allowed, format, [&](const Row& row, std::size_t fields, std::size_t line) {
        table.components = static_cast<int>(fields) - 1;
        table.nodes.push_back(row.node);
        table.values.push_back({row.values[0], row.values[1], fields == 4 ? row.values[2] : 0.0});
        table.lines.push_back(line);
    });
    drop_duplicates(table);
    return table;
}

}  // namespace

NodeTable<Vec3> read_displacement_csv(const std::filesystem::path& path) {
    return read_vector_table(path, true, "node,dx,dy[,dz]");
}

NodeTable<Vec3> read_su2_surface_file(const std::filesystem::path& path) {
    return read_vector_table(path, false, "global_id x y [z]");
}

NodeTable<NodeMotion> read_node_motion_csv(const std::filesystem::path& path) {
    TextReader in = TextReader::open(path);
    NodeTable<NodeMotion> table;
    table.source = path.string();
    read_rows(in, {6, 10}, true, "node,tx,ty,tz,wx,wy,wz,cx,cy,cz or node,tx,ty,wz,cx,cy",
              [&](const Row& row, std::size_t fields, std::size_t line) {
                  const auto& v = row.values;
                  NodeMotion m;
                  if (fields == 10) {
                      m.translation = {v[0], v[1], v[2]};
                      m.rotation = {v[3], v[4], v[5]};
                      m.center = {v[6], v[7], v[8]};
                      table.components = 3;
                  } else {
                      m.translation = {v[0], v[1], 0};
                      m.rotation = {0, 0, v[2]};
                      m.center = {v[3], v[4], 0};
                      table.components = 2;
                  }
                  table.nodes.push_back(row.node);
                  table.values.push_back(m);
                  table.lines.push_back(line);
              });
    drop_duplicates(table);
    return table;
}

}  // namespace dgwarp
