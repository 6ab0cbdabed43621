#include "dgwarp/io/vtu/vtk_xml.hpp"

#include <algorithm>
#include <cstdint>

#include "dgwarp/core/error.hpp"

namespace dgwarp::xml {

namespace {

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }
bool is_name_start(char c) {
    return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || c == '_' || c == ':' ||
           static_cast<unsigned char>(c) >= 0x80;
}
bool is_name_char(char c) { return is_name_start(c) || (c >= '0' && c <= '9') || c == '-' || c == '.'; }

/// At most `n` characters of `s` from `at`, for "found" in messages.
std::string excerpt(std::string_view s, std::size_t at, std::size_t n = 20) {
    if (at >= s.size()) return "end of file";
    std::string e(s.substr(at, n));
    for (char& c : e)
        if (c == '\n' || c == '\r' || c == '\t') c = ' ';
    return e;
}

void append_utf8(std::string& s, std::uint32_t cp) {
    if (cp < 0x80) {
        s += static_cast<char>(cp);
    } else if (cp < 0x800) {
        s += static_cast<char>(0xC0 | (cp >> 6));
        s += static_cast<char>(0x80 | (cp & 0x3F));
    } else if (cp < 0x10000) {
        s += static_cast<char>(0xE0 | (cp >> 12));
        s += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
        s += static_cast<char>(0x80 | (cp & 0x3F));
    } else {
        s += static_cast<char>(0xF0 | (cp >> 18));
        s += static_cast<char>(0x80 | ((cp >> 12) & 0x3F));
        s += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
        s += static_cast<char>(0x80 | (cp & 0x3F));
    }
}

class Scanner {
public:
    Scanner(const std::string& file, std::string_view content) : file_(file), s_(content) {}

    Document run() {
        if (s_.starts_with("\xEF\xBB\xBF")) pos_ = 3;  // UTF-8 byte order mark
        std::vector<std::size_t> open;                  // the elements not yet closed, innermost last
        bool root_closed = false;
        while (pos_ < s_.size()) {
            const std::size_t lt = s_.find('<', pos_);
            const std::size_t text_end = lt == std::string_view::npos ? s_.size() : lt;
            if (text_end > pos_) {
                if (!open.empty()) {
                    doc_.elements[open.back()].text.emplace_back(pos_, text_end);
                } else {
                    const std::size_t c = first_non_blank(pos_, text_end);
                    if (c != text_end)
                        fail(c, root_closed ? "nothing after the end of the root element" : "'<' (an XML element)",
                             excerpt(s_, c));
                }
            }
            if (lt == std::string_view::npos) break;
            pos_ = lt;
            if (starts("<?")) {
                skip_past(pos_, "?>", "'?>' closing the processing instruction");
            } else if (starts("<!--")) {
                skip_past(pos_, "-->", "'-->' closing the comment");
            } else if (starts("<![CDATA[")) {
                const std::size_t begin = pos_ + 9;
                const std::size_t end = s_.find("]]>", begin);
                if (end == std::string_view::npos) fail(pos_, "']]>' closing the CDATA section", "end of file");
                if (open.empty()) fail(pos_, "a CDATA section inside an element", excerpt(s_, pos_));
                doc_.elements[open.back()].text.emplace_back(begin, end);
                pos_ = end + 3;
            } else if (starts("<!")) {
                skip_past(pos_, ">", "'>' closing the declaration");
            } else if (starts("</")) {
                const std::size_t at = pos_;
                pos_ += 2;
                const std::string name = read_name("an element name after '</'");
                skip_blanks();
                if (!starts(">")) fail(pos_, "'>' closing </" + name, excerpt(s_, pos_));
                ++pos_;
                if (open.empty()) fail(at, "no end tag here (no element is open)", "</" + name + ">");
                const Element& e = doc_.elements[open.back()];
                if (e.name != name)
                    fail(at, "</" + e.name + "> (closing <" + e.name + "> of line " +
                                 std::to_string(line_at(s_, e.offset)) + ")",
                         "</" + name + ">");
                open.pop_back();
                root_closed = open.empty();
            } else {
                if (root_closed) fail(pos_, "nothing after the end of the root element", excerpt(s_, pos_));
                const bool self_closing = read_start_tag(open.empty() ? std::string_view::npos : open.back());
                const std::size_t index = doc_.elements.size() - 1;
                if (doc_.elements[index].name == "AppendedData" && !self_closing) {
                    // Its data is not XML: find '_' and stop scanning.
                    const std::size_t c = first_non_blank(pos_, s_.size());
                    if (c == s_.size() || s_[c] != '_')
                        fail(c, "'_' starting the data of <AppendedData>", excerpt(s_, c));
                    doc_.appended_data = c + 1;
                    doc_.appended_element = index;
                    return std::move(doc_);
                }
                if (self_closing) root_closed = open.empty();
                else open.push_back(index);
            }
        }
        if (doc_.elements.empty()) fail(s_.size(), "an XML root element such as <VTKFile>", "end of file");
        if (!open.empty()) {
            const Element& e = doc_.elements[open.back()];
            fail(s_.size(), "</" + e.name + "> (closing <" + e.name + "> of line " +
                                std::to_string(line_at(s_, e.offset)) + ")",
                 "end of file");
        }
        return std::move(doc_);
    }

private:
    [[noreturn]] void fail(std::size_t at, const std::string& expected, const std::string& found) const {
        throw ParseError(file_, line_at(s_, std::min(at, s_.size())), expected, found);
    }

