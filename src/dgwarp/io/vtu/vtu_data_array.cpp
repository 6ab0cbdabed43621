#include "dgwarp/io/vtu/vtu_data_array.hpp"

#include <zlib.h>

#include <algorithm>
#include <bit>
#include <cstring>
#include <limits>

#include "dgwarp/core/error.hpp"
#include "dgwarp/io/vtu/base64.hpp"
#include "dgwarp/io/text_reader.hpp"

namespace dgwarp::vtu {

namespace {

enum class Scalar { int8, uint8, int16, uint16, int32, uint32, int64, uint64, float32, float64, string };

struct TypeInfo {
    std::string_view name;
    Scalar scalar;
    std::size_t size;  // bytes per value (1 for strings: bytes)
};

constexpr TypeInfo vtk_types[] = {
    {"Int8", Scalar::int8, 1},       {"UInt8", Scalar::uint8, 1},     {"Int16", Scalar::int16, 2},
    {"UInt16", Scalar::uint16, 2},   {"Int32", Scalar::int32, 4},     {"UInt32", Scalar::uint32, 4},
    {"Int64", Scalar::int64, 8},     {"UInt64", Scalar::uint64, 8},   {"Float32", Scalar::float32, 4},
    {"Float64", Scalar::float64, 8}, {"String", Scalar::string, 1},
};

// Older VTK files spell some types the C way.
constexpr std::pair<std::string_view, std::string_view> legacy_type_names[] = {
    {"Char", "Int8"}, {"UnsignedChar", "UInt8"}, {"Short", "Int16"}, {"UnsignedShort", "UInt16"},
    {"Int", "Int32"}, {"UnsignedInt", "UInt32"}, {"Long", "Int64"},  {"UnsignedLong", "UInt64"},
    {"Float", "Float32"}, {"Double", "Float64"}, {"vtkIdType", "Int64"}};

// Deflate cannot compress better than about 1032:1.
constexpr std::uint64_t max_zlib_ratio = 1032;

bool is_integer(Scalar s) { return s != Scalar::float32 && s != Scalar::float64 && s != Scalar::string; }

const TypeInfo* find_type(std::string_view name) {
    for (const auto& [legacy, modern] : legacy_type_names)
        if (name == legacy) name = modern;
    for (const TypeInfo& t : vtk_types)
        if (t.name == name) return &t;
    return nullptr;
}

const TypeInfo& type_of(const Encoding& enc, const ArrayRef& a) {
    const std::string* name = a.element->attribute("type");
    if (!name) fail_at(enc, a, "a type attribute (Int8 .. UInt64, Float32, Float64)", "none");
    const TypeInfo* t = find_type(*name);
    if (!t)
        fail_at(enc, a, "a type Int8, UInt8, Int16, UInt16, Int32, UInt32, Int64, UInt64, Float32 or Float64", *name);
    return *t;
}

std::string str(std::uint64_t v) { return std::to_string(v); }

std::uint64_t load_unsigned(const std::byte* p, std::size_t size, bool big_endian) {
    std::uint8_t b[8];
    std::memcpy(b, p, size);
    if (big_endian) std::reverse(b, b + size);
    std::uint64_t v = 0;
    for (std::size_t k = size; k-- > 0;) v = (v << 8) | b[k];
    return v;
}

/// Value i of `bytes` (items of `type`, in the file's byte order) as T.
template <class T>
T load_value(const std::byte* p, Scalar type, bool big_endian) {
    auto bits = [&](std::size_t size) { return load_unsigned(p, size, big_endian); };
    switch (type) {
        case Scalar::int8: return static_cast<T>(static_cast<std::int8_t>(bits(1)));
        case Scalar::uint8: return static_cast<T>(static_cast<std::uint8_t>(bits(1)));
        case Scalar::int16: return static_cast<T>(static_cast<std::int16_t>(bits(2)));
        case Scalar::uint16: return static_cast<T>(static_cast<std::uint16_t>(bits(2)));
        case Scalar::int32: return static_cast<T>(static_cast<std::int32_t>(bits(4)));
        case Scalar::uint32: return static_cast<T>(static_cast<std::uint32_t>(bits(4)));
        case Scalar::int64: return static_cast<T>(static_cast<std::int64_t>(bits(8)));
        case Scalar::uint64: return static_cast<T>(bits(8));
        case Scalar::float32: return static_cast<T>(std::bit_cast<float>(static_cast<std::uint32_t>(bits(4))));
        case Scalar::float64: return static_cast<T>(std::bit_cast<double>(bits(8)));
        case Scalar::string: break;
    }
    return T{};
}

// Where the bytes of a binary array come from: appended raw bytes, or base64
// text (inline or appended). Both say what stopped a short read.
class RawSource {
public:
    RawSource(std::string_view bytes, std::size_t file_offset) : bytes_(bytes), file_offset_(file_offset) {}
    std::size_t read(std::byte* out, std::size_t n) {
        n = std::min(n, bytes_.size() - pos_);
        if (n > 0) std::memcpy(out, bytes_.data() + pos_, n);
        pos_ += n;
        return n;
    }
    /// Bytes that can still be read.
    std::uint64_t capacity() const { return bytes_.size() - pos_; }
    std::string stop_reason() const { return "the end of the file at byte offset " + str(file_offset_ + pos_); }

private:
    std::string_view bytes_;
    std::size_t pos_ = 0;
    std::size_t file_offset_;
};

class Base64Source {
public:
    Base64Source(std::string_view text, std::string_view content) : text_(text), content_(content), decoder_(text) {}
    std::size_t read(std::byte* out, std::size_t n) { return decoder_.read(out, n); }
    /// An upper bound on the bytes that can still be read.
    std::uint64_t capacity() const { return (text_.size() - decoder_.position()) / 4 * 3 + 3; }
    std::string stop_reason() const {
        const std::size_t bad = decoder_.bad_position();
        if (bad == std::string_view::npos) return "the end of the base64 text";
        std::string reason(1, '\'');
        reason += text_[bad];
        reason += "', not base64";
        // text_ lies in the file unless an element's text came in pieces (then it is a copy).
        const auto at = reinterpret_cast<std::uintptr_t>(text_.data() + bad);
        const auto begin = reinterpret_cast<std::uintptr_t>(content_.data());
        if (at >= begin && at < begin + content_.size()) reason += ", on line " + str(xml::line_at(content_, at - begin));
        return reason;
    }

private:
    std::string_view text_, content_;
    Base64Decoder decoder_;
};

template <class Source>
void read_exactly(const Encoding& enc, const ArrayRef& a, Source& src, std::byte* out, std::uint64_t n,
                  const std::string& what) {
    if (src.read(out, static_cast<std::size_t>(n)) != n) fail_at(enc, a, what, src.stop_reason());
}

template <class Source>
std::uint64_t read_word(const Encoding& enc, const ArrayRef& a, Source& src, const std::string& what) {
    std::byte b[8];
    read_exactly(enc, a, src, b, static_cast<std::uint64_t>(enc.header_bytes), what);
    return load_unsigned(b, static_cast<std::size_t>(enc.header_bytes), enc.big_endian);
}

/// "36 values (3 per point × NumberOfPoints 12)", or "" without a count.
std::string expected_values(std::optional<std::size_t> count, const std::string& reason) {
    return count ? str(*count) + " values (" + reason + ")" : std::string();
}

void check_byte_count(const Encoding& enc, const ArrayRef& a, const TypeInfo& t, std::uint64_t bytes,
                      std::optional<std::size_t> count, const std::string& reason) {
    if (bytes % t.size)
        fail_at(enc, a, "a byte count that is a whole number of " + std::string(t.name) + " values (" + str(t.size) +
                            " bytes each)",
                str(bytes) + " bytes");
    if (count && bytes / t.size != *count)
        fail_at(enc, a, expected_values(count, reason), str(bytes / t.size) + " (" + str(bytes) + " bytes)");
}

/// The data bytes of a binary array (after its header), uncompressed.
template <class Source>
std::vector<std::byte> read_payload(const Encoding& enc, const ArrayRef& a, const TypeInfo& t, Source& src,
                                    std::optional<std::size_t> count, const std::string& reason) {
    if (!enc.zlib) {
        const std::uint64_t n = read_word(enc, a, src, "the header (the byte count)");
        check_byte_count(enc, a, t, n, count, reason);
        if (n > src.capacity())
            fail_at(enc, a, str(n) + " bytes of data, as its header declares", "room for at most " + str(src.capacity()));
        std::vector<std::byte> bytes(static_cast<std::size_t>(n));
        read_exactly(enc, a, src, bytes.data(), n, str(n) + " bytes of data, as its header declares");
        return bytes;
    }
    const std::string header = "the compression header [blocks, block size, last block size, compressed sizes]";
    const std::uint64_t blocks = read_word(enc, a, src, header);
    const std::uint64_t block_size = read_word(enc, a, src, header);
    const std::uint64_t last_size = read_word(enc, a, src, header);
    if (blocks > src.capacity() / static_cast<std::uint64_t>(enc.header_bytes))
        fail_at(enc, a, "a number of compressed blocks whose sizes the file can hold", str(blocks) + " blocks");
    if (blocks > 0 && (block_size == 0 || last_size > block_size))
        fail_at(enc, a, "a block size > 0 and a last block size no larger", str(block_size) + " and " + str(last_size));
    const std::uint64_t last = last_size ? last_size : block_size;  // 0: the last block is full
    std::vector<std::uint64_t> compressed(static_cast<std::size_t>(blocks));
    std::uint64_t compressed_total = 0;
    for (auto& c : compressed) {
        c = read_word(enc, a, src, header);
        if (c > src.capacity()) fail_at(enc, a, "compressed block sizes the file can hold", str(c) + " bytes");
        compressed_total += c;
    }
    if (compressed_total > src.capacity())
        fail_at(enc, a, str(compressed_total) + " bytes of compressed blocks, as the header declares",
                "room for at most " + str(src.capacity()));
    // Checked before multiplying: the total must not exceed what the blocks can inflate to.
    const std::uint64_t most = max_zlib_ratio * compressed_total + 64;
    if (blocks > 0 && (last > most || (blocks > 1 && ((blocks - 1) > most / block_size ||
                                                      (blocks - 1) * block_size > most - last))))
        fail_at(enc, a, "uncompressed sizes that " + str(compressed_total) + " compressed bytes can hold",
                str(blocks) + " blocks of " + str(block_size) + " bytes");
    const std::uint64_t total = blocks == 0 ? 0 : (blocks - 1) * block_size + last;
    check_byte_count(enc, a, t, total, count, reason);
    std::vector<std::byte> bytes(static_cast<std::size_t>(total));
    std::vector<std::byte> block;
    std::uint64_t at = 0;
    for (std::uint64_t b = 0; b < blocks; ++b) {
        block.resize(static_cast<std::size_t>(compressed[b]));
        read_exactly(enc, a, src, block.data(), compressed[b],
                     "compressed block " + str(b + 1) + " of " + str(blocks) + " (" + str(compressed[b]) + " bytes)");
        const std::uint64_t size = b + 1 == blocks ? last : block_size;
        uLongf got = static_cast<uLongf>(size);
        const int rc = uncompress(reinterpret_cast<Bytef*>(bytes.data() + at), &got,
                                  reinterpret_cast<const Bytef*>(block.data()), static_cast<uLong>(block.size()));
        if (rc != Z_OK || got != size)
            fail_at(enc, a, "zlib data of " + str(size) + " bytes in block " + str(b + 1) + " of " + str(blocks),
                    rc == Z_OK ? str(got) + " bytes" : std::string("zlib error: ") + zError(rc));
        at += size;
    }
    return bytes;
}

/// The decoded data bytes of a binary or appended array.
std::vector<std::byte> binary_payload(const Encoding& enc, const ArrayRef& a, const TypeInfo& t,
                                      const std::string& format, std::optional<std::size_t> count,
                                      const std::string& reason) {
    if (format == "binary") {
        std::string storage;
        const std::string_view text = xml::text_of(*a.element, enc.content, storage);
        Base64Source src(text, enc.content);
        return read_payload(enc, a, t, src, count, reason);
    }
    // format="appended"
    if (enc.appended == std::string_view::npos)
        fail_at(enc, a, "an <AppendedData> section (the array's format is \"appended\")", "none in the file");
    const std::string* offset_text = a.element->attribute("offset");
    std::int64_t offset = -1;
    if (!offset_text || !parse_int(trim(*offset_text), offset) || offset < 0)
        fail_at(enc, a, "an offset attribute >= 0 (format=\"appended\")", offset_text ? *offset_text : "none");
    const std::size_t available = enc.content.size() - enc.appended;
    if (static_cast<std::uint64_t>(offset) > available)
        fail_at(enc, a, "an offset within the " + str(available) + " bytes of <AppendedData>", *offset_text);
    const std::string_view data = enc.content.substr(enc.appended + static_cast<std::size_t>(offset));
    if (enc.appended_raw) {
        RawSource src(data, enc.appended + static_cast<std::size_t>(offset));
        return read_payload(enc, a, t, src, count, reason);
    }
    Base64Source src(data, enc.content);
    return read_payload(enc, a, t, src, count, reason);
}

/// The array's format attribute: "ascii", "binary" or "appended".
std::string format_of(const Encoding& enc, const ArrayRef& a) {
    const std::string* format = a.element->attribute("format");
    if (!format || (*format != "ascii" && *format != "binary" && *format != "appended"))
        fail_at(enc, a, "format=\"ascii\", \"binary\" or \"appended\"", format ? *format : "no format attribute");
    return *format;
}

/// Calls `take(token, line_offset)` for each blank-separated token of an ascii array.
template <class Take>
void for_each_token(const Encoding& enc, const ArrayRef& a, Take take) {
    std::string storage;
    const std::string_view text = xml::text_of(*a.element, enc.content, storage);
    std::size_t i = 0;
    while (i < text.size()) {
        while (i < text.size() && (text[i] == ' ' || text[i] == '\t' || text[i] == '\n' || text[i] == '\r')) ++i;
        const std::size_t b = i;
        while (i < text.size() && !(text[i] == ' ' || text[i] == '\t' || text[i] == '\n' || text[i] == '\r')) ++i;
        if (i > b) take(text.substr(b, i - b));
    }
}

/// ParseError on the line of an ascii token (when it lies in the file's text).
[[noreturn]] void fail_token(const Encoding& enc, const ArrayRef& a, std::string_view token, const std::string& expected) {
    // The token lies in the file unless the element's text came in pieces (then it is a copy).
    const auto at = reinterpret_cast<std::uintptr_t>(token.data());
    const auto begin = reinterpret_cast<std::uintptr_t>(enc.content.data());
    const bool inside = at >= begin && at < begin + enc.content.size();
    const std::size_t line = xml::line_at(enc.content, inside ? at - begin : a.element->offset);
    throw ParseError(*enc.file, line, expected + " in " + a.what, std::string(token.substr(0, 40)));
}

void check_count(const Encoding& enc, const ArrayRef& a, std::size_t got, std::optional<std::size_t> count,
                 const std::string& reason) {
    if (count && got != *count) fail_at(enc, a, expected_values(count, reason), str(got));
}

template <class T>
std::vector<T> read_numbers(const Encoding& enc, const ArrayRef& a, std::optional<std::size_t> count,
                            const std::string& reason) {
    const TypeInfo& t = type_of(enc, a);
    if (t.scalar == Scalar::string) fail_at(enc, a, "a numeric type", "String");
    const std::string format = format_of(enc, a);
    std::vector<T> values;
    if (format == "ascii") {
        for_each_token(enc, a, [&](std::string_view token) {
            if constexpr (std::is_integral_v<T>) {
                std::int64_t v = 0;
                if (!parse_int(token, v)) fail_token(enc, a, token, "an integer");
                values.push_back(v);
            } else {
                double v = 0;
                if (!parse_double(token, v)) fail_token(enc, a, token, "a finite number");
                values.push_back(v);
            }
        });
        check_count(enc, a, values.size(), count, reason);
        return values;
    }
    const std::vector<std::byte> bytes = binary_payload(enc, a, t, format, count, reason);
    const std::size_t n = bytes.size() / t.size;
    values.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        const std::byte* p = bytes.data() + i * t.size;
        if (std::is_integral_v<T> && t.scalar == Scalar::uint64 &&
            load_unsigned(p, 8, enc.big_endian) > static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max()))
            fail_at(enc, a, "values up to " + str(std::numeric_limits<std::int64_t>::max()),
                    str(load_unsigned(p, 8, enc.big_endian)) + " (value " + str(i) + ")");
        values[i] = load_value<T>(p, t.scalar, enc.big_endian);
    }
    return values;
}

}  // namespace

