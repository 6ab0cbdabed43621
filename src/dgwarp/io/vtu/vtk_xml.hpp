#pragma once
// The XML of VTK's XML files (.vtu), scanned into a tree of elements that
// points into the file's bytes instead of copying them: DataArray text can be
// hundreds of megabytes.
//
// What VTK, ParaView, meshio and dgwarp write, and no more: the XML
// declaration, comments, <!DOCTYPE>, CDATA sections, elements with attributes
// in either quotes, character data, the five predefined entities and numeric
// character references in attribute values. Scanning stops inside
// <AppendedData>, after its '_' marker: what follows is raw or base64 data
// addressed by byte offsets, not XML.
#include <cstddef>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace dgwarp::xml {

struct Element {
    std::string name;
    std::vector<std::pair<std::string, std::string>> attributes;  // values with references replaced
    std::vector<std::size_t> children;                          // indices into Document::elements
    std::vector<std::pair<std::size_t, std::size_t>> text;      // [begin, end) byte ranges of the
                                                                // character data directly inside
    std::size_t offset = 0;                                      // byte offset of its '<'

    /// The attribute's value, or nullptr when the element has no such attribute.
    const std::string* attribute(std::string_view key) const;
};

struct Document {
    std::vector<Element> elements;  // elements[0] is the root
    /// Byte offset of the first byte after the '_' that starts the data of
    /// <AppendedData>; npos when the file has no AppendedData element.
    std::size_t appended_data = std::string_view::npos;
    /// Index of the <AppendedData> element (0 when there is none).
    std::size_t appended_element = 0;
};

/// Scans `content`. Throws ParseError naming `file`, the line and what was
/// expected on malformed XML (an unclosed or mismatched element, a bad
/// attribute, text outside the root, an unknown entity, an <AppendedData>
/// without its '_').
Document scan(const std::string& file, std::string_view content);

/// 1-based line of the byte at `offset` (counts the newlines before it).
std::size_t line_at(std::string_view content, std::size_t offset);

/// The element's character data without surrounding blanks: a view into
/// `content` when it is one piece (the usual case), else the pieces joined
/// into `storage`.
std::string_view text_of(const Element& element, std::string_view content, std::string& storage);

}  // namespace dgwarp::xml
