#include "dgwarp/io/text_reader.hpp"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>

#include "dgwarp/core/error.hpp"
#include "dgwarp/io/record_lines.hpp"

namespace dgwarp {

namespace {
bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }

std::string shorten(std::string_view s) {
    constexpr std::size_t max = 60;
    return s.size() <= max ? std::string(s) : std::string(s.substr(0, max)) + "...";
}
}  // namespace

std::string_view trim(std::string_view s) {
    while (!s.empty() && is_blank(s.front())) s.remove_prefix(1);
    while (!s.empty() && is_blank(s.back())) s.remove_suffix(1);
    return s;
}

std::string read_file_text(const std::filesystem::path& path) {
    // Opening a folder succeeds; reading it does not (and would look like an
    // empty file). A device or a pipe (/dev/zero, also through a symbolic
    // link) may never end: reading it would fill the memory; opening a pipe
    // may wait for ever. A missing file is left to open() to name the reason.
    std::error_code ec;
    const auto type = std::filesystem::status(path, ec).type();
    if (type == std::filesystem::file_type::directory)
        throw IoError(path.string(), std::string("cannot read it: ") + std::strerror(EISDIR), EISDIR);
    if (type != std::filesystem::file_type::regular && type != std::filesystem::file_type::not_found &&
        type != std::filesystem::file_type::none)
        throw IoError(path.string(), "is not a regular file (a device, a pipe or a socket): dgwarp reads files only");
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        const int err = errno;
        throw IoError(path.string(), std::string("cannot open file for reading: ") + std::strerror(err), err);
    }
    // One read of the whole size into a string of that size (a stream copy
    // through an ostringstream ran at 0.5 GB/s from the page cache); then
    // whatever the file grew by meanwhile, in blocks, up to its end.
    std::string text;
    const auto size = type == std::filesystem::file_type::regular ? std::filesystem::file_size(path, ec) : 0;
    if (!ec && size > 0) {
        text.resize(static_cast<std::size_t>(size));
        in.read(text.data(), static_cast<std::streamsize>(size));
        text.resize(static_cast<std::size_t>(in.gcount()));
    }
    if (!in.bad() && in.good()) {
        char block[1 << 16];
        while (in.read(block, sizeof block) || in.gcount() > 0) text.append(block, static_cast<std::size_t>(in.gcount()));
    }
    if (in.bad()) throw IoError(path.string(), std::string("read error: ") + std::strerror(errno));
    return text;
}

TextReader TextReader::open(const std::filesystem::path& path) {
    return TextReader(path.string(), FileBytes::read(path));
}

TextReader::TextReader(std::string file_name, std::string content)
    : TextReader(std::move(file_name), FileBytes(std::move(content))) {}

TextReader::TextReader(std::string file_name, FileBytes content)
    : file_(std::move(file_name)), bytes_(std::move(content)) {
    // A UTF-8 byte order mark (editors on Windows write one) is not part of the first line.
    if (bytes_.view().starts_with("\xEF\xBB\xBF")) pos_ = 3;
}

void TextReader::set_progress(ProgressFn progress) {
    progress_ = std::move(progress);
    next_report_ = progress_ ? pos_ : static_cast<std::size_t>(-1);
}

void TextReader::report_progress() { report_progress_to(pos_); }

void TextReader::report_progress_to(std::size_t pos) {
    if (!progress_ || pos < next_report_) return;
    constexpr std::size_t mib = std::size_t{1} << 20;
    const std::size_t size = content().size();
    progress_(size == 0 ? 1.0 : std::min(1.0, static_cast<double>(pos) / static_cast<double>(size)));
    next_report_ = pos + std::max(mib, size / 100);
}

bool TextReader::next_line() {
    const std::string_view text = content();
    if (pos_ >= next_report_) report_progress();
    if (pos_ >= text.size()) {
        line_ = {};
        cursor_ = 0;
        return false;
    }
    std::size_t end = text.find('\n', pos_);
    if (end == std::string::npos) end = text.size();
    std::string_view l(text.data() + pos_, end - pos_);
    if (!l.empty() && l.back() == '\r') l.remove_suffix(1);
    line_ = l;
    cursor_ = 0;
    pos_ = end + 1;
    ++line_number_;
    return true;
}

void TextReader::seek(std::size_t pos, std::size_t line_number) {
    const std::string_view text = content();
    pos_ = std::min(pos, text.size());
    line_number_ = line_number;
    // The current line: the one ending just before pos (its '\n', or the end of the content).
    std::size_t end = pos_;
    if (end > 0 && text[end - 1] == '\n') --end;
    const std::size_t nl = end == 0 ? std::string::npos : text.rfind('\n', end - 1);
    const std::size_t start = nl == std::string::npos ? 0 : nl + 1;
    line_ = std::string_view(text.data() + start, end - start);
    if (!line_.empty() && line_.back() == '\r') line_.remove_suffix(1);
    cursor_ = line_.size();
}

bool TextReader::next_nonblank_line() {
    while (next_line())
        if (!trim(line_).empty()) return true;
    return false;
}

void TextReader::require_line(std::string_view what) {
    if (!next_nonblank_line()) fail(what, "end of file");
}

std::string_view TextReader::next_token() {
    while (cursor_ < line_.size() && is_blank(line_[cursor_])) ++cursor_;
    const std::size_t start = cursor_;
    while (cursor_ < line_.size() && !is_blank(line_[cursor_])) ++cursor_;
    return line_.substr(start, cursor_ - start);
}

std::string_view TextReader::require_token(std::string_view what) {
    std::string_view t = next_token();
    if (t.empty()) fail(what, "end of line");
    return t;
}

std::string_view TextReader::rest_of_line() {
    std::string_view rest = trim(line_.substr(cursor_));
    cursor_ = line_.size();
    return rest;
}

std::int64_t TextReader::next_int(std::string_view what) {
    std::string_view t = require_token(what);
    std::int64_t v = 0;
    if (!parse_int(t, v)) fail(std::string(what) + " (an integer)", t);
    return v;
}

double TextReader::next_double(std::string_view what) {
    std::string_view t = require_token(what);
    double v = 0;
    if (!parse_double(t, v)) fail(std::string(what) + " (a finite number)", t);
    return v;
}

void TextReader::fail(std::string_view expected, std::string_view found) const {
    throw ParseError(file_, line_number_, std::string(expected), shorten(found));
}

bool parse_int(std::string_view token, std::int64_t& value) {
    if (!token.empty() && token.front() == '+') token.remove_prefix(1);
    if (parse_plain_digits(token, value)) return true;  // the usual case, without from_chars' generality
    auto [p, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
    return ec == std::errc() && p == token.data() + token.size() && !token.empty();
}

bool parse_double(std::string_view token, double& value) {
    if (!token.empty() && token.front() == '+') token.remove_prefix(1);
    auto [p, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
    return ec == std::errc() && p == token.data() + token.size() && !token.empty() && std::isfinite(value);
}

}  // namespace dgwarp