void fail_at(const Encoding& enc, const ArrayRef& array, const std::string& expected, const std::string& found) {
    throw ParseError(*enc.file, xml::line_at(enc.content, array.element->offset), expected + " in " + array.what, found);
}

bool is_integer_array(const xml::Element& element) {
    const std::string* name = element.attribute("type");
    const TypeInfo* t = name ? find_type(*name) : nullptr;
    return t && is_integer(t->scalar);
}

std::vector<double> read_doubles(const Encoding& enc, const ArrayRef& array, std::optional<std::size_t> count,
                                 const std::string& count_reason) {
    return read_numbers<double>(enc, array, count, count_reason);
}

std::vector<std::int64_t> read_integers(const Encoding& enc, const ArrayRef& array, std::optional<std::size_t> count,
                                        const std::string& count_reason) {
    const TypeInfo& t = type_of(enc, array);
    if (!is_integer(t.scalar)) fail_at(enc, array, "an integer type (Int8 .. UInt64)", std::string(t.name));
    return read_numbers<std::int64_t>(enc, array, count, count_reason);
}

std::vector<std::string> read_strings(const Encoding& enc, const ArrayRef& array, std::size_t count,
                                      const std::string& count_reason) {
    const TypeInfo& t = type_of(enc, array);
    // dgwarp writes UInt8 (meshio cannot read String arrays); VTK's String type is read too.
    if (t.scalar != Scalar::string && t.scalar != Scalar::uint8 && t.scalar != Scalar::int8)
        fail_at(enc, array, "type=\"UInt8\" or \"String\"", std::string(t.name));
    const std::string format = format_of(enc, array);
    std::string chars;
    if (format == "ascii") {
        for_each_token(enc, array, [&](std::string_view token) {
            std::int64_t v = 0;
            if (!parse_int(token, v) || v < 0 || v > 255) fail_token(enc, array, token, "a character code from 0 to 255");
            chars += static_cast<char>(v);
        });
    } else {
        const std::vector<std::byte> bytes = binary_payload(enc, array, t, format, std::nullopt, count_reason);
        chars.assign(reinterpret_cast<const char*>(bytes.data()), bytes.size());
    }
    std::vector<std::string> strings;
    std::size_t begin = 0;
    while (begin < chars.size()) {
        const std::size_t end = chars.find('\0', begin);
        if (end == std::string::npos) {
            std::string found(1, '\'');
            found += chars.substr(begin, 40);
            found += "' without one";
            fail_at(enc, array, "each string ended by a 0 byte", found);
        }
        strings.push_back(chars.substr(begin, end - begin));
        begin = end + 1;
    }
    if (strings.size() != count) fail_at(enc, array, str(count) + " strings (" + count_reason + ")", str(strings.size()));
    return strings;
}

}  // namespace dgwarp::vtu