    bool starts(std::string_view prefix) const { return s_.substr(pos_).starts_with(prefix); }

    std::size_t first_non_blank(std::size_t from, std::size_t to) const {
        while (from < to && is_blank(s_[from])) ++from;
        return from;
    }
    void skip_blanks() { pos_ = first_non_blank(pos_, s_.size()); }

    void skip_past(std::size_t from, std::string_view end, const std::string& what) {
        const std::size_t e = s_.find(end, from + 2);
        if (e == std::string_view::npos) fail(from, what, "end of file");
        pos_ = e + end.size();
    }

    std::string read_name(const std::string& what) {
        if (pos_ >= s_.size() || !is_name_start(s_[pos_])) fail(pos_, what, excerpt(s_, pos_));
        const std::size_t begin = pos_;
        while (pos_ < s_.size() && is_name_char(s_[pos_])) ++pos_;
        return std::string(s_.substr(begin, pos_ - begin));
    }

    /// An attribute value between quotes at pos_, with references replaced.
    std::string read_value(const std::string& attribute) {
        const char quote = s_[pos_];
        const std::size_t begin = ++pos_;
        const std::size_t end = s_.find(quote, begin);
        if (end == std::string_view::npos)
            fail(begin - 1, std::string("the closing ") + quote + " of attribute " + attribute, "end of file");
        std::string value;
        for (std::size_t i = begin; i < end; ++i) {
            const char c = s_[i];
            if (c == '<') fail(i, "no '<' inside the value of attribute " + attribute, excerpt(s_, i));
            if (c != '&') {
                value += c;
                continue;
            }
            const std::size_t semi = s_.find(';', i);
            if (semi == std::string_view::npos || semi > end || semi - i > 10)
                fail(i, "a reference such as &amp; in attribute " + attribute, excerpt(s_, i, 8));
            const std::string_view ref = s_.substr(i + 1, semi - i - 1);
            if (ref == "lt") value += '<';
            else if (ref == "gt") value += '>';
            else if (ref == "amp") value += '&';
            else if (ref == "quot") value += '"';
            else if (ref == "apos") value += '\'';
            else if (ref.size() > 1 && ref[0] == '#') {
                const bool hex = ref[1] == 'x';
                std::uint32_t cp = 0;
                bool ok = ref.size() > (hex ? 2u : 1u);
                for (char d : ref.substr(hex ? 2 : 1)) {
                    int v = -1;
                    if (d >= '0' && d <= '9') v = d - '0';
                    else if (hex && d >= 'a' && d <= 'f') v = d - 'a' + 10;
                    else if (hex && d >= 'A' && d <= 'F') v = d - 'A' + 10;
                    if (v < 0) ok = false;
                    else cp = cp * (hex ? 16 : 10) + static_cast<std::uint32_t>(v);
                }
                if (!ok || cp == 0 || cp > 0x10FFFF)
                    fail(i, "a character reference such as &#10; in attribute " + attribute,
                         std::string(s_.substr(i, semi - i + 1)));
                append_utf8(value, cp);
            } else {
                fail(i, "a predefined entity (&lt; &gt; &amp; &quot; &apos;) or a character reference in attribute " +
                            attribute,
                     std::string(s_.substr(i, semi - i + 1)));
            }
            i = semi;
        }
        pos_ = end + 1;
        return value;
    }

