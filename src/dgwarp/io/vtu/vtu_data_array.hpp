#pragma once
// The values of one VTK XML DataArray (or String Array), in every encoding
// VTK writes (VTK File Formats, "XML File Formats"):
//  - format="ascii": numbers separated by blanks (strings as their character
//    codes, each string ended by 0);
//  - format="binary": base64 text inside the element;
//  - format="appended" offset="N": data at byte N after the '_' of
//    <AppendedData encoding="raw"> (bytes) or encoding="base64" (characters).
// Binary data is [header][values]: uncompressed, the header is one
// header_type integer (UInt32 or UInt64), the byte count; with
// compressor="vtkZLibDataCompressor", it is [number of blocks, block size,
// size of the last block (0: a full block), compressed size of each block]
// followed by the zlib-compressed blocks. Values are in the file's
// byte_order. Every error is a ParseError naming the file, the line of the
// array's tag (and, for appended data, the byte offset), the array and what
// was expected; nothing is allocated beyond what the file's bytes can hold
// (compressed data: at most deflate's 1032:1 ratio).
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "dgwarp/io/vtu/vtk_xml.hpp"

namespace dgwarp::vtu {

/// What every DataArray of one file shares.
struct Encoding {
    const std::string* file = nullptr;  // the file's name, for errors
    std::string_view content;           // the whole file
    bool big_endian = false;            // byte_order="BigEndian"
    int header_bytes = 4;               // header_type UInt32 (4) or UInt64 (8)
    bool zlib = false;                  // compressor="vtkZLibDataCompressor"
    std::size_t appended = std::string_view::npos;  // first byte after '_' of <AppendedData>
    bool appended_raw = true;           // <AppendedData encoding="raw"> (else base64)
};

/// A DataArray and what the reader calls it in messages, e.g. "DataArray
/// 'connectivity' of <Cells>".
struct ArrayRef {
    const xml::Element* element = nullptr;
    std::string what;
};

/// The values of a numeric array as doubles. `count`, when given, is the
/// number of values expected (tuples × components); `count_reason` says where
/// it comes from ("3 per point × NumberOfPoints 12").
std::vector<double> read_doubles(const Encoding& enc, const ArrayRef& array, std::optional<std::size_t> count,
                                 const std::string& count_reason);

/// The values of an integer array (Int8 .. UInt64); a floating-point array is
/// an error, and so is a UInt64 value above the largest Int64.
std::vector<std::int64_t> read_integers(const Encoding& enc, const ArrayRef& array, std::optional<std::size_t> count,
                                        const std::string& count_reason);

/// The strings of a type="String" array: `count` strings, each ended by a 0 byte.
std::vector<std::string> read_strings(const Encoding& enc, const ArrayRef& array, std::size_t count,
                                      const std::string& count_reason);

/// True when the array's type attribute names an integer type.
bool is_integer_array(const xml::Element& element);

/// Throws ParseError at the line of `array`'s tag: `expected` in `array.what`.
[[noreturn]] void fail_at(const Encoding& enc, const ArrayRef& array, const std::string& expected,
                          const std::string& found);

}  // namespace dgwarp::vtu
