#include "dgwarp/io/openfoam/foam_file.hpp"

#include <algorithm>
#include <bit>
#include <cstring>

#include "dgwarp/core/error.hpp"
#include "dgwarp/io/record_lines.hpp"
#include "dgwarp/io/text_reader.hpp"

namespace dgwarp::foam {

namespace {

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v'; }
bool is_delimiter(char c) {
    return is_space(c) || c == '(' || c == ')' || c == '{' || c == '}' || c == ';' || c == '"';
}

std::string shown(std::string_view s) {
    std::string out;
    for (char c : s.substr(0, 40)) out += (static_cast<unsigned char>(c) < 32 || static_cast<unsigned char>(c) > 126) ? '?' : c;
    return s.size() > 40 ? out + "..." : out;
}

template <class T>
T from_little_endian(const char* bytes) {
    T v;
    std::memcpy(&v, bytes, sizeof v);
    if constexpr (std::endian::native == std::endian::big) {
        char b[sizeof v];
        std::memcpy(b, &v, sizeof v);
        std::reverse(b, b + sizeof v);
        std::memcpy(&v, b, sizeof v);
    }
    return v;
}

template <class T>
void put_little_endian(std::ostream& out, T v) {
    char b[sizeof v];
    std::memcpy(b, &v, sizeof v);
    if constexpr (std::endian::native == std::endian::big) std::reverse(b, b + sizeof v);
    out.write(b, sizeof v);
}

}  // namespace

std::string_view format_name(Format f) { return f == Format::binary ? "binary" : "ascii"; }

Scanner::Scanner(std::string file, std::string_view content) : file_(std::move(file)), s_(content) {}

void Scanner::fail(std::string_view expected, std::string_view found) const { fail_at(line_, expected, found); }

void Scanner::fail_at(std::size_t line, std::string_view expected, std::string_view found) const {
    throw ParseError(file_, line, std::string(expected), shown(found));
}

void Scanner::skip_blanks() {
    while (pos_ < s_.size()) {
        const char c = s_[pos_];
        if (c == '\n') {
            ++line_;
            ++pos_;
        } else if (is_space(c)) {
            ++pos_;
        } else if (c == '/' && pos_ + 1 < s_.size() && s_[pos_ + 1] == '/') {
            const std::size_t end = s_.find('\n', pos_);
            pos_ = end == std::string_view::npos ? s_.size() : end;
        } else if (c == '/' && pos_ + 1 < s_.size() && s_[pos_ + 1] == '*') {
            const std::size_t end = s_.find("*/", pos_ + 2);
            if (end == std::string_view::npos) fail("the end of the comment begun here ('*/')", "end of file");
            line_ += static_cast<std::size_t>(std::count(s_.begin() + static_cast<std::ptrdiff_t>(pos_),
                                                         s_.begin() + static_cast<std::ptrdiff_t>(end), '\n'));
            pos_ = end + 2;
        } else {
            return;
        }
    }
}

bool Scanner::at_end() {
    skip_blanks();
    return pos_ >= s_.size();
}

char Scanner::peek() {
    skip_blanks();
    return pos_ < s_.size() ? s_[pos_] : '\0';
}

void Scanner::expect(char c, std::string_view what) {
    const char next = peek();
    if (pos_ >= s_.size()) fail(what, "end of file");
    if (next != c) {
        const std::size_t start = pos_;
        std::size_t end = start + 1;
        while (end < s_.size() && !is_delimiter(s_[end])) ++end;
        fail(what, s_.substr(start, end - start));
    }
    ++pos_;
}

std::string_view Scanner::word(std::string_view what) {
    skip_blanks();
    if (pos_ >= s_.size()) fail(what, "end of file");
    if (s_[pos_] == '"') {
        const std::size_t start = pos_ + 1;
        std::size_t end = start;
        while (end < s_.size() && s_[end] != '"') {
            if (s_[end] == '\\' && end + 1 < s_.size()) ++end;
            if (s_[end] == '\n') fail(std::string(what) + " (a string ended by '\"' on its line)", s_.substr(start, end - start));
            ++end;
        }
        if (end >= s_.size()) fail(std::string(what) + " (a string ended by '\"')", "end of file");
        pos_ = end + 1;
        return s_.substr(start, end - start);
    }
    const std::size_t start = pos_;
    pos_ = word_end();
    if (pos_ == start) fail(what, s_.substr(start, 1));
    return s_.substr(start, pos_ - start);
}

std::size_t Scanner::word_end() const {
    std::size_t end = pos_;
    while (end < s_.size() && !is_delimiter(s_[end]) &&
           !(s_[end] == '/' && end + 1 < s_.size() && (s_[end + 1] == '/' || s_[end + 1] == '*')))
        ++end;
    return end;
}

bool Scanner::try_integer(std::int64_t& v) {
    skip_blanks();
    if (pos_ >= s_.size() || s_[pos_] == '"') return false;
    // The usual label, 1 to 18 plain digits ended by a delimiter, read as its
    // digits are scanned (word_end and parse_int would read them twice).
    std::int64_t value = 0;
    const auto digits_end = static_cast<std::size_t>(
        scan_plain_digits(s_.data() + pos_, s_.data() + s_.size(), value) - s_.data());
    if (digits_end > pos_ && (digits_end == s_.size() || is_delimiter(s_[digits_end]))) {
        v = value;
        pos_ = digits_end;
        return true;
    }
    const std::size_t end = word_end();
    if (end == pos_ || !parse_int(s_.substr(pos_, end - pos_), v)) return false;
    pos_ = end;
    return true;
}

bool Scanner::try_number(double& v) {
    skip_blanks();
    if (pos_ >= s_.size() || s_[pos_] == '"') return false;
    const std::size_t end = word_end();
    if (end == pos_ || !parse_double(s_.substr(pos_, end - pos_), v)) return false;
    pos_ = end;
    return true;
}

bool Scanner::try_char(char c) {
    skip_blanks();
    if (pos_ >= s_.size() || s_[pos_] != c) return false;
    ++pos_;
    return true;
}

std::int64_t Scanner::integer(std::string_view what) {
    const std::size_t line = (skip_blanks(), line_);
    const std::string_view w = word(what);
    std::int64_t v = 0;
    if (!parse_int(w, v)) fail_at(line, std::string(what) + " (an integer)", w);
    return v;
}

double Scanner::number(std::string_view what) {
    const std::size_t line = (skip_blanks(), line_);
    const std::string_view w = word(what);
    double v = 0;
    if (!parse_double(w, v)) fail_at(line, std::string(what) + " (a finite number)", w);
    return v;
}

std::string_view Scanner::raw(std::size_t bytes, std::string_view what) {
    if (bytes > s_.size() - pos_)
        fail(std::string(what) + ": " + std::to_string(bytes) + " bytes of binary data from byte " +
                 std::to_string(pos_) + " (the file has " + std::to_string(s_.size() - pos_) + " left)",
             "end of file");
    const std::string_view r = s_.substr(pos_, bytes);
    line_ += static_cast<std::size_t>(std::count(r.begin(), r.end(), '\n'));
    pos_ += bytes;
    return r;
}

std::int64_t Scanner::list_size(std::string_view what, std::size_t min_item_bytes) {
    const std::size_t line = (skip_blanks(), line_);
    const std::int64_t n = integer(std::string("the size of ") + std::string(what));
    if (n < 0) fail_at(line, "a list size >= 0 for " + std::string(what), std::to_string(n));
    const std::size_t left = s_.size() - pos_;
    if (static_cast<std::uint64_t>(n) > left / std::max<std::size_t>(min_item_bytes, 1))
        fail_at(line,
                "a size of " + std::string(what) + " that the rest of the file can hold (at most " +
                    std::to_string(left / std::max<std::size_t>(min_item_bytes, 1)) + " in its " +
                    std::to_string(left) + " bytes)",
                std::to_string(n));
    return n;
}

std::string_view Scanner::entry_value(std::string_view key) {
    skip_blanks();
    const std::size_t start = pos_, line = line_;
    int depth = 0;
    while (true) {
        if (at_end()) fail_at(line, "';' ending the entry '" + std::string(key) + "'", "end of file");
        const char c = s_[pos_];
        if (c == '(' || c == '{') {
            ++depth;
            ++pos_;
        } else if (c == ')' || c == '}') {
            if (depth == 0) fail(std::string("';' ending the entry '") + std::string(key) + "'", std::string(1, c));
            ++pos_;
            // A sub-dictionary `key { ... }` ends without ';'.
            if (--depth == 0 && c == '}' && s_[start] == '{') return s_.substr(start, pos_ - start);
        } else if (c == ';') {
            ++pos_;
            if (depth == 0) return trim(s_.substr(start, pos_ - 1 - start));
        } else {
            word("a value of the entry '" + std::string(key) + "'");
        }
    }
}

void Scanner::check_arch(std::string_view arch, std::size_t line) const {
    // "LSB;label=32;scalar=64": every part must be what dgwarp reads.
    std::size_t at = 0;
    while (at <= arch.size()) {
        std::size_t end = arch.find(';', at);
        if (end == std::string_view::npos) end = arch.size();
        const std::string_view part = trim(arch.substr(at, end - at));
        const bool ok = part.empty() || part == "LSB" || part == "label=32" || part == "scalar=64" ||
                        (part.substr(0, 6) != "label=" && part.substr(0, 7) != "scalar=" && part != "MSB");
        if (!ok)
            throw FormatError(file_ + ":" + std::to_string(line) + ": binary data with arch \"" + std::string(arch) +
                              "\": dgwarp reads binary OpenFOAM files with little-endian (LSB) 32-bit labels and "
                              "64-bit scalars (\"LSB;label=32;scalar=64\"); convert this one to ascii with "
                              "OpenFOAM's foamFormatConvert (writeFormat ascii in system/controlDict)");
        at = end + 1;
    }
}

Header Scanner::read_header() {
    const std::string_view first = word("the FoamFile header");
    if (first != "FoamFile") fail_at(line_, "the FoamFile header", first);
    const std::size_t header_line = line_;
    expect('{', "'{' after FoamFile");
    Header h;
    h.class_line = header_line;
    std::string_view arch;
    std::size_t arch_line = 0;
    bool has_format = false;
    while (peek() != '}') {
        const std::size_t line = line_;
        const std::string_view key = word("an entry of the FoamFile header or '}'");
        const std::string_view value = entry_value(key);
        const std::string_view unquoted =
            value.size() >= 2 && value.front() == '"' && value.back() == '"' ? value.substr(1, value.size() - 2) : value;
        if (key == "format") {
            if (unquoted == "ascii") h.format = Format::ascii;
            else if (unquoted == "binary") h.format = Format::binary;
            else fail_at(line, "format ascii or binary", unquoted);
            has_format = true;
        } else if (key == "class") {
            h.class_name = std::string(unquoted);
            h.class_line = line;
        } else if (key == "object") {
            h.object = std::string(unquoted);
        } else if (key == "arch") {
            arch = unquoted;
            arch_line = line;
        }
    }
    expect('}', "'}' ending the FoamFile header");
    if (!has_format) fail_at(header_line, "a 'format' entry (ascii or binary) in the FoamFile header", "none");
    if (h.format == Format::binary && !arch.empty()) check_arch(arch, arch_line);
    format_ = h.format;
    return h;
}

std::int32_t binary_label(const char* bytes) { return from_little_endian<std::int32_t>(bytes); }
double binary_scalar(const char* bytes) { return from_little_endian<double>(bytes); }
void put_binary_label(std::ostream& out, std::int32_t v) { put_little_endian(out, v); }
void put_binary_scalar(std::ostream& out, double v) { put_little_endian(out, v); }

void write_header(std::ostream& out, Format format, std::string_view class_name, std::string_view location,
                  std::string_view object, std::string_view note) {
    out << "/*--------------------------------*- C++ -*----------------------------------*\\\n"
           "| =========                 |                                                 |\n"
           "| \\\\      /  F ield         | OpenFOAM: The Open Source CFD Toolbox           |\n"
           "|  \\\\    /   O peration     | Written by dgwarp                               |\n"
           "|   \\\\  /    A nd           |                                                 |\n"
           "|    \\\\/     M anipulation  |                                                 |\n"
           "\\*---------------------------------------------------------------------------*/\n"
           "FoamFile\n{\n    version     2.0;\n    format      "
        << format_name(format) << ";\n    class       " << class_name << ";\n";
    if (format == Format::binary) out << "    arch        \"LSB;label=32;scalar=64\";\n";
    if (!note.empty()) out << "    note        \"" << note << "\";\n";
    out << "    location    \"" << location << "\";\n    object      " << object
        << ";\n}\n// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //\n\n";
}

void write_footer(std::ostream& out) {
    out << "\n\n// ************************************************************************* //\n";
}

}  // namespace dgwarp::foam
