#pragma once
// Line-by-line reading of a text mesh file with positions for error messages.
// Shared by every text format reader: each error names the file, the 1-based
// line, what was expected and what was found (ParseError).
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

#include "dgwarp/core/progress.hpp"
#include "dgwarp/io/file_bytes.hpp"

namespace dgwarp {

/// The whole content of the file at `path`. Throws IoError with the operating
/// system's reason ("No such file or directory", "Permission denied", "Is a
/// directory") when it cannot be read, and when it is not a regular file
/// (a device such as /dev/zero, a pipe, a socket: reading it might not end).
std::string read_file_text(const std::filesystem::path& path);

class TextReader {
public:
    /// A reader over the file's bytes (mapped when large: file_bytes.hpp);
    /// throws IoError when it cannot be read.
    static TextReader open(const std::filesystem::path& path);
    /// A reader over `content`, reporting errors as coming from `file_name`.
    /// A UTF-8 byte order mark at its start is skipped.
    TextReader(std::string file_name, std::string content);
    TextReader(std::string file_name, FileBytes content);

    /// Reports the bytes consumed / the content's size to `progress` as
    /// next_line() advances: every 1% or 1 MiB, whichever is more.
    void set_progress(ProgressFn progress);

    /// Advances to the next line (the first call reads line 1); false at end of file.
    bool next_line();
    /// Advances to the next line that is not blank; false at end of file.
    bool next_nonblank_line();
    /// Like next_nonblank_line, but throws ParseError("expected <what>",
    /// "end of file") at end of file.
    void require_line(std::string_view what);

    /// The current line without its end-of-line characters.
    std::string_view line() const { return line_; }
    /// Byte offset of the current line's first character in the content.
    /// (the content's size at the end of the file).
    std::size_t line_offset() const {
        return line_.data() ? static_cast<std::size_t>(line_.data() - content().data()) : content().size();
    }
    /// The whole content.
    std::string_view content() const { return bytes_.view(); }
    /// The content before byte offset `pos` is read (FileBytes::release_before):
    /// a mapped file's pages there leave memory; content() is unchanged.
    void release_before(std::size_t pos) noexcept { bytes_.release_before(pos); }
    /// 1-based number of the current line (0 before the first next_line()).
    std::size_t line_number() const { return line_number_; }
    const std::string& file() const { return file_; }
    bool at_end() const { return pos_ >= content().size(); }
    /// Bytes after the current line: bounds what a count read from a header
    /// can honestly announce, before anything is allocated for it.
    std::size_t remaining_bytes() const { return at_end() ? 0 : content().size() - pos_; }

    /// The next whitespace-separated token of the current line, or an empty
    /// view at the end of the line.
    std::string_view next_token();
    /// The next token; throws ParseError("expected <what>") at the end of the line.
    std::string_view require_token(std::string_view what);
    /// The rest of the current line after the tokens already taken, trimmed.
    std::string_view rest_of_line();

    /// Next token parsed as an integer / a finite floating-point number;
    /// throws ParseError naming `what` on a missing or malformed token.
    std::int64_t next_int(std::string_view what);
    double next_double(std::string_view what);

    /// Byte offset where the next line begins (the content's size at its end).
    std::size_t position() const { return pos_; }
    /// Continues at byte offset `pos` (the first byte of a line), as if the
    /// line before it had just been read (its tokens all taken) and was line
    /// `line_number`: for a reader that parsed a block of lines itself
    /// (record_lines.hpp).
    void seek(std::size_t pos, std::size_t line_number);

    /// Where next_line() next reports progress (a byte offset; the largest
    /// size_t without a progress function).
    std::size_t progress_due() const { return next_report_; }
    /// Reports progress as next_line() would at byte offset `pos`, when it is due there.
    void report_progress_to(std::size_t pos);

    /// Throws ParseError at the current line.
    [[noreturn]] void fail(std::string_view expected, std::string_view found = {}) const;

private:
    std::string file_;
    FileBytes bytes_;
    std::size_t pos_ = 0;
    std::string_view line_;
    std::size_t cursor_ = 0;  // position of the next token in line_
    std::size_t line_number_ = 0;
    ProgressFn progress_;
    std::size_t next_report_ = static_cast<std::size_t>(-1);  // position of the next progress report
    void report_progress();
};

/// Parses a whole token as an integer / a finite double; false if malformed.
bool parse_int(std::string_view token, std::int64_t& value);
bool parse_double(std::string_view token, double& value);

/// `s` without leading and trailing blanks (spaces, tabs, CR).
std::string_view trim(std::string_view s);

}  // namespace dgwarp