    /// Reads "<name attr="value" ...>" or ".../>" at pos_ and appends the
    /// element (a child of `parent` unless npos). Returns true for "/>".
    bool read_start_tag(std::size_t parent) {
        Element e;
        e.offset = pos_;
        ++pos_;
        e.name = read_name("an element name after '<'");
        while (true) {
            const std::size_t before = pos_;
            skip_blanks();
            if (pos_ >= s_.size()) fail(e.offset, "'>' closing the tag <" + e.name, "end of file");
            if (starts("/>") || starts(">")) break;
            if (pos_ == before) fail(pos_, "a blank before the next attribute of <" + e.name + ">", excerpt(s_, pos_));
            const std::string key = read_name("an attribute name or '>' in <" + e.name + ">");
            skip_blanks();
            if (!starts("=")) fail(pos_, "'=' after attribute " + key, excerpt(s_, pos_));
            ++pos_;
            skip_blanks();
            if (!starts("\"") && !starts("'")) fail(pos_, "a quoted value for attribute " + key, excerpt(s_, pos_));
            for (const auto& [k, v] : e.attributes)
                if (k == key) fail(pos_, "attribute " + key + " only once in <" + e.name + ">", key);
            std::string value = read_value(key);
            e.attributes.emplace_back(key, std::move(value));
        }
        const bool self_closing = starts("/>");
        pos_ += self_closing ? 2 : 1;
        if (parent == std::string_view::npos && !doc_.elements.empty())
            fail(e.offset, "a single root element", "<" + e.name + ">");
        doc_.elements.push_back(std::move(e));
        if (parent != std::string_view::npos) doc_.elements[parent].children.push_back(doc_.elements.size() - 1);
        return self_closing;
    }

    const std::string& file_;
    std::string_view s_;
    std::size_t pos_ = 0;
    Document doc_;
};

}  // namespace

const std::string* Element::attribute(std::string_view key) const {
    for (const auto& [k, v] : attributes)
        if (k == key) return &v;
    return nullptr;
}

Document scan(const std::string& file, std::string_view content) { return Scanner(file, content).run(); }

std::size_t line_at(std::string_view content, std::size_t offset) {
    offset = std::min(offset, content.size());
    return 1 + static_cast<std::size_t>(std::count(content.begin(), content.begin() + static_cast<std::ptrdiff_t>(offset), '\n'));
}

std::string_view text_of(const Element& element, std::string_view content, std::string& storage) {
    auto trimmed = [&](std::pair<std::size_t, std::size_t> r) {
        std::size_t b = r.first, e = r.second;
        while (b < e && is_blank(content[b])) ++b;
        while (e > b && is_blank(content[e - 1])) --e;
        return content.substr(b, e - b);
    };
    std::string_view only;
    int pieces = 0;
    for (const auto& r : element.text)
        if (const std::string_view t = trimmed(r); !t.empty()) {
            only = t;
            ++pieces;
        }
    if (pieces <= 1) return only;
    storage.clear();
    for (const auto& r : element.text) {
        if (!storage.empty()) storage += ' ';
        storage += trimmed(r);
    }
    return storage;
}

}  // namespace dgwarp::xml
