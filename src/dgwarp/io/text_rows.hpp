#pragma once
// Writing many text rows fast: rows formatted in blocks on every thread
// (std::to_chars into a buffer per thread, no stream call per number), each
// block written by the thread that formatted it, in order, while the others
// format theirs (parallel_for_ordered). The text never crosses to another
// core: a writer thread that copied blocks formatted elsewhere made two
// threads no faster than one (the 865k-node sphere's 5.3M cells: 0.21 s
// either way, against 0.09 s for formatting and writing each block on its
// own thread). Memory: one block per thread. The bytes are those of writing
// each row in turn, whatever the thread count. In a process forked after
// OpenMP ran (its runtime is not fork-safe), call set_num_threads(1) first,
// as run_in_child_process does.
#include <algorithm>
#include <charconv>
#include <cstdint>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "dgwarp/core/parallel_for.hpp"

namespace dgwarp {

/// A block of rows being formatted: numbers are written in place
/// (std::to_chars straight into the buffer, one capacity test per number),
/// not through a std::string append call per number. The buffer is kept
/// from block to block.
class RowText {
public:
    void clear() { at_ = 0; }
    std::string_view view() const { return {buffer_.data(), at_}; }
    /// Makes room for `n` more bytes.
    void reserve(std::size_t n) {
        if (buffer_.size() - at_ < n) buffer_.resize(std::max(buffer_.size() * 2, at_ + n));
    }
    void push_back(char c) {
        reserve(1);
        buffer_[at_++] = c;
    }
    RowText& operator+=(char c) {
        push_back(c);
        return *this;
    }
    RowText& operator+=(std::string_view s) {
        append(s);
        return *this;
    }
    void append(std::string_view s) {
        reserve(s.size());
        std::copy(s.begin(), s.end(), buffer_.data() + at_);
        at_ += s.size();
    }
    /// Writes a number: write_number's text (number_text.hpp), the shortest that reads back exactly.
    template <class Number>
    void append_number(Number value) {
        reserve(32);
        char* begin = buffer_.data() + at_;
        const auto [end, ec] = std::to_chars(begin, begin + 32, value);
        at_ += static_cast<std::size_t>(end - begin);
    }

private:
    std::string buffer_;
    std::size_t at_ = 0;
};

inline void append_number(RowText& s, double value) { s.append_number(value); }
inline void append_number(RowText& s, long long value) { s.append_number(value); }

/// Writes rows 0 .. rows-1 to `out`: row(i, text) appends row i's text to
/// `text` (a RowText). The rows are formatted in blocks on every thread, and
/// each block written to `out` in turn by the thread that formatted it.
template <class Row>
void write_rows(std::ostream& out, std::int64_t rows, const Row& row) {
    constexpr std::int64_t block = 16384;
    parallel_for_ordered<RowText>(
        (rows + block - 1) / block,
        [&](std::int64_t b, RowText& text) {
            text.clear();
            const std::int64_t first = b * block, last = std::min(rows, first + block);
            text.reserve(static_cast<std::size_t>(last - first) * 48);
            for (std::int64_t i = first; i < last; ++i) row(i, text);
        },
        [&out](std::int64_t, const RowText& text) {
            const std::string_view bytes = text.view();
            out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
        });
}

}  // namespace dgwarp
