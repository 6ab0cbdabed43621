#pragma once
// OpenFOAM's FoamFile format, as its mesh files (constant/polyMesh/points,
// faces, owner, neighbour, boundary) use it: a `FoamFile { ... }` header
// dictionary, then the object's data. Internal to the OpenFOAM reader and
// writer (openfoam_read.cpp, openfoam_write.cpp).
//
// Tokens are separated by blanks, `// ...` and `/* ... */` comments. A list is
// `N ( item item ... )`, or `N { item }` for N copies of one item. In binary
// format (`format binary;` in the header), a list of a fixed-size item (label,
// scalar, vector) is `N (` followed at once by the N items' raw bytes and `)`;
// labels and scalars have the sizes the header's `arch` entry gives
// ("LSB;label=32;scalar=64" when absent, OpenFOAM's default build).
#include <cstdint>
#include <ostream>
#include <string>
#include <string_view>

namespace dgwarp::foam {

enum class Format : std::uint8_t { ascii, binary };

/// "ascii" or "binary".
std::string_view format_name(Format f);

/// What a FoamFile header says.
struct Header {
    Format format = Format::ascii;
    std::string class_name;       // "vectorField", "faceList", "faceCompactList", "labelList", "polyBoundaryMesh"
    std::string object;           // "points", "faces", ...
    std::size_t class_line = 0;   // line of the `class` entry (of the header when absent), for errors
};

/// A cursor over one FoamFile's bytes that knows the line it is on. Every
/// error is a ParseError naming the file and the line (FormatError for a
/// binary layout dgwarp does not read: big-endian, 64-bit labels, scalars
/// other than 64-bit).
class Scanner {
public:
    /// `content` must outlive the scanner; `file` names it in errors.
    Scanner(std::string file, std::string_view content);

    /// Reads the `FoamFile { ... }` header (the first thing after comments)
    /// and remembers its format for the lists that follow.
    Header read_header();

    const std::string& file() const { return file_; }
    /// 1-based line of the next unread byte.
    std::size_t line() const { return line_; }
    /// Byte offset of the next unread byte.
    std::size_t offset() const { return pos_; }
    bool binary() const { return format_ == Format::binary; }

    /// Skips blanks and comments; true when nothing else is left.
    bool at_end();
    /// Skips blanks and comments; the next byte (0 at the end).
    char peek();
    /// Skips blanks and comments, then takes the byte `c`; fails naming `what`.
    void expect(char c, std::string_view what);
    /// Skips blanks and comments, then takes a word (up to a blank, a comment
    /// or one of `(){};"`) or a quoted string (its content); fails naming `what`.
    std::string_view word(std::string_view what);
    /// A word parsed as an integer / a finite number; fails naming `what`.
    std::int64_t integer(std::string_view what);
    double number(std::string_view what);
    /// The fast paths of the lists' items: skip blanks and comments, then take
    /// an integer / a finite number / the byte `c` and return true; return
    /// false, taking nothing, when the next token is something else (the
    /// caller then calls integer, number or expect, which throw with its words).
    bool try_integer(std::int64_t& v);
    bool try_number(double& v);
    bool try_char(char c);
    /// Bytes not read yet.
    std::size_t remaining() const { return s_.size() - pos_; }

    /// The next `bytes` bytes as they are (binary list data: no blank is
    /// skipped); fails when the file is shorter.
    std::string_view raw(std::size_t bytes, std::string_view what);

    /// A list's size: a non-negative integer, no larger than the bytes left
    /// can hold when each item takes at least `min_item_bytes` (checked
    /// before anything is allocated for it).
    std::int64_t list_size(std::string_view what, std::size_t min_item_bytes);

    /// Skips a dictionary entry's value up to its `;` (or a `{ ... }`
    /// sub-dictionary), nested lists and dictionaries included; returns its
    /// text, trimmed.
    std::string_view entry_value(std::string_view key);

    /// Byte sizes of a binary label and scalar (4 and 8: read_header refuses others).
    static constexpr std::size_t label_bytes = 4;
    static constexpr std::size_t scalar_bytes = 8;

    /// Throws ParseError at the current line.
    [[noreturn]] void fail(std::string_view expected, std::string_view found) const;
    /// Throws ParseError at `line`.
    [[noreturn]] void fail_at(std::size_t line, std::string_view expected, std::string_view found) const;

private:
    void skip_blanks();
    /// The end of the word starting at pos_ (see word()).
    std::size_t word_end() const;
    void check_arch(std::string_view arch, std::size_t line) const;

    std::string file_;
    std::string_view s_;
    std::size_t pos_ = 0;
    std::size_t line_ = 1;
    Format format_ = Format::ascii;
};

/// The value of a binary label / scalar at `bytes` (little-endian).
std::int32_t binary_label(const char* bytes);
double binary_scalar(const char* bytes);
/// Appends the little-endian bytes of `v`.
void put_binary_label(std::ostream& out, std::int32_t v);
void put_binary_scalar(std::ostream& out, double v);

/// Writes OpenFOAM's banner and a FoamFile header: version 2.0, `format`,
/// `class_name`, (binary) arch "LSB;label=32;scalar=64", `note` when not
/// empty, `location` and `object`, then the separator line, as OpenFOAM writes them.
void write_header(std::ostream& out, Format format, std::string_view class_name, std::string_view location,
                  std::string_view object, std::string_view note = {});

/// The closing comment line OpenFOAM ends its files with.
void write_footer(std::ostream& out);

}  // namespace dgwarp::foam
